/* Model definitions: units, gravity, materials, sections. */
#include "model/model.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int finite3(const double v[3]) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

int ctn_model_set_gravity(ctn_model *m, const double g[3])
{
    if (!m || !g) return CTN_ERR_INVALID;
    if (!finite3(g)) return ctn_model_error(m, CTN_ERR_MODEL, "gravity must be finite");
    double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2], big = fmax(fmax(fabs(g[0]), fabs(g[1])), fabs(g[2]));
    if (!isfinite(g2) || (big > 0 && !(g2 > 0x1p-1000)))      /* its length squared: every use */
        return ctn_model_error(m, CTN_ERR_MODEL, "gravity (%g, %g, %g) is beyond double precision: its length "
                               "squared %s; scale the units", g[0], g[1], g[2], isfinite(g2) ? "underflows" : "overflows");
    memcpy(m->gravity, g, sizeof m->gravity);
    m->gravity_line = m->line;
    return CTN_OK;
}

static int check_name(const ctn_model *m, const char *what, const char *name)
{
    if (!name || !*name) return ctn_model_error(m, CTN_ERR_MODEL, "%s name is empty", what);
    if (strlen(name) >= CTN_NAME_MAX)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s name longer than %d characters", what, CTN_NAME_MAX - 1);
    return CTN_OK;
}

void ctn_material_spec_init(ctn_material_spec *s)
{
    if (!s) return;
    memset(s, 0, sizeof *s);
    s->size = sizeof *s;
    s->strain = CTN_STRAIN_GREEN_LAGRANGE;
}

void ctn_section_spec_init(ctn_section_spec *s)
{
    if (!s) return;
    memset(s, 0, sizeof *s);
    s->size = sizeof *s;
    s->safety = 1;
    s->mass = CTN_MASS_DEFAULT;
}

int ctn_model_add_material(ctn_model *m, const char *name, double E, ctn_strain strain,
                           int tension_only)
{
    ctn_material_spec s;
    ctn_material_spec_init(&s);
    s.name = name;
    s.E = E;
    s.strain = strain;
    s.tension_only = tension_only;
    return ctn_model_add_material_spec(m, &s);
}

int ctn_model_add_section(ctn_model *m, const char *name, const char *material, double A,
                          double w)
{
    ctn_section_spec s;
    ctn_section_spec_init(&s);
    s.name = name;
    s.material = material;
    s.A = A;
    s.w = w;
    return ctn_model_add_section_spec(m, &s);
}

int ctn_model_add_material_spec(ctn_model *m, const ctn_material_spec *spec)
{
    if (!m || !spec || spec->size < sizeof(size_t)) return CTN_ERR_INVALID;
    ctn_material_spec s;
    ctn_material_spec_init(&s);
    ctn_spec_copy(&s, sizeof s, spec);
    const char *name = s.name;
    double E = s.E;
    ctn_strain strain = s.strain;
    int tension_only = s.tension_only, rc = check_name(m, "material", name);
    if (rc) return rc;
    if (ctn_model_find_material(m, name) >= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "duplicate material '%s'", name);
    if (!isfinite(E) || E <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "material '%s': E must be positive and finite (got %g)", name, E);
    if (strain != CTN_STRAIN_GREEN_LAGRANGE && strain != CTN_STRAIN_ENGINEERING)
        return ctn_model_error(m, CTN_ERR_MODEL, "material '%s': unknown strain measure", name);
    if (!isfinite(s.alpha) || fabs(s.alpha) >= 0.01)
        return ctn_model_error(m, CTN_ERR_MODEL, "material '%s': alpha must be finite and below 0.01 per kelvin in size (got %g)", name, s.alpha);
    if (!isfinite(s.G) || s.G < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "material '%s': G must be >= 0 and finite (got %g)", name, s.G);
    if (!isfinite(s.fy) || s.fy < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "material '%s': fy must be positive and finite (got %g)", name, s.fy);
    if ((rc = CTN_ARRAY_RESERVE(m->ctx, m->materials, 1))) return rc;
    ctn_material *p = &m->materials.v[m->materials.n++];
    snprintf(p->name, sizeof p->name, "%s", name);
    p->E = E;
    p->strain = strain;
    p->tension_only = tension_only != 0;
    p->alpha = s.alpha;
    p->G = s.G;
    p->fy = s.fy;
    return CTN_OK;
}

/* The beam properties of a section: each >= 0 and finite. */
static int check_beam(const ctn_model *m, const ctn_section_spec *s)
{
    const char *key[7] = { "Iy", "Iz", "J", "Asy", "Asz", "Wy", "Wz" };
    const double v[7] = { s->Iy, s->Iz, s->J, s->Asy, s->Asz, s->Wy, s->Wz };
    for (int k = 0; k < 7; k++)
        if (!isfinite(v[k]) || v[k] < 0)
            return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': %s must be >= 0 and finite (got %g)", s->name, key[k], v[k]);
    return CTN_OK;
}

int ctn_model_add_section_spec(ctn_model *m, const ctn_section_spec *spec)
{
    if (!m || !spec || spec->size < sizeof(size_t)) return CTN_ERR_INVALID;
    ctn_section_spec s;
    ctn_section_spec_init(&s);
    ctn_spec_copy(&s, sizeof s, spec);
    const char *name = s.name, *material = s.material;
    double A = s.A, w = s.w;
    int rc = check_name(m, "section", name);
    if (rc) return rc;
    if (ctn_model_find_section(m, name) >= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "duplicate section '%s'", name);
    int mat = material ? ctn_model_find_material(m, material) : -1;
    if (mat < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': undefined material '%s'", name,
                               material ? material : "");
    if (!isfinite(A) || A <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': A must be positive and finite (got %g)", name, A);
    if (!isfinite(w) || w < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': w must be >= 0 and finite (got %g)", name, w);
    if (!isfinite(s.mbl) || s.mbl < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': mbl must be positive and finite (got %g)", name, s.mbl);
    if (!isfinite(s.safety) || s.safety <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': safety must be positive and finite (got %g)", name, s.safety);
    if (s.mass != CTN_MASS_DEFAULT && !(isfinite(s.mass) && s.mass >= 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': mass must be >= 0 and finite (got %g)", name, s.mass);
    if (!isfinite(m->materials.v[mat].E * A))
        return ctn_model_error(m, CTN_ERR_MODEL, "section '%s': E A = %g * %g overflows", name, m->materials.v[mat].E, A);
    if ((rc = check_beam(m, &s))) return rc;
    if ((rc = CTN_ARRAY_RESERVE(m->ctx, m->sections, 1))) return rc;
    ctn_section *p = &m->sections.v[m->sections.n++];
    snprintf(p->name, sizeof p->name, "%s", name);
    p->material = mat;
    p->A = A;
    p->w = w;
    p->line = m->line;
    p->mbl = s.mbl;
    p->safety = s.safety;
    p->mass = s.mass;
    p->Iy = s.Iy;
    p->Iz = s.Iz;
    p->J = s.J;
    p->Asy = s.Asy;
    p->Asz = s.Asz;
    p->Wy = s.Wy;
    p->Wz = s.Wz;
    return CTN_OK;
}
