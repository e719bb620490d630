/* The VTU pieces of an MPI job and their .pvtu (vtu.h; docs/format.md, "ParaView"):
 * ParaView's parallel format, one UnstructuredGrid piece per rank and a
 * PUnstructuredGrid file naming them. Each rank writes its piece from its replicated
 * model and solution. */
#include "io/vtu.h"
#include "core/ctx.h"
#include "dist/comm.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

void ctn_vtu_piece_name(char *name, int rank) { snprintf(name, CTN_VTU_NAME_MAX, "result_r%d.vtu", rank); }

/* The piece of rank r of n: its elements, the nodes they reference (model order), and
 * the nodes of no element in [nn r / n, nn (r + 1) / n). points and local: nn each. */
static int subset_of(ctn_writer *w, int r, int n, size_t *points, size_t *local, ctn_vtu_subset *sub)
{
    size_t nn = ctn_model_node_count(w->m), ne = ctn_model_element_count(w->m);
    sub->e0 = (size_t)((unsigned long long)ne * (unsigned)r / (unsigned)n);
    sub->e1 = (size_t)((unsigned long long)ne * (unsigned)(r + 1) / (unsigned)n);
    size_t lo = (size_t)((unsigned long long)nn * (unsigned)r / (unsigned)n);
    size_t hi = (size_t)((unsigned long long)nn * (unsigned)(r + 1) / (unsigned)n);
    for (size_t i = 0; i < nn; i++) local[i] = 0;           /* 0: not in; 1: in; 2: in an element */
    for (size_t e = 0; e < ne; e++) {
        ctn_element_info info;
        if (ctn_model_element(w->m, e, &info)) return ctn_writer_mismatch(w);
        for (int k = 0; k < info.nnodes; k++) {
            size_t i = (size_t)info.nodes[k];
            if (e >= sub->e0 && e < sub->e1) local[i] |= 1;
            local[i] |= 2;
        }
    }
    size_t np = 0;
    for (size_t i = 0; i < nn; i++)
        if ((local[i] & 1) || (!(local[i] & 2) && i >= lo && i < hi)) points[np++] = i;
    for (size_t p = 0; p < np; p++) local[points[p]] = p;
    sub->npoints = np;
    sub->points = points;
    sub->local = local;
    return CTN_OK;
}

static int piece_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    if (k != w->step) return CTN_OK;
    const ctn_comm *c = ctn_ctx_comm(w->ctx);
    size_t nn = ctn_model_node_count(w->m);
    size_t *points = ctn_malloc(w->ctx, 2 * (nn ? nn : 1), sizeof(size_t));
    if (!points) return CTN_ERR_NOMEM;
    ctn_vtu_subset sub;
    int rc = subset_of(w, ctn_comm_rank(c), ctn_comm_size(c), points, points + (nn ? nn : 1), &sub);
    if (!rc) rc = ctn_vtu_put_piece(w, s, k, &sub);
    ctn_free(points);
    return rc;
}

const ctn_writer_ops ctn_writer_vtu_piece = { .name = "result_r.vtu", .size = sizeof(ctn_writer),
                                              .begin = ctn_vtu_begin, .step = piece_step, .end = ctn_vtu_end };

static int pvtu_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    return ctn_vtu_begin_with(p, m, sink, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
                                          "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                                          "  <PUnstructuredGrid GhostLevel=\"0\">\n");
}

/* The arrays, the points' type, a <Piece> per rank. */
static int pvtu_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    if (k != w->step) return CTN_OK;
    int rc = ctn_vtu_put_parrays(w, s, k), n = ctn_comm_size(ctn_ctx_comm(w->ctx));
    ctn_wbuf_puts(&w->out, "    <PPoints>\n      <PDataArray type=\"Float64\" Name=\"coordinates\" "
                           "NumberOfComponents=\"3\"/>\n    </PPoints>\n");
    for (int r = 0; r < n; r++) {
        char name[CTN_VTU_NAME_MAX];
        ctn_vtu_piece_name(name, r);
        ctn_wbuf_puts(&w->out, "    <Piece Source=\"");
        ctn_wbuf_puts(&w->out, name);
        ctn_wbuf_puts(&w->out, "\"/>\n");
    }
    return rc ? rc : w->out.err;
}

static int pvtu_end(void *p) { return ctn_vtu_end_with(p, "  </PUnstructuredGrid>\n</VTKFile>\n"); }

const ctn_writer_ops ctn_writer_pvtu = { .name = "result.pvtu", .size = sizeof(ctn_writer), .begin = pvtu_begin,
                                         .step = pvtu_step, .end = pvtu_end };

/* Whether file name is a piece this writer makes, result_rR.vtu (R as it writes it: no
 * leading zero), and R in *r. */
static int piece_file(const char *name, long *r)
{
    size_t len = strlen(name), digits = len > 12 ? len - 12 : 0;
    if (len < 13 || strncmp(name, "result_r", 8) || strcmp(name + len - 4, ".vtu") || digits > 9) return 0;
    if (name[8] == '0' && digits > 1) return 0;
    *r = 0;
    for (size_t i = 8; i < len - 4; i++) {
        if (name[i] < '0' || name[i] > '9') return 0;
        *r = 10 * *r + (name[i] - '0');
    }
    return 1;
}

static int remove_file(ctn_ctx *ctx, const char *dir, const char *name)
{
    char path[4096];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, name) >= sizeof path)
        return ctn_error(ctx, CTN_ERR_IO, "%s: path too long", dir);
    if (unlink(path) && errno != ENOENT) return ctn_error(ctx, CTN_ERR_IO, "%s: cannot remove: %s", path, strerror(errno));
    return CTN_OK;
}

int ctn_vtu_pieces_remove_stale(ctn_ctx *ctx, const char *dir, int size)
{
    DIR *d = opendir(dir);
    int rc = CTN_OK;
    if (!d) return CTN_OK;                       /* no directory: nothing stale */
    for (struct dirent *e; !rc && (e = readdir(d));) {
        long r;
        if (piece_file(e->d_name, &r) && (size == 1 || r >= size)) rc = remove_file(ctx, dir, e->d_name);
    }
    closedir(d);
    if (!rc && size == 1) rc = remove_file(ctx, dir, ctn_writer_pvtu.name);
    return rc;
}
