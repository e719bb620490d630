/* The VTU series of a dynamics analysis (docs/format.md "ParaView"): one .vtu per kept
 * frame (the rows of the histories, ctn_solution_frame) in dynamics/, and dynamics.pvd
 * listing them with their times, for ParaView's time slider. A frame's file:
 *
 *   field data  TimeValue (ParaView's name for the time of a dataset) [s]
 *   point data  displacement, velocity, reaction (f_int + M a + C v - f_ext at the
 *               supports, 0 elsewhere): 3 components per node
 *   cell data   force: the elements' axial forces
 *   points, cells as result.vtu's (vtu.c)
 *
 * Numbers as "%.17g": they round-trip. Staged and committed with the rest of the result
 * set (results.c). */
#include "io/writer.h"
#include "catena/analysis.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

void ctn_frame_name(char *name, size_t k, size_t n)
{
    int width = 5;
    for (size_t v = n > 0 ? (n - 1) / 100000 : 0; v > 0 && width < 20; v /= 10) width++;
    char digits[32];
    snprintf(digits, sizeof digits, "%0*zu", width, k);
    snprintf(name, CTN_VTU_NAME_MAX, "%s/frame_%.20s.vtu", CTN_FRAMES_DIR, digits);
}

/* A point (3 per node) or cell (1 per element) array of n tuples. */
static void put_array(ctn_wbuf *b, const char *name, const double *v, size_t n, int ncomp)
{
    ctn_wbuf_puts(b, "        <DataArray type=\"Float64\" Name=\"");
    ctn_wbuf_puts(b, name);
    ctn_wbuf_puts(b, "\" NumberOfComponents=\"");
    ctn_wbuf_int(b, ncomp);
    ctn_wbuf_puts(b, "\" format=\"ascii\">\n");
    for (size_t i = 0; i < n && !b->err; i++)
        for (int c = 0; c < ncomp; c++) {
            ctn_wbuf_g17(b, v[(size_t)ncomp * i + (size_t)c]);
            ctn_wbuf_putc(b, c + 1 < ncomp ? ' ' : '\n');
        }
    ctn_wbuf_puts(b, "        </DataArray>\n");
}

static int put_frame(ctn_writer *w, const ctn_dyn_frame *f)
{
    ctn_wbuf *b = &w->out;
    size_t nn = ctn_model_node_count(w->m), ne = ctn_model_element_count(w->m);
    ctn_wbuf_puts(b, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                     "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <FieldData>\n"
                     "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">");
    ctn_wbuf_g17(b, f->t);
    ctn_wbuf_puts(b, "</DataArray>\n    </FieldData>\n    <Piece NumberOfPoints=\"");
    ctn_wbuf_int(b, (long long)nn);
    ctn_wbuf_puts(b, "\" NumberOfCells=\"");
    ctn_wbuf_int(b, (long long)ne);
    ctn_wbuf_puts(b, "\">\n      <PointData>\n");
    put_array(b, "displacement", f->d, nn, 3);
    put_array(b, "velocity", f->v, nn, 3);
    put_array(b, "reaction", f->react, nn, 3);
    ctn_wbuf_puts(b, "      </PointData>\n      <CellData>\n");
    put_array(b, "force", f->force, ne, 1);
    ctn_wbuf_puts(b, "      </CellData>\n");
    int rc = ctn_vtu_put_points(w, NULL, nn);
    if (!rc) rc = ctn_vtu_put_cells(w, ne);
    ctn_wbuf_puts(b, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    return rc ? rc : b->err;
}

int ctn_write_frame_vtu(ctn_ctx *ctx, size_t k, ctn_sink *sink, const ctn_model *m, const ctn_solution *s)
{
    ctn_dyn_frame f;
    ctn_writer w;
    memset(&w, 0, sizeof w);
    w.ctx = ctx;
    if (ctn_solution_frame(s, k, &f)) return ctn_error(ctx, CTN_ERR_INVALID, "dynamics: no frame %zu", k);
    int rc = ctn_writer_open(&w, m, sink);
    if (rc) return rc;
    rc = put_frame(&w, &f);
    int rc_close = ctn_wbuf_close(&w.out);
    return rc ? rc : rc_close;
}

int ctn_write_frames_pvd(ctn_ctx *ctx, ctn_sink *sink, const ctn_model *m, const ctn_solution *s)
{
    ctn_writer w;
    size_t n = ctn_solution_frame_count(s);
    memset(&w, 0, sizeof w);
    w.ctx = ctx;
    int rc = ctn_writer_open(&w, m, sink);
    if (rc) return rc;
    ctn_wbuf *b = &w.out;
    ctn_wbuf_puts(b, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                     "  <Collection>\n");
    for (size_t k = 0; k < n && !b->err; k++) {
        ctn_dyn_frame f;
        char name[CTN_VTU_NAME_MAX];
        ctn_solution_frame(s, k, &f);
        ctn_frame_name(name, k, n);
        ctn_wbuf_puts(b, "    <DataSet timestep=\"");
        ctn_wbuf_g17(b, f.t);
        ctn_wbuf_puts(b, "\" group=\"\" part=\"0\" file=\"");
        ctn_wbuf_puts(b, name);
        ctn_wbuf_puts(b, "\"/>\n");
    }
    ctn_wbuf_puts(b, "  </Collection>\n</VTKFile>\n");
    return ctn_wbuf_close(b);
}

/* Whether file name (in dir/dynamics) is one this writer makes: frame_DIGITS.vtu, and
 * the frame's index in *k. */
static int frame_file(const char *name, size_t *k)
{
    size_t len = strlen(name), digits = 0;
    if (len < 11 || strncmp(name, "frame_", 6) || strcmp(name + len - 4, ".vtu")) return 0;
    *k = 0;
    for (const char *c = name + 6; c < name + len - 4; c++, digits++) {
        if (*c < '0' || *c > '9' || digits > 18) return 0;
        *k = 10 * *k + (size_t)(*c - '0');
    }
    return 1;
}

int ctn_frames_remove_stale(ctn_ctx *ctx, const char *dir, size_t n)
{
    char path[4096], want[CTN_VTU_NAME_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, CTN_FRAMES_DIR);
    DIR *d = opendir(path);
    int rc = CTN_OK;
    if (!d) return CTN_OK;                               /* no directory: nothing stale */
    for (struct dirent *e; !rc && (e = readdir(d));) {
        size_t k;
        if (!frame_file(e->d_name, &k)) continue;
        ctn_frame_name(want, k, n);
        if (k < n && !strcmp(want + strlen(CTN_FRAMES_DIR) + 1, e->d_name)) continue;
        if ((size_t)snprintf(path, sizeof path, "%s/%s/%s", dir, CTN_FRAMES_DIR, e->d_name) >= sizeof path) continue;
        if (unlink(path) && errno != ENOENT) rc = ctn_error(ctx, CTN_ERR_IO, "%s: cannot remove: %s", path, strerror(errno));
    }
    closedir(d);
    if (!rc && !n && (size_t)snprintf(path, sizeof path, "%s/%s", dir, CTN_FRAMES_PVD) < sizeof path &&
        unlink(path) && errno != ENOENT)
        rc = ctn_error(ctx, CTN_ERR_IO, "%s: cannot remove: %s", path, strerror(errno));
    return rc;
}
