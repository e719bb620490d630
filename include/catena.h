/*
 * catena.h - geometrically non-linear static analysis of 3D cable structures.
 *
 * This header is the entry point of the library: include it and nothing else. It
 * includes every module header; each documents its own functions, and the comment of
 * each function says what it returns, what it writes and who owns what.
 *
 * The public API, by module (include/catena/):
 *   catena/export.h    CTN_API_BEGIN / CTN_API_END: what the shared library exports
 *   catena/version.h   CATENA_VERSION_* macros (the headers) and ctn_version() (the library)
 *   catena/core.h      the context (ctn_ctx), status codes (CTN_OK, CTN_ERR_*), errors,
 *                      model size limits and an allocation-failure hook for tests
 *   catena/model.h     building a model: nodes, materials, sections, elements of any
 *                      family (cable, spring; versioned spec structs), generated cables,
 *                      supports, loads and load steps; queries on a model
 *   catena/io.h        reading .cable model files (docs/format.md) with their solve
 *                      options, writing the results as JSON and CSV, atomic file writes
 *   catena/solve.h     the analysis: options, the problem object (set up once, solved,
 *                      then asked for the stability of its solution and for its natural
 *                      modes), Newton-Raphson / globalized Newton / arc-length,
 *                      convergence reasons, displacements, reactions, element forces,
 *                      modes (frequencies, shapes, participation); it includes
 *   catena/results.h   the results per load step (nodes, elements, catenaries, beams,
 *                      groups, utilisation)
 *   catena/analytic.h  closed forms of a single cable: catenary, elastic catenary,
 *                      parabola, funicular polygon (reference solutions)
 *   catena/compare.h   a model's single span against those closed forms; the length
 *                      study and the mesh-convergence study
 *   catena/plot.h      figures as gnuplot scripts and data files
 *   catena/formfind.h  form finding by force density: the shape that carries the
 *                      members' force densities or target forces, written as a model
 *   catena/parallel.h  an MPI communicator on a context: the analyses on the PETSc
 *                      linear solvers over the processes of an MPI job
 *
 * How to use it:
 *
 *   ctn_ctx *ctx = NULL;                 context: one per thread, holds the last error
 *   ctn_model *m = NULL;                 the model (nodes, elements, loads)
 *   ctn_solution *s = NULL;              the result of one solve
 *   ctn_solve_options opt;               options belong to the solve, not the model
 *   ctn_solve_summary sum;
 *   if (ctn_ctx_create(&ctx)) return out_of_memory;
 *   int rc = ctn_read_file(ctx, "bridge.cable", &m, &opt);    or ctn_model_create +
 *   if (!rc) rc = ctn_solve(ctx, m, &opt, &s);                   ctn_model_add_*
 *   if (rc) fprintf(stderr, "%s\n", ctn_ctx_message(ctx));
 *   else {
 *       ctn_solution_summary(s, &sum);   sum.reason == CTN_CONVERGED, or why not
 *       const double *d = ctn_solution_displacements(s);        3 per node
 *   }
 *   ctn_solution_destroy(&s);            each destroy accepts NULL and sets it to NULL
 *   ctn_model_destroy(&m);
 *   ctn_ctx_destroy(&ctx);
 *
 * Context. Every call that can fail takes a ctn_ctx (or an object bound to one, such as
 * a model) and records the error there: ctn_ctx_code() and ctn_ctx_message(), which for
 * model input starts with "file:line: ". A context is not thread-safe: use one per
 * thread. The library never prints, never exits and keeps no global state of its own;
 * the eigen-solver of modal analysis (ARPACK) keeps state between its calls, so run one
 * modal analysis at a time in a process.
 *
 * Errors. Every function that can fail returns an int status: CTN_OK (0) or a
 * CTN_ERR_* code (catena/core.h; ctn_strerror() names it); results come back through
 * out-parameters (a call that creates an object sets *out to NULL when it fails).
 *
 * Solving. ctn_solve() takes a ctn_solve_options filled by ctn_solve_options_default()
 * (or read from a file's `solve` line by ctn_read_file) and changed; NULL means the
 * defaults. ctn_problem_create() + ctn_problem_solve() do the same in two steps and keep
 * the problem (DOF map, pattern, factorization) for what follows a solve, such as
 * ctn_problem_stability() and ctn_problem_modes() (natural frequencies and mode shapes
 * about the solved state; a file's `modes` line sets opt.modal, and ctn_solve then runs
 * it: read the modes with ctn_solution_mode_count() and ctn_solution_mode()). Non-convergence is an outcome, not an error: ctn_solve() returns CTN_OK and
 * a solution whose summary's reason says why it stopped (positive: converged,
 * negative: diverged, with the last converged state kept).
 *
 * Ownership. Objects come in create/destroy pairs (ctn_ctx, ctn_model, ctn_problem, ctn_solution,
 * ctn_compare, ctn_study, ctn_convergence); destroy(&p) accepts NULL and sets p to
 * NULL. A model is bound to the context it was created with, which must outlive it.
 * Arrays returned by const pointer (displacements, reactions, histories) belong to the
 * object they came from and live as long as it; strings allocated for the caller say
 * how to free them (ctn_json_free). Input arrays are copied or only read during the
 * call.
 *
 * Linking: cc app.c $(pkg-config --cflags --libs catena), see README.md.
 */
#ifndef CATENA_H
#define CATENA_H

#include "catena/export.h"
#include "catena/version.h"
#include "catena/core.h"
#include "catena/model.h"
#include "catena/io.h"
#include "catena/solve.h"
#include "catena/analysis.h"
#include "catena/analytic.h"
#include "catena/compare.h"
#include "catena/plot.h"
#include "catena/formfind.h"
#include "catena/parallel.h"

#endif
