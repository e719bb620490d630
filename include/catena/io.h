/*
 * catena/io.h - reading .cable model files and writing results.
 *
 * The .cable format is documented in docs/format.md. Errors carry "file:line: what
 * was expected, what was found" in the context's message and CTN_ERR_MODEL (bad
 * content) or CTN_ERR_IO (unreadable file). Number I/O is locale-independent.
 * Every file writer is atomic: it writes a temporary file beside the target and renames
 * it, so no half-written file is left after a failure. Results are streamed (through a
 * fixed buffer), never built in memory first, except by ctn_result_json, which returns
 * the text.
 */
#ifndef CATENA_IO_H
#define CATENA_IO_H

#include <stddef.h>
#include <stdio.h>

#include "catena/core.h"
#include "catena/model.h"
#include "catena/solve.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* Read a model file. On success *out owns a new model (ctn_model_destroy) and, when opt
 * is not NULL, *opt holds the options of the file's `solve` line (the defaults where it
 * has none): options belong to the solve, so the caller passes them on to ctn_solve. */
int ctn_read_file(ctn_ctx *ctx, const char *path, ctn_model **out, ctn_solve_options *opt);
/* The same from memory (len bytes, need not be NUL-terminated); name is used in
 * messages in place of a file name. */
int ctn_read_string(ctn_ctx *ctx, const char *name, const char *text, size_t len,
                    ctn_model **out, ctn_solve_options *opt);
/* More .cable text read into an existing model m, as if it followed the lines m was
 * built from: its lines are numbered from first_line (>= 1) in messages naming `name`
 * (NULL: "<string>"), and the `solve` line's options go to *opt (NULL: dropped; give the
 * same opt to every call, initialised once by ctn_solve_options_default). With
 * ctn_model_add_nodes and ctn_model_add_elements between the calls, a program builds a
 * model partly from text and partly from arrays, numbered as the one file they make
 * (a model built so and that file read by ctn_read_string are the same). On failure the
 * context names the bad line; m keeps the lines before it and should be discarded. */
int ctn_read_string_into(ctn_model *m, const char *name, int first_line, const char *text, size_t len,
                         ctn_solve_options *opt);
/* ctn_read_file / ctn_read_string without the options. */
int ctn_model_read_file(ctn_ctx *ctx, const char *path, ctn_model **out);
int ctn_model_read_string(ctn_ctx *ctx, const char *name, const char *text, size_t len,
                          ctn_model **out);

/* The result as JSON text (see docs/format.md, "Results"). *json is allocated; free it
 * with ctn_json_free. pretty: indent for people (the layout of result.json), else no
 * whitespace. A result holding a NaN or Inf is refused with CTN_ERR_INVALID. */
int ctn_result_json(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, int pretty,
                    char **json);
/* Free the text of ctn_result_json; NULL is a harmless no-op. */
void ctn_json_free(char *json);
/* The same text as ctn_result_json, streamed to out (no trailing newline), which is
 * then flushed; memory use does not grow with the result. CTN_ERR_INVALID (nothing
 * written) for a NaN or Inf; CTN_ERR_IO when a write or the flush fails: the message
 * says "stdout: write error: <strerror>" for stdout. The caller keeps out open. */
int ctn_write_json(ctn_ctx *ctx, FILE *out, const ctn_model *m, const ctn_solution *s,
                   int pretty);

/* Write result.json, nodes.csv, elements.csv and result.vtu (VTK XML, for ParaView; the
 * last step) into directory dir (created if missing); for a solution of several steps
 * also result_K.vtu for every step K = 1, 2, ... and result.pvd, the collection of
 * them (a one-step set removes an earlier result.pvd). Each file is streamed into a
 * temporary beside its target and synced; only when all are complete are they
 * renamed onto their targets, so a failure
 * (CTN_ERR_IO, CTN_ERR_NOMEM, CTN_ERR_INVALID for a NaN or Inf, checked before
 * anything is written) leaves no temporary and the older files, if any, untouched. */
int ctn_write_results(ctn_ctx *ctx, const char *dir, const ctn_model *m,
                      const ctn_solution *s);

/* Write step k (0-based, < ctn_solution_step_count) of the solution as one ParaView
 * .vtu file at path: the content of result.vtu (or result_K.vtu) of ctn_write_results,
 * staged beside path and renamed onto it (atomic). CTN_ERR_INVALID for k out of range or
 * a result holding a NaN or Inf (nothing written); CTN_ERR_IO when it cannot be written. */
int ctn_write_vtu(ctn_ctx *ctx, const char *path, const ctn_model *m, const ctn_solution *s,
                  size_t k);

/* CTN_OK when every number the writers would print (summary, histories, the model's
 * coordinates and lengths, every step's displacements, reactions and element states,
 * the modes) is finite; else CTN_ERR_INVALID, recorded as "the result holds a NaN or
 * Inf; not written". The writers above make this check first; a program that prints
 * its own summary makes it too, so that its verdict does not depend on the output. */
int ctn_result_check(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s);

/* Write len bytes atomically to path (temporary file + rename). */
int ctn_write_file_atomic(ctn_ctx *ctx, const char *path, const char *data, size_t len);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
