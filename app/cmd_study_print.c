/* The tables and the JSON of `catena study` (cmd_study.c). */
#include "app.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* "FEA", or "element" when each row is one catenary element. */
static const char *fea_label(const ctn_study *st)
{
    return ctn_study_element_kind(st) == CTN_STUDY_CATENARY ? "element" : "FEA";
}

static void print_marked(const ctn_study *st)
{
    const ctn_span *s = ctn_study_span(st);
    const char *fea = fea_label(st);
    char L[16], S[16], h[3][16];
    snprintf(L, sizeof L, "[%s]", s->length_unit);
    snprintf(S, sizeof S, "[%s]", s->mpa > 0 ? "MPa" : "F/L^2");
    snprintf(h[0], sizeof h[0], "sag %s", *fea == 'e' ? "el." : fea);
    snprintf(h[1], sizeof h[1], "s_max %s", *fea == 'e' ? "el." : fea);
    snprintf(h[2], sizeof h[2], "s_min %s", *fea == 'e' ? "el." : fea);
    if (*fea == 'e') printf("\nThe catenary element (one per length) against the inextensible catenary at the marked lengths\n"
                            "(difference = (catenary - element) / element)\n");
    else printf("\nFEA against the inextensible catenary at the marked lengths (difference = (catenary - FEA) / FEA)\n");
    printf("%10s %4s | %9s %9s %7s | %9s %9s %7s | %9s %9s %7s\n", "L0", "it", h[0], "catenary", "diff",
           h[1], "catenary", "diff", h[2], "catenary", "diff");
    printf("%10s %4s | %9s %9s %7s | %9s %9s %7s | %9s %9s %7s\n", L, "", L, L, "[%]", S, S, "[%]", S, S, "[%]");
    for (size_t i = 0; i < ctn_study_count(st); i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        if (!r->marked) continue;
        const ctn_compare_values *f = &r->v[CTN_FORM_FEA], *c = &r->v[CTN_FORM_CATENARY];
        printf("%10.4f %4d", r->L0, r->iterations);
        if (!(r->present & 1u << CTN_FORM_FEA)) { printf("  %s not converged: %s\n", fea, ctn_reason_name(r->reason)); continue; }
        if (!(r->present & 1u << CTN_FORM_CATENARY)) { printf("  no catenary (not longer than the chord)\n"); continue; }
        printf(" | %9.4f %9.4f %+7.2f | %9.3f %9.3f %+7.2f | %9.3f %9.3f %+7.2f\n", f->sag, c->sag,
               100 * ctn_compare_rel(c->sag, f->sag), ctn_app_stress(s, f->stress_max), ctn_app_stress(s, c->stress_max),
               100 * ctn_compare_rel(c->stress_max, f->stress_max), ctn_app_stress(s, f->stress_min),
               ctn_app_stress(s, c->stress_min), 100 * ctn_compare_rel(c->stress_min, f->stress_min));
    }
}

/* Relative difference of a from the element b, or "-" when a is absent. */
static void print_rel(int has, double a, double b)
{
    if (has) printf(" %+10.2e", ctn_compare_rel(a, b));
    else printf(" %10s", "-");
}

/* The catenary element against the elastic catenary (the same law, so round-off) and the
 * span's mesh (its strain law and discretization) at the marked lengths. */
static void print_mesh(const ctn_study *st)
{
    const ctn_span *s = ctn_study_span(st);
    int any = 0;
    for (size_t i = 0; i < ctn_study_count(st); i++) any |= ctn_study_row_at(st, i)->has_mesh;
    if (!any) return;
    printf("\nThe catenary element against the elastic catenary and the FE mesh (%zu cable elements, %s strain)\n"
           "at the marked lengths (relative difference = (X - element) / element)\n", s->n,
           s->strain == CTN_STRAIN_ENGINEERING ? "engineering" : "Green-Lagrange");
    printf("%10s | %10s %10s %10s | %10s %10s %10s | %10s %10s\n", "L0", "sag el.", "elastic", "mesh", "s_max el.",
           "elastic", "mesh", "H elastic", "H mesh");
    for (size_t i = 0; i < ctn_study_count(st); i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        if (!r->marked) continue;
        const ctn_compare_values *f = &r->v[CTN_FORM_FEA], *e = &r->v[CTN_FORM_ECATENARY], *m = &r->mesh;
        int he = (r->present & 1u << CTN_FORM_ECATENARY) != 0;
        printf("%10.4f |", r->L0);
        if (!(r->present & 1u << CTN_FORM_FEA)) { printf(" element not converged: %s\n", ctn_reason_name(r->reason)); continue; }
        printf(" %10.4f", f->sag);
        print_rel(he, e->sag, f->sag);
        print_rel(r->has_mesh, m->sag, f->sag);
        printf(" | %10.3f", ctn_app_stress(s, f->stress_max));
        print_rel(he, e->stress_max, f->stress_max);
        print_rel(r->has_mesh, m->stress_max, f->stress_max);
        printf(" |");
        print_rel(he, e->H, f->H);
        print_rel(r->has_mesh, m->H, f->H);
        putchar('\n');
    }
}

/* The claim at this level, or 0. */
static double claim_at(const double *claims, size_t nclaims, double level)
{
    for (size_t i = 0; i < nclaims; i++)
        if (fabs(claims[2 * i] - level) <= 1e-9 * level) return claims[2 * i + 1];
    return 0;
}

static void print_level(const ctn_study *st, ctn_level_axis axis, double level)
{
    const ctn_span *s = ctn_study_span(st);
    ctn_study_level L;
    ctn_study_level_at(st, axis, s->mpa > 0 ? level / s->mpa : level, &L);
    if (!L.found) printf(" %10s %8s %8s %8s |", "-", "", "", "");
    else printf(" %10.4f %+8.2f %+8.2f %+8.2f |", L.L0, 100 * L.err_max, 100 * L.err_min, 100 * L.err_sag);
}

/* Largest |difference| over the rows past the least FEA support stress (slack branch). */
static void print_slack(const ctn_study *st)
{
    const ctn_span *s = ctn_study_span(st);
    const unsigned both = 1u << CTN_FORM_FEA | 1u << CTN_FORM_CATENARY;
    size_t n = ctn_study_count(st), end = n, k = 0;
    double best = INFINITY, e[3] = { 0, 0, 0 }, lo = INFINITY, hi = 0;
    for (size_t i = 0; i < n; i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        if ((r->present & both) == both && r->v[CTN_FORM_FEA].stress_max < best) best = r->v[CTN_FORM_FEA].stress_max, end = i;
    }
    for (size_t i = end + 1; i < n; i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        if ((r->present & both) != both) continue;
        const ctn_compare_values *f = &r->v[CTN_FORM_FEA], *c = &r->v[CTN_FORM_CATENARY];
        e[0] = fmax(e[0], fabs(ctn_compare_rel(c->stress_max, f->stress_max)));
        e[1] = fmax(e[1], fabs(ctn_compare_rel(c->stress_min, f->stress_min)));
        e[2] = fmax(e[2], fabs(ctn_compare_rel(c->sag, f->sag)));
        lo = fmin(lo, f->stress_max), hi = fmax(hi, f->stress_max), k++;
    }
    if (!k) return;
    printf("slack branch (L0 > %.4f %s, %zu length%s, %s support stress %.4g to %.4g %s): |difference| at most\n"
           "  %.2f %% (support stress), %.2f %% (vertex stress), %.2f %% (sag)\n", ctn_study_row_at(st, end)->L0,
           s->length_unit, k, k > 1 ? "s" : "", fea_label(st), ctn_app_stress(s, lo), ctn_app_stress(s, hi),
           s->mpa > 0 ? "MPa" : "F/L^2", 100 * e[0], 100 * e[1], 100 * e[2]);
}

static int by_value(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* The error table at the levels (and at the claims' stresses, added to the list). */
static void print_levels(const ctn_study *st, double *levels, size_t nlevels, size_t cap,
                         const double *claims, size_t nclaims)
{
    for (size_t i = 0; i < nclaims && nlevels < cap; i++) {
        size_t j = 0;
        while (j < nlevels && fabs(levels[j] - claims[2 * i]) > 1e-9 * claims[2 * i]) j++;
        if (j == nlevels) levels[nlevels++] = claims[2 * i];
    }
    qsort(levels, nlevels, sizeof *levels, by_value);
    char su[16], L[16];
    snprintf(su, sizeof su, "[%s]", ctn_study_span(st)->mpa > 0 ? "MPa" : "F/L^2");
    snprintf(L, sizeof L, "L0 [%s]", ctn_study_span(st)->length_unit);
    const char *fea = fea_label(st);
    char lv[48];
    snprintf(lv, sizeof lv, "level = %s support stress", fea);
    printf("\nDifference of the inextensible catenary from the %s against the stress level, in %%\n"
           "(taut branch of the sweep, interpolated; the level is the support stress of the %s or of the catenary)\n", fea, fea);
    printf("%8s | %37s | %37s |%s\n", "level", lv, "level = catenary support stress", nclaims ? " reference" : "");
    printf("%8s | %10s %8s %8s %8s | %10s %8s %8s %8s |%s\n", su, L, "s_max", "s_min", "sag", L, "s_max",
           "s_min", "sag", nclaims ? "       [%]" : "");
    for (size_t i = 0; i < nlevels; i++) {
        printf("%8.6g |", levels[i]);
        print_level(st, CTN_LEVEL_FEA, levels[i]);
        print_level(st, CTN_LEVEL_CATENARY, levels[i]);
        double c = claim_at(claims, nclaims, levels[i]);
        if (c > 0) printf(" %9.4g", c);
        putchar('\n');
    }
    print_slack(st);
}

static void print_summary(const ctn_study *st, const char *model, size_t sweep)
{
    size_t n = ctn_study_count(st), fb = 0, bad = 0;
    for (size_t i = 0; i < n; i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        fb += r->fallback;
        bad += !(r->present & 1u << CTN_FORM_FEA);
    }
    const ctn_span *s = ctn_study_span(st);
    printf("%s\n", model);
    ctn_app_print_span(stdout, s);
    printf("%zu lengths from %.6g to %.6g %s (a sweep of %zu and the marked ones): ", n,
           ctn_study_row_at(st, 0)->L0, ctn_study_row_at(st, n - 1)->L0, s->length_unit, sweep);
    if (ctn_study_element_kind(st) == CTN_STUDY_CATENARY) printf("each length one catenary element: ");
    if (!fb && !bad) printf("every FEA converged with the model's solver\n");
    else printf("%zu solved only by the globalized Newton, %zu did not converge\n", fb, bad);
}

int ctn_app_study_json(const ctn_study *st, const char *model)
{
    cJSON *root = cJSON_CreateObject(), *rows = root ? cJSON_AddArrayToObject(root, "rows") : NULL;
    int ok = rows && cJSON_AddStringToObject(root, "model", model) &&
             cJSON_AddNumberToObject(root, "mpa_factor", ctn_study_span(st)->mpa) &&
             cJSON_AddStringToObject(root, "element", ctn_study_element_kind(st) == CTN_STUDY_CATENARY ? "catenary" : "mesh");
    for (size_t i = 0; ok && i < ctn_study_count(st); i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        cJSON *o = cJSON_CreateObject();
        ok = o && cJSON_AddItemToArray(rows, o);
        if (!ok) { cJSON_Delete(o); break; }
        ok = cJSON_AddNumberToObject(o, "length", r->L0) && cJSON_AddBoolToObject(o, "marked", r->marked) &&
             cJSON_AddBoolToObject(o, "converged", (r->present & 1u) != 0) &&
             cJSON_AddNumberToObject(o, "iterations", r->iterations) && cJSON_AddBoolToObject(o, "fallback", r->fallback);
        for (int f = 0; ok && f < CTN_FORM_COUNT; f++)
            if (r->present >> f & 1u)
                ok = ctn_app_values_json(o, ctn_form_key((ctn_form)f), &r->v[f],
                                         f && (r->present & 1u) ? &r->v[CTN_FORM_FEA] : NULL) != NULL;
        if (ok && r->has_mesh)
            ok = ctn_app_values_json(o, "mesh", &r->mesh, (r->present & 1u) ? &r->v[CTN_FORM_FEA] : NULL) != NULL;
    }
    int code = ctn_app_print_json(ok ? root : NULL);
    cJSON_Delete(root);
    return code;
}

void ctn_app_study_report(const ctn_study *st, const char *model, size_t sweep, double *levels,
                          size_t nlevels, size_t cap, const double *claims, size_t nclaims)
{
    print_summary(st, model, sweep);
    print_marked(st);
    print_mesh(st);
    print_levels(st, levels, nlevels, cap, claims, nclaims);
}
