/* The modal validation study (docs/validation.md, "Modal analysis"), a program on the
 * public API: each part solves its models, prints its table (markdown) and writes its
 * figure (data, gnuplot script, SVG) into the output directory. */
#ifndef CTN_STUDIES_MODAL_STUDY_H
#define CTN_STUDIES_MODAL_STUDY_H

#include "catena.h"

#define PI 3.14159265358979323846

/* A solved model and its context. */
typedef struct study_run {
    ctn_ctx *ctx;
    ctn_model *m;
    ctn_solution *s;
} study_run;

/* Read and solve a model text (with its modes line): 0 when it converged with modes,
 * else a status (the message printed). study_free in any case. */
int study_solve(study_run *r, const char *text);
void study_free(study_run *r);
/* Frequency of mode k [Hz]. */
double study_freq(const study_run *r, size_t k);
/* Mode k of a generated cable (ends nodes 1, 2, interior in order, gravity -y, span
 * along x): 1 in-plane symmetric, -1 in-plane antisymmetric, 0 out of plane. */
int study_classify(const study_run *r, size_t k);
/* The first omega_bar of each kind (0 if none among the modes). */
void study_first_kinds(const study_run *r, double f0, double *sym, double *anti, double *out);
/* The first root in (pi, 3 pi) of Irvine's tan(w/2) = w/2 - (4/l2)(w/2)^3. */
double irvine_symmetric(double l2);
/* Irvine's lambda^2 and the frequency unit f0 = sqrt(H/m)/(2 pi L) (omega_bar = f/f0) of a
 * solved level cable of span L, weight w, rigidity EA. */
void irvine_parameters(const study_run *r, double L, double w, double EA, double *l2, double *f0);
/* Data file, then the figure's script, rendered. */
int study_data(ctn_ctx *ctx, const char *dir, const char *file, const char *header, size_t ncol,
               size_t nrow, const double *d);
int study_figure(ctn_ctx *ctx, const char *dir, const ctn_plot_figure *f);

int study_string(ctn_ctx *ctx, const char *dir);
int study_irvine(ctn_ctx *ctx, const char *dir);
int study_depth(ctn_ctx *ctx, const char *dir);
int study_paper(const char *root);
int study_net(ctn_ctx *ctx, const char *dir);

#endif
