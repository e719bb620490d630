/* Internal: result writers. A writer turns a model and its solution into bytes through
 * a sink, in three calls: begin (the model: headers), step for every load step k =
 * 0, 1, ... in order (what the format keeps of that step), end (closing text). The
 * driver, ctn_writer_run, allocates the writer's state (ops->size bytes, zeroed, which
 * begin with a ctn_writer it fills in), calls them, flushes and frees. A writer reads
 * the model and the solution only through the public accessors of catena/model.h and
 * catena/solve.h, and prints through the buffered output of io/sink.h.
 *
 * Writers do not test numbers: ctn_result_check refuses a result that holds a NaN or
 * Inf before anything is written. */
#ifndef CTN_IO_WRITER_H
#define CTN_IO_WRITER_H

#include "catena/model.h"
#include "catena/solve.h"
#include "io/piece.h"
#include "io/sink.h"

/* The head of every writer's state. */
typedef struct ctn_writer {
    ctn_ctx *ctx;          /* set by the driver */
    int pretty;            /* set by the driver; JSON: cJSON_Print's layout, else
                              cJSON_PrintUnformatted's */
    const ctn_model *m;    /* set by ctn_writer_open */
    ctn_wbuf out;          /* opened by ctn_writer_open, closed by the driver */
    size_t step;           /* set by the driver: the step a one-step writer (result.vtu)
                              writes; ctn_writer_run: the last */
    const ctn_pieces *pieces; /* set by the driver: where the nodes' results come from, a
                              piece at a time (piece.h; one process: ctn_pieces_local) */
    const ctn_solution *base; /* set by ctn_writer_run_case for a case's files: the run's
                              solution, whose step base_step is the case's installed
                              state; NULL otherwise */
    size_t base_step;
} ctn_writer;

typedef struct ctn_writer_ops {
    const char *name;      /* the file it writes in a result directory */
    size_t size;           /* bytes of its state, a struct that starts with a ctn_writer */
    int (*begin)(void *w, const ctn_model *m, ctn_sink *sink);
    int (*step)(void *w, const ctn_solution *s, size_t k);
    int (*end)(void *w);
} ctn_writer_ops;

extern const ctn_writer_ops ctn_writer_json;          /* result.json (docs/format.md) */
extern const ctn_writer_ops ctn_writer_nodes_csv;     /* nodes.csv: the last step */
extern const ctn_writer_ops ctn_writer_elements_csv;  /* elements.csv: the last step */
extern const ctn_writer_ops ctn_writer_modes_csv;     /* modes.csv: the modal analysis */
extern const ctn_writer_ops ctn_writer_buckling_csv;  /* buckling.csv: the buckling analysis */
extern const ctn_writer_ops ctn_writer_history_csv;   /* history.csv: the dynamics analysis */
extern const ctn_writer_ops ctn_writer_vtu;           /* result.vtu: one step (vtu.c) */
extern const ctn_writer_ops ctn_writer_pvd;           /* result.pvd: the steps' .vtu files */
extern const ctn_writer_ops ctn_writer_chart_csv;     /* sag_tension.csv: the sag-tension chart */

/* The file of step k (0-based) of n in a result directory: "result_K.vtu", K = k + 1
 * written with as many digits as n has (zero-padded, so that names sort), in
 * name[CTN_VTU_NAME_MAX]. */
#define CTN_VTU_NAME_MAX 48
void ctn_vtu_step_name(char *name, size_t k, size_t n);

/* The <Points> (reference coordinates, displaced by base unless NULL) and <Cells> of a
 * .vtu piece (vtu.c). */
int ctn_vtu_put_points(ctn_writer *w, const double *base, size_t nn);
int ctn_vtu_put_cells(ctn_writer *w, size_t ne);

/* The dynamics analysis's VTU series (vtu_frames.c): the name of frame k of n in a result
 * directory ("dynamics/frame_KKKKK.vtu", k from 0, zero-padded to at least 5 digits, name
 * of CTN_VTU_NAME_MAX); frame k of s (ctn_solution_frame) as a .vtu; the collection of
 * the frames with their times (dynamics.pvd); the frame files of an earlier run in
 * dir/dynamics that the n frames written do not replace, removed. */
#define CTN_FRAMES_DIR "dynamics"
#define CTN_FRAMES_PVD "dynamics.pvd"
void ctn_frame_name(char *name, size_t k, size_t n);
int ctn_write_frame_vtu(ctn_ctx *ctx, size_t k, ctn_sink *sink, const ctn_model *m, const ctn_solution *s);
int ctn_write_frames_pvd(ctn_ctx *ctx, ctn_sink *sink, const ctn_model *m, const ctn_solution *s);
int ctn_frames_remove_stale(ctn_ctx *ctx, const char *dir, size_t n);

/* The same with the nodes' results taken from pieces (piece.h) in place of the
 * solution's own (a distributed run's gathering source; tests). */
int ctn_writer_run_pieces(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, size_t k, const ctn_pieces *pieces,
                          ctn_sink *sink, const ctn_model *m, const ctn_solution *s);
/* ctn_writer_run_step for the file of a case (its solution s, step 0) whose installed
 * state is step base_step of the run's solution base (result.vtu: the displacements
 * from that state). */
int ctn_writer_run_case(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, ctn_sink *sink, const ctn_model *m,
                        const ctn_solution *s, const ctn_solution *base, size_t base_step);
/* For begin: remember the model, open the buffered output over sink. */
int ctn_writer_open(ctn_writer *w, const ctn_model *m, ctn_sink *sink);
/* Record and return CTN_ERR_INVALID: an accessor refused an index (a solution of
 * another model). */
int ctn_writer_mismatch(ctn_writer *w);
/* Run one writer over sink: begin, step for every step of s, end, flush. */
int ctn_writer_run(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, ctn_sink *sink,
                   const ctn_model *m, const ctn_solution *s);
/* The same with the writer's step (ctn_writer.step) set to k < the step count. */
int ctn_writer_run_step(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, size_t k, ctn_sink *sink,
                        const ctn_model *m, const ctn_solution *s);

#endif
