/* The catena command: shared declarations of the sub-commands. */
#ifndef CTN_APP_APP_H
#define CTN_APP_APP_H

#include <stdio.h>

#include "catena.h"

/* Exit codes of the catena command (docs/format.md, "The command line"; README.md). */
enum {
    CTN_EXIT_OK = 0,         /* converged / success */
    CTN_EXIT_USAGE = 1,      /* bad command line */
    CTN_EXIT_MODEL = 2,      /* bad model file */
    CTN_EXIT_NOCONV = 3,     /* the solution did not converge */
    CTN_EXIT_IO = 4,         /* a file could not be read or written, or another failure */
};

/* 1 if the program's start asked the BLAS for one thread to fit an address-space limit
 * (blas_limit.c): its contexts then run one thread. */
int ctn_app_blas_capped(void);

int ctn_cmd_solve(int argc, char **argv);
int ctn_cmd_formfind(int argc, char **argv);
int ctn_cmd_batch(int argc, char **argv);

/* The commands (help.c): one table of name, entry point and help text. */
typedef struct ctn_app_command {
    const char *name;                    /* "solve" */
    int (*run)(int argc, char **argv);   /* argv[0] is the command name; exit code */
    const char *synopsis;                /* the arguments, after "catena NAME " */
    const char *args;                    /* the arguments, short, for `catena help` */
    const char *summary;                 /* one line for `catena help` */
    const char *help;                    /* description, one line per option, exit codes */
} ctn_app_command;
/* The command called name; NULL if there is none. */
const ctn_app_command *ctn_app_command_find(const char *name);
/* `catena help`: every command, how to get the help of one, the exit codes. */
void ctn_app_usage(FILE *f);
/* `catena COMMAND --help`: "usage: catena NAME SYNOPSIS" and the help text. */
void ctn_app_command_help(FILE *f, const ctn_app_command *c);
/* 1 if argv[1..argc-1] holds --help or -h. */
int ctn_app_wants_help(int argc, char **argv);

/* MODEL [--json] [-o DIR] [-q], as `solve` and `compare` take them (args.c). 0, or 1
 * after printing a usage message naming cmd. */
typedef struct ctn_model_args {
    const char *model, *outdir;   /* outdir NULL: no files */
    int json, quiet;
    long reactions;               /* solve: the most reaction rows, -1 all (cmd_solve.c) */
} ctn_model_args;
int ctn_app_model_args(const char *cmd, int argc, char **argv, ctn_model_args *a);

/* SIGINT and SIGTERM noted instead of ending the process (signals.c), and the command's
 * context (ctn_app_ctx_create): no thread limit of its own (the library's default is
 * none started; the command lets a file's threads= and the machine decide,
 * docs/solver.md "Threads"), and an interrupt callback that reads the note: the library
 * stops at its next safe point with CTN_ERR_INTERRUPTED, which ctn_app_fail turns into
 * 128 + the signal (130, 143). */
void ctn_app_signals_install(void);
int ctn_app_ctx_create(ctn_ctx **ctx);
/* The same without the MPI job's communicator: a serial solve on one rank (batch). */
int ctn_app_ctx_create_local(ctn_ctx **ctx);
int ctn_app_interrupt_code(void);

/* The MPI job (mpi.c): PETSc and MPI initialised when under mpirun or given options
 * after --petsc (taken out of argv); rank 0 alone prints; the job's communicator set on
 * a context (ctn_app_ctx_create does it); finalize returns the largest code of the job
 * (every rank exits with it). Without PETSc: no-ops (--petsc is a usage error). */
int ctn_app_mpi_init(int *argc, char ***argv);
int ctn_app_mpi_rank(void);
int ctn_app_mpi_size(void);
int ctn_app_mpi_attach(ctn_ctx *ctx);
int ctn_app_mpi_finalize(int code);
/* With CATENA_MPI_DEBUG=1 in the environment, in a job: one line on stderr (rank 0's)
 * saying how the static analysis held the tangent ("by columns" or "whole on every
 * rank"), the check tests/cli/mpi.sh makes that the distributed path is taken. */
void ctn_app_mpi_report(const ctn_solution *s);

/* The command: argv[1] names the sub-command (dispatch.c); its exit code. What it prints
 * goes to stdout and stderr; the caller flushes stdout (main.c). */
int ctn_app_dispatch(int argc, char **argv);

/* Exit code for a failed library call, after printing its message to stderr. */
int ctn_app_fail(ctn_ctx *ctx, int status);
/* The same for a failure about the model read from path: the message is printed with
 * the "path:" prefix (added unless the library's message already starts with it). */
int ctn_app_fail_model(ctn_ctx *ctx, int status, const char *path);
/* Flush f and check it for a write error; CTN_EXIT_OK, or CTN_EXIT_IO after printing
 * "catena: NAME: write error: ..." to stderr. */
int ctn_app_flush(FILE *f, const char *name);

/* Warn (on out) when a converged solution is not stable: unstable (negative eigenvalues
 * of the tangent) or semi-definite (a zero one), with the node and direction. */
void ctn_print_stability(FILE *out, const char *model, const ctn_solution *s);
/* Warn (on out) about answers no cable gives: a strain above 10 %, a deformed model more
 * than 10,000 km across (usually a unit or input error). */
void ctn_print_warnings(FILE *out, const char *model, const ctn_model *m, const ctn_solution *s);
/* Human-readable result summary (without the reactions). */
void ctn_print_summary(FILE *out, const ctn_model *m, const ctn_solution *s);
/* A line per load case and combination, and the envelope (print_cases.c). */
void ctn_print_cases(FILE *out, const ctn_model *m, const ctn_solution *s);
/* The largest displacement of each step (from the reference geometry) and of each case
 * and combination (from its installed state), with its node (print_cases.c). */
void ctn_print_displacements(FILE *out, const ctn_model *m, const ctn_solution *s);
/* 1 when every case and combination converged; else 0 and the first that did not. */
int ctn_cases_converged(const ctn_solution *s, const char **failed);
/* A line per group, and the most utilised element (print_groups.c). */
void ctn_print_groups(FILE *out, const ctn_model *m, const ctn_solution *s);
/* The warning (exit code unchanged) when an element's utilisation exceeds 1. */
void ctn_print_capacity_warning(FILE *out, const char *model, const ctn_model *m, const ctn_solution *s);
/* Its modal part: the analysis and one line per mode (nothing without modes). */
void ctn_print_modes(FILE *out, const ctn_model *m, const ctn_solution *s);
/* Its buckling part: the analysis and one line per factor (print_buckling.c; nothing
 * without a buckling analysis). */
void ctn_print_buckling(FILE *out, const ctn_model *m, const ctn_solution *s);
/* Its dynamics part (print_dynamics.c; nothing without a dynamics analysis), and on out
 * the time a failed dynamics stopped at. */
void ctn_print_dynamics(FILE *out, const ctn_model *m, const ctn_solution *s);
void ctn_print_dynamics_failure(FILE *out, const char *model, const ctn_solution *s);
/* The reactions of the supported nodes, at most limit rows (-1: all), then their sum
 * and, when rows were left out, the largest by magnitude (print_reactions.c). */
#define CTN_APP_REACTIONS 20
void ctn_print_reactions(FILE *out, const ctn_model *m, const ctn_solution *s, long limit);
/* Iteration log state: the monitor prints one line per Newton iteration with the
 * observed order log(r_k/r_k-1) / log(r_k-1/r_k-2) (2 for quadratic convergence). */
typedef struct ctn_iter_log {
    FILE *out;
    double r[2];   /* the two previous residual norms, 0 if none */
} ctn_iter_log;
void ctn_print_iteration(void *data, const ctn_iterate *it);

/* Progress of long phases on stderr when it is a terminal (progress.c). */
#define CTN_APP_PROGRESS_AFTER 2.0   /* seconds a phase runs before its progress shows */
typedef struct ctn_app_progress {
    int tty;              /* stderr is a terminal: else nothing is shown */
    const char *what;     /* the phase */
    double start, last;   /* its start, the last line shown [s, monotonic] */
    int shown;            /* a progress line is on the terminal */
} ctn_app_progress;
void ctn_app_progress_init(ctn_app_progress *p);
/* A new phase: the clock restarts, the line is cleared. */
void ctn_app_progress_phase(ctn_app_progress *p, const char *what);
/* Clear the line (before printing anything else). */
void ctn_app_progress_done(ctn_app_progress *p);
/* The library's progress callback (ctn_ctx_set_progress), data a ctn_app_progress. */
void ctn_app_progress_report(void *data, const char *what, double done, double total);
/* A Newton iteration of the phase "solving". */
void ctn_app_progress_iteration(ctn_app_progress *p, const ctn_iterate *it);

/* ---- compare, study, convergence (cmd_compare.c, cmd_study.c, cmd_convergence.c) ---- */
#include <cjson/cJSON.h>

int ctn_cmd_compare(int argc, char **argv);
int ctn_cmd_study(int argc, char **argv);
int ctn_cmd_convergence(int argc, char **argv);
/* Shared helpers (cmd_report.c). */
/* Comma-separated numbers (':' also separates) into out[cap]; 0 on success. */
int ctn_app_parse_list(const char *s, double *out, size_t cap, size_t *n);
void ctn_app_print_span(FILE *out, const ctn_span *s);
/* Stress in MPa when the model has units, else unchanged. */
double ctn_app_stress(const ctn_span *s, double stress);
void ctn_app_print_header(FILE *out, const ctn_span *s);
void ctn_app_print_values(FILE *out, const char *label, const ctn_span *s, const ctn_compare_values *v);
void ctn_app_print_diffs(FILE *out, const ctn_compare_values *v, const ctn_compare_values *ref);
/* Object `key` in parent with the compared values (and their relative differences to
 * ref when ref is not NULL); NULL when out of memory. */
cJSON *ctn_app_values_json(cJSON *parent, const char *key, const ctn_compare_values *v,
                           const ctn_compare_values *ref);
/* Print root on stdout, flushed and checked; exit code (CTN_EXIT_IO when root is NULL:
 * out of memory, or when stdout fails, after a message). */
int ctn_app_print_json(cJSON *root);
/* Render the figures names[0..n-1] in dir with gnuplot, or say how to. Exit code. */
int ctn_app_render(ctn_ctx *ctx, const char *dir, const char *const *names, size_t n, int quiet);

/* `catena study` output (cmd_study_print.c): the summary, the marked lengths and the
 * error table at levels[0..nlevels-1] (room for cap; the claims' stresses are added). */
void ctn_app_study_report(const ctn_study *st, const char *model, size_t sweep, double *levels,
                          size_t nlevels, size_t cap, const double *claims, size_t nclaims);
int ctn_app_study_json(const ctn_study *st, const char *model);

#endif
