/* result.vtu: one step of the result as a VTK XML UnstructuredGrid (ascii, numbers as
 * "%.17g", so they round-trip), for ParaView (docs/format.md, "ParaView").
 *
 *   points      the nodes in model order (result.json's "nodes"), at their reference
 *               coordinates; the point data hold the displacements (ParaView's "Warp
 *               By Vector" draws the deformed shape). A load case's file
 *               (ctn_writer_run_case): the points at the case's installed state (the
 *               reference coordinates plus its displacements), `displacement` from it
 *               (the JSON's ux_from), `displacement_total` from the reference geometry
 *   cells       the elements in model order (result.json's "elements"): a line (VTK
 *               type 3) through the two nodes of a two-node element, a polyline (4)
 *               through the nodes of a longer one
 *   field data  load_factor of the step
 *
 * Point and cell arrays come from one table, fields[]: a name, where, how many
 * components, and a function giving the values of one point or cell. An entry may stand
 * for no array (a value the model does not know) or for several, numbered NAME_1,
 * NAME_2, ... (e.g. one array per vibration mode). To add an array, add one entry. */
#include "io/vtu.h"
#include "catena/analysis.h"

#include <stdio.h>

/* What a field's functions see: the model, the solution and the step written. */
typedef struct vtu_data {
    const ctn_model *m;
    const ctn_solution *s;
    size_t k;                       /* the step (0-based) */
    ctn_step_result st;             /* its displacements, reactions, load factor */
    const double *base;             /* a case's installed state's displacements, or NULL */
    const ctn_vtu_subset *sub;      /* the piece written (NULL: every node and element) */
} vtu_data;

typedef enum vtu_where { VTU_POINT, VTU_CELL } vtu_where;

typedef struct vtu_field {
    const char *name;               /* the array's Name */
    vtu_where where;
    int ncomp;                      /* components per tuple: 1 or 3 */
    int integer;                    /* 1: written as Int32, else Float64 */
    /* NULL: one array named `name`. Else the number of arrays of the entry (0: none;
     * when numbered, NAME_1 .. NAME_count, else at most 1, named NAME). */
    size_t (*count)(const vtu_data *d);
    int numbered;
    /* The ncomp values of point or cell i of array j (0-based) into v; CTN_OK or
     * CTN_ERR_INVALID (a solution of another model). */
    int (*get)(const vtu_data *d, size_t j, size_t i, double *v);
} vtu_field;

/* displacement: from the reference geometry, or for a case from its installed state */
static int point_displacement(const vtu_data *d, size_t j, size_t i, double *v)
{
    (void)j;
    for (int c = 0; c < 3; c++) v[c] = d->st.d[3 * i + (size_t)c] - (d->base ? d->base[3 * i + (size_t)c] : 0.0);
    return CTN_OK;
}

/* displacement_total: a case's, from the reference geometry (beside `displacement`). */
static size_t has_base(const vtu_data *d) { return d->base != NULL; }

static int point_total(const vtu_data *d, size_t j, size_t i, double *v)
{
    (void)j;
    for (int c = 0; c < 3; c++) v[c] = d->st.d[3 * i + (size_t)c];
    return CTN_OK;
}

static int point_reaction(const vtu_data *d, size_t j, size_t i, double *v)
{
    (void)j;
    for (int c = 0; c < 3; c++) v[c] = d->st.react[3 * i + (size_t)c];
    return CTN_OK;
}

/* rotation, moment: the rotations and reaction moments of the nodes, arrays only in a
 * model with rotations (0 on a node without). */
static size_t has_rotations(const vtu_data *d) { return ctn_model_has_rotations(d->m) ? 1 : 0; }

static int point_rotation3(const vtu_data *d, size_t i, int moment, double *v)
{
    const double *rot = NULL, *mom = NULL;
    if (ctn_solution_step_rotations(d->s, d->k, &rot, &mom) || !rot) return CTN_ERR_INVALID;
    for (int c = 0; c < 3; c++) v[c] = (moment ? mom : rot)[3 * i + (size_t)c];
    return CTN_OK;
}

static int point_rotation(const vtu_data *d, size_t j, size_t i, double *v) { (void)j; return point_rotation3(d, i, 0, v); }
static int point_moment(const vtu_data *d, size_t j, size_t i, double *v) { (void)j; return point_rotation3(d, i, 1, v); }

/* One number of the state of element i at the step: the force, the stress (0 for a
 * spring: it has no section), the strain or slack (0 or 1). */
enum { CELL_FORCE, CELL_STRESS, CELL_STRAIN, CELL_SLACK };
static int cell_value(const vtu_data *d, size_t i, int which, double *v)
{
    ctn_element_info e;
    ctn_element_state es;
    if (ctn_model_element(d->m, i, &e) || ctn_solution_step_element(d->s, d->k, i, &es)) return CTN_ERR_INVALID;
    double values[4] = { es.force, e.has_section ? es.stress : 0, es.strain, es.slack };
    *v = values[which];
    return CTN_OK;
}

static int cell_force(const vtu_data *d, size_t j, size_t i, double *v) { (void)j; return cell_value(d, i, CELL_FORCE, v); }
static int cell_stress(const vtu_data *d, size_t j, size_t i, double *v) { (void)j; return cell_value(d, i, CELL_STRESS, v); }
static int cell_strain(const vtu_data *d, size_t j, size_t i, double *v) { (void)j; return cell_value(d, i, CELL_STRAIN, v); }
static int cell_slack(const vtu_data *d, size_t j, size_t i, double *v) { (void)j; return cell_value(d, i, CELL_SLACK, v); }

/* utilisation: N / (mbl / safety), 0 for members whose section has no mbl; an array
 * only when some section has one. */
static size_t has_capacity(const vtu_data *d)
{
    for (size_t i = 0; i < ctn_model_element_count(d->m); i++) {
        ctn_element_info e;
        if (!ctn_model_element(d->m, i, &e) && e.capacity > 0) return 1;
    }
    return 0;
}

static int cell_utilisation(const vtu_data *d, size_t j, size_t i, double *v)
{
    ctn_element_info e;
    ctn_element_state es;
    (void)j;
    if (ctn_model_element(d->m, i, &e) || ctn_solution_step_element(d->s, d->k, i, &es)) return CTN_ERR_INVALID;
    *v = ctn_utilisation(&e, &es);
    return CTN_OK;
}

/* mode_1 .. mode_n: the shapes of the modal analysis about the last step (mass-
 * normalized, 3 per node), in that step's files only. */
static size_t mode_count(const vtu_data *d)
{
    return d->k + 1 == ctn_solution_step_count(d->s) ? ctn_solution_mode_count(d->s) : 0;
}

static int point_mode(const vtu_data *d, size_t j, size_t i, double *v)
{
    ctn_mode md;
    if (ctn_solution_mode(d->s, j, &md) || i >= ctn_model_node_count(d->m)) return CTN_ERR_INVALID;
    for (int c = 0; c < 3; c++) v[c] = md.shape[3 * i + (size_t)c];
    return CTN_OK;
}

/* buckling_1 .. buckling_n: the shapes of the buckling analysis about the last step
 * (largest component 1), in that step's files only. */
static size_t buckling_count(const vtu_data *d)
{
    return d->k + 1 == ctn_solution_step_count(d->s) ? ctn_solution_buckling_count(d->s) : 0;
}

static int point_buckling(const vtu_data *d, size_t j, size_t i, double *v)
{
    ctn_buckling_mode b;
    if (ctn_solution_buckling(d->s, j, &b) || i >= ctn_model_node_count(d->m)) return CTN_ERR_INVALID;
    for (int c = 0; c < 3; c++) v[c] = b.shape[3 * i + (size_t)c];
    return CTN_OK;
}

/* The arrays, one entry each. */
static const vtu_field fields[] = {
    { "displacement", VTU_POINT, 3, 0, NULL, 0, point_displacement },
    { "displacement_total", VTU_POINT, 3, 0, has_base, 0, point_total },
    { "reaction", VTU_POINT, 3, 0, NULL, 0, point_reaction },
    { "rotation", VTU_POINT, 3, 0, has_rotations, 0, point_rotation },
    { "moment", VTU_POINT, 3, 0, has_rotations, 0, point_moment },
    { "force", VTU_CELL, 1, 0, NULL, 0, cell_force },
    { "stress", VTU_CELL, 1, 0, NULL, 0, cell_stress },
    { "strain", VTU_CELL, 1, 0, NULL, 0, cell_strain },
    { "slack", VTU_CELL, 1, 1, NULL, 0, cell_slack },
    { "utilisation", VTU_CELL, 1, 0, has_capacity, 0, cell_utilisation },
    { "mode", VTU_POINT, 3, 0, mode_count, 1, point_mode },
    { "buckling", VTU_POINT, 3, 0, buckling_count, 1, point_buckling },
};

#define NFIELDS (sizeof fields / sizeof *fields)

static void put_int(ctn_wbuf *b, long long v, char after)
{
    ctn_wbuf_int(b, v);
    ctn_wbuf_putc(b, after);
}

/* <DataArray type=... Name=... NumberOfComponents=... format="ascii">, name NULL: none. */
static void array_open(ctn_wbuf *b, const char *type, const char *name, size_t j, int numbered, int ncomp)
{
    ctn_wbuf_puts(b, "        <DataArray type=\"");
    ctn_wbuf_puts(b, type);
    if (name) {
        ctn_wbuf_puts(b, "\" Name=\"");
        ctn_wbuf_puts(b, name);
        if (numbered) {
            ctn_wbuf_putc(b, '_');
            ctn_wbuf_int(b, (long long)j + 1);
        }
    }
    ctn_wbuf_puts(b, "\" NumberOfComponents=\"");
    ctn_wbuf_int(b, ncomp);
    ctn_wbuf_puts(b, "\" format=\"ascii\">\n");
}

static void array_close(ctn_wbuf *b) { ctn_wbuf_puts(b, "        </DataArray>\n"); }

/* Array j of field f over its n points or cells, one tuple per line. */
/* The model's index of point or cell i of the piece written. */
static size_t global_index(const vtu_data *d, vtu_where where, size_t i)
{
    if (!d->sub) return i;
    return where == VTU_POINT ? d->sub->points[i] : d->sub->e0 + i;
}

static int put_array(ctn_writer *w, const vtu_data *d, const vtu_field *f, size_t j, size_t n)
{
    ctn_wbuf *b = &w->out;
    array_open(b, f->integer ? "Int32" : "Float64", f->name, j, f->numbered, f->ncomp);
    for (size_t i = 0; i < n && !b->err; i++) {
        double v[3];
        if (f->get(d, j, global_index(d, f->where, i), v)) return ctn_writer_mismatch(w);
        for (int c = 0; c < f->ncomp; c++) {
            if (c) ctn_wbuf_putc(b, ' ');
            if (f->integer) ctn_wbuf_int(b, (long long)v[c]);
            else ctn_wbuf_g17(b, v[c]);
        }
        ctn_wbuf_putc(b, '\n');
    }
    array_close(b);
    return b->err;
}

/* <PointData> or <CellData>: every array of the fields of that kind. */
static int put_data(ctn_writer *w, const vtu_data *d, vtu_where where, size_t n)
{
    ctn_wbuf_puts(&w->out, where == VTU_POINT ? "      <PointData>\n" : "      <CellData>\n");
    for (size_t f = 0; f < NFIELDS && !w->out.err; f++) {
        if (fields[f].where != where) continue;
        size_t count = fields[f].count ? fields[f].count(d) : 1;
        if (!fields[f].numbered && count > 1) count = 1;
        for (size_t j = 0; j < count; j++) {
            int rc = put_array(w, d, &fields[f], j, n);
            if (rc) return rc;
        }
    }
    ctn_wbuf_puts(&w->out, where == VTU_POINT ? "      </PointData>\n" : "      </CellData>\n");
    return w->out.err;
}

/* <Points>: the reference coordinates, plus d->base (a case's installed displacements)
 * unless NULL. */
static int put_points(ctn_writer *w, const vtu_data *d, size_t nn)
{
    ctn_wbuf *b = &w->out;
    ctn_wbuf_puts(b, "      <Points>\n");
    array_open(b, "Float64", "coordinates", 0, 0, 3);
    for (size_t i = 0; i < nn && !b->err; i++) {
        ctn_node_info p;
        size_t g = global_index(d, VTU_POINT, i);
        if (ctn_model_node(w->m, g, &p)) return ctn_writer_mismatch(w);
        for (int c = 0; c < 3; c++) {
            ctn_wbuf_g17(b, p.X[c] + (d->base ? d->base[3 * g + (size_t)c] : 0.0));
            ctn_wbuf_putc(b, c < 2 ? ' ' : '\n');
        }
    }
    array_close(b);
    ctn_wbuf_puts(b, "      </Points>\n");
    return b->err;
}

/* <Cells>: connectivity (node indices), offsets (the end of each cell's run) and types
 * (3 line, 4 polyline). A curved element drawn by sample points would add its points
 * after the nodes and be a polyline through them. */
static int put_cells(ctn_writer *w, const vtu_data *d, size_t ne)
{
    ctn_wbuf *b = &w->out;
    ctn_element_info e;
    long long end = 0;
    size_t e0 = d->sub ? d->sub->e0 : 0;
    ctn_wbuf_puts(b, "      <Cells>\n");
    array_open(b, "Int64", "connectivity", 0, 0, 1);
    for (size_t i = 0; i < ne && !b->err; i++) {
        if (ctn_model_element(w->m, e0 + i, &e)) return ctn_writer_mismatch(w);
        for (int k = 0; k < e.nnodes; k++)
            put_int(b, d->sub ? (long long)d->sub->local[e.nodes[k]] : (long long)e.nodes[k], k + 1 < e.nnodes ? ' ' : '\n');
    }
    array_close(b);
    array_open(b, "Int64", "offsets", 0, 0, 1);
    for (size_t i = 0; i < ne && !b->err && !ctn_model_element(w->m, e0 + i, &e); i++) put_int(b, end += e.nnodes, '\n');
    array_close(b);
    array_open(b, "UInt8", "types", 0, 0, 1);
    for (size_t i = 0; i < ne && !b->err && !ctn_model_element(w->m, e0 + i, &e); i++) put_int(b, e.nnodes == 2 ? 3 : 4, '\n');
    array_close(b);
    ctn_wbuf_puts(b, "      </Cells>\n");
    return b->err;
}

/* begin: open the output and print text; end: print text. */
int ctn_vtu_begin_with(void *p, const ctn_model *m, ctn_sink *sink, const char *text)
{
    ctn_writer *w = p;
    int rc = ctn_writer_open(w, m, sink);
    if (!rc) ctn_wbuf_puts(&w->out, text);
    return rc ? rc : w->out.err;
}

int ctn_vtu_end_with(void *p, const char *text)
{
    ctn_writer *w = p;
    ctn_wbuf_puts(&w->out, text);
    return w->out.err;
}

int ctn_vtu_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    return ctn_vtu_begin_with(p, m, sink, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                                  "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n");
}

int ctn_vtu_put_points(ctn_writer *w, const double *base, size_t nn)
{
    vtu_data d = { w->m, NULL, 0, { 0 }, base, NULL };
    return put_points(w, &d, nn);
}

int ctn_vtu_put_cells(ctn_writer *w, size_t ne)
{
    vtu_data d = { w->m, NULL, 0, { 0 }, NULL, NULL };
    return put_cells(w, &d, ne);
}

/* The piece of step k: field data, point data, cell data, points, cells; sub NULL: the
 * whole model. */
int ctn_vtu_put_piece(ctn_writer *w, const ctn_solution *s, size_t k, const ctn_vtu_subset *sub)
{
    vtu_data d = { w->m, s, k, { 0 }, NULL, sub };
    size_t nn = sub ? sub->npoints : ctn_model_node_count(w->m);
    size_t ne = sub ? sub->e1 - sub->e0 : ctn_model_element_count(w->m);
    ctn_step_result installed;
    if (ctn_solution_step(s, k, &d.st)) return ctn_writer_mismatch(w);
    if (w->base && ctn_solution_step(w->base, w->base_step, &installed)) return ctn_writer_mismatch(w);
    if (w->base) d.base = installed.d;
    ctn_wbuf *b = &w->out;
    ctn_wbuf_puts(b, "    <FieldData>\n");
    ctn_wbuf_puts(b, "      <DataArray type=\"Float64\" Name=\"load_factor\" NumberOfTuples=\"1\" format=\"ascii\">");
    ctn_wbuf_g17(b, d.st.load_factor);
    ctn_wbuf_puts(b, "</DataArray>\n    </FieldData>\n    <Piece NumberOfPoints=\"");
    ctn_wbuf_int(b, (long long)nn);
    ctn_wbuf_puts(b, "\" NumberOfCells=\"");
    ctn_wbuf_int(b, (long long)ne);
    ctn_wbuf_puts(b, "\">\n");
    int rc = put_data(w, &d, VTU_POINT, nn);
    if (!rc) rc = put_data(w, &d, VTU_CELL, ne);
    if (!rc) rc = put_points(w, &d, nn);
    if (!rc) rc = put_cells(w, &d, ne);
    ctn_wbuf_puts(b, "    </Piece>\n");
    return rc ? rc : b->err;
}

/* <PPointData> and <PCellData> of a .pvtu: the arrays a piece of step k holds. */
int ctn_vtu_put_parrays(ctn_writer *w, const ctn_solution *s, size_t k)
{
    vtu_data d = { w->m, s, k, { 0 }, NULL, NULL };
    ctn_wbuf *b = &w->out;
    for (int where = VTU_POINT; where <= VTU_CELL; where++) {
        ctn_wbuf_puts(b, where == VTU_POINT ? "    <PPointData>\n" : "    <PCellData>\n");
        for (size_t f = 0; f < NFIELDS; f++) {
            if ((int)fields[f].where != where) continue;
            size_t count = fields[f].count ? fields[f].count(&d) : 1;
            if (!fields[f].numbered && count > 1) count = 1;
            for (size_t j = 0; j < count; j++) {
                ctn_wbuf_puts(b, "      <PDataArray type=\"");
                ctn_wbuf_puts(b, fields[f].integer ? "Int32" : "Float64");
                ctn_wbuf_puts(b, "\" Name=\"");
                ctn_wbuf_puts(b, fields[f].name);
                if (fields[f].numbered) {
                    ctn_wbuf_putc(b, '_');
                    ctn_wbuf_int(b, (long long)j + 1);
                }
                ctn_wbuf_puts(b, "\" NumberOfComponents=\"");
                ctn_wbuf_int(b, fields[f].ncomp);
                ctn_wbuf_puts(b, "\"/>\n");
            }
        }
        ctn_wbuf_puts(b, where == VTU_POINT ? "    </PPointData>\n" : "    </PCellData>\n");
    }
    return b->err;
}

static int vtu_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    return k == w->step ? ctn_vtu_put_piece(w, s, k, NULL) : CTN_OK;
}

int ctn_vtu_end(void *p) { return ctn_vtu_end_with(p, "  </UnstructuredGrid>\n</VTKFile>\n"); }

const ctn_writer_ops ctn_writer_vtu = { .name = "result.vtu", .size = sizeof(ctn_writer), .begin = ctn_vtu_begin,
                                        .step = vtu_step, .end = ctn_vtu_end };

/* ---- result.pvd: the collection of the steps' files, for ParaView's time slider ---- */

void ctn_vtu_step_name(char *name, size_t k, size_t n)
{
    int width = 1;
    for (size_t v = n; v >= 10; v /= 10) width++;
    snprintf(name, CTN_VTU_NAME_MAX, "result_%0*zu.vtu", width, k + 1);
}

static int pvd_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    return ctn_vtu_begin_with(p, m, sink, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                                  "byte_order=\"LittleEndian\">\n  <Collection>\n");
}

/* Step k at time k + 1 (the step's number). */
static int pvd_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    char name[CTN_VTU_NAME_MAX];
    ctn_vtu_step_name(name, k, ctn_solution_step_count(s));
    ctn_wbuf_puts(&w->out, "    <DataSet timestep=\"");
    ctn_wbuf_int(&w->out, (long long)k + 1);
    ctn_wbuf_puts(&w->out, "\" group=\"\" part=\"0\" file=\"");
    ctn_wbuf_puts(&w->out, name);
    ctn_wbuf_puts(&w->out, "\"/>\n");
    return w->out.err;
}

static int pvd_end(void *p) { return ctn_vtu_end_with(p, "  </Collection>\n</VTKFile>\n"); }

const ctn_writer_ops ctn_writer_pvd = { .name = "result.pvd", .size = sizeof(ctn_writer), .begin = pvd_begin,
                                        .step = pvd_step, .end = pvd_end };
