/* (b) Irvine's suspended cable: the first symmetric and antisymmetric in-plane modes and
 * the first out-of-plane mode against lambda^2 across the crossover 4 pi^2 (a level span
 * L = 100 m, w = 0.1 kN/m, sag L/50, EA swept), and where the shallow theory departs (sag
 * over span from 1/100 to 1/4 at a steel strand's EA). */
#include "modal_study.h"

#include <math.h>
#include <stdio.h>

#define NSWEEP 25
#define NTHEORY 200
#define NDEPTH 9

/* A level cable of span 100 m, w = 0.1 kN/m, 120 elements, EA, unstressed length S. */
static int cable_run(study_run *r, double EA, double S)
{
    char text[640];
    snprintf(text, sizeof text,
             "units kN m\nmaterial steel E=%.17g strain=engineering\nsection s material=steel A=1 w=0.1\n"
             "gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 100 0 0 fix=xyz\n"
             "cable 1 2 section=s n=120 length=%.17g shape=%s\nmodes count=10\n", EA, S, S > 100 ? "arc" : "straight");
    return study_solve(r, text);
}

/* EA and S for lambda^2 = target at sag d0 (shallow parabola: H = wL^2/(8d),
 * S = L (1 + 8/3 (d/L)^2) - H L_e / EA). */
static void design(double target, double *EA, double *S)
{
    const double L = 100, w = 0.1, d0 = 2, H0 = w * L * L / (8 * d0);
    double Le = L * (1 + 8 * (d0 / L) * (d0 / L)), H = H0, d = d0;
    *EA = target * H0 * Le / (pow(w * L / H0, 2) * L);
    for (int it = 0; it < 5; it++) {
        H = cbrt(pow(w * L, 2) * L * *EA / (target * Le));
        d = w * L * L / (8 * H);
        Le = L * (1 + 8 * (d / L) * (d / L));
    }
    *S = L * (1 + 8.0 / 3 * (d / L) * (d / L)) - H * Le / *EA;
}

static int theory_curve(ctn_ctx *ctx, const char *dir)
{
    double d[NTHEORY * 4];
    for (int i = 0; i < NTHEORY; i++) {
        double l2 = 0.5 * pow(1000.0, (double)i / (NTHEORY - 1));   /* 0.5 .. 500 */
        double row[4] = { l2, irvine_symmetric(l2), 2 * PI, PI };
        for (int k = 0; k < 4; k++) d[4 * i + k] = row[k];
    }
    return study_data(ctx, dir, "modal_irvine_theory.dat",
                      "Irvine: lambda^2, first symmetric in-plane, antisymmetric 2 pi, out-of-plane pi", 4, NTHEORY, d);
}

int study_irvine(ctn_ctx *ctx, const char *dir)
{
    double d[NSWEEP * 5];
    size_t n = 0;
    printf("\n(b) Irvine, sag/span 1/50: omega_bar = omega L / sqrt(H/m)\n\n"
           "| lambda^2 | symmetric FE | Irvine | antisymmetric FE (2 pi) | out-of-plane FE (pi) |\n"
           "|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < NSWEEP; i++) {
        double target = 1.0 * pow(300.0, (double)i / (NSWEEP - 1)), EA, S, l2, f0, sym, anti, out;
        study_run r;
        design(target, &EA, &S);
        int rc = cable_run(&r, EA, S);
        if (!rc) {
            irvine_parameters(&r, 100, 0.1, EA, &l2, &f0);
            study_first_kinds(&r, f0, &sym, &anti, &out);
            double row[5] = { l2, sym, anti, out, irvine_symmetric(l2) };
            for (int k = 0; k < 5; k++) d[5 * n + (size_t)k] = row[k];
            n++;
            printf("| %.4g | %.5f | %.5f | %.5f | %.5f |\n", l2, sym, irvine_symmetric(l2), anti, out);
        }
        study_free(&r);
        if (rc) return rc;
    }
    int rc = study_data(ctx, dir, "modal_irvine.dat",
                        "FE, sag/span 1/50: lambda^2, first symmetric, antisymmetric, out-of-plane omega_bar, "
                        "Irvine's symmetric", 5, n, d);
    if (!rc) rc = theory_curve(ctx, dir);
    ctn_plot_series s[6] = {
        { "modal_irvine_theory.dat", 1, 2, "Irvine: symmetric", CTN_PLOT_LINES, 1 },
        { "modal_irvine_theory.dat", 1, 3, "Irvine: antisymmetric 2{/Symbol p}", CTN_PLOT_LINES, 2 },
        { "modal_irvine_theory.dat", 1, 4, "Irvine: out of plane {/Symbol p}", CTN_PLOT_LINES, 3 },
        { "modal_irvine.dat", 1, 2, "catena: symmetric", CTN_PLOT_POINTS, 1 },
        { "modal_irvine.dat", 1, 3, "catena: antisymmetric", CTN_PLOT_POINTS, 2 },
        { "modal_irvine.dat", 1, 4, "catena: out of plane", CTN_PLOT_POINTS, 3 },
    };
    ctn_plot_figure f = { "modal_irvine", "Suspended cable, sag/span 1/50: first modes against Irvine's {/Symbol l}^2",
                          "{/Symbol l}^2", "{/Symbol w} L / (H/m)^{1/2}", 1, 0, "top left",
                          "set arrow from 39.478,graph 0 to 39.478,graph 1 nohead dashtype 3\n"
                          "set label \"{/Symbol l}^2 = 4{/Symbol p}^2\" at 45,3.5\nset xrange [0.5:500]", 6, s };
    return rc ? rc : study_figure(ctx, dir, &f);
}

/* Arc length of the parabola of sag ratio r over span L. */
static double parabola_length(double L, double r)
{
    return L / 2 * sqrt(1 + 16 * r * r) + L / (8 * r) * asinh(4 * r);
}

int study_depth(ctn_ctx *ctx, const char *dir)
{
    static const double ratios[NDEPTH] = { 0.01, 0.02, 0.04, 0.0625, 0.08333, 0.1, 0.125, 0.16667, 0.25 };
    const double EA = 2e8 * 3.14e-4;                    /* the paper's strand */
    double d[NDEPTH * 4];
    size_t n = 0;
    printf("\n(b) departure from the shallow theory, EA = %g kN: FE / Irvine - 1\n\n"
           "| sag/span | lambda^2 | symmetric | antisymmetric | out-of-plane |\n|---:|---:|---:|---:|---:|\n", EA);
    for (int i = 0; i < NDEPTH; i++) {
        double r0 = ratios[i], H = 0.1 * 100 * 100 / (8 * r0 * 100), l2, f0, sym, anti, out, sag = 0;
        study_run r;
        int rc = cable_run(&r, EA, parabola_length(100, r0) - H * 100 * (1 + 8 * r0 * r0) / EA);
        if (!rc) {
            irvine_parameters(&r, 100, 0.1, EA, &l2, &f0);
            study_first_kinds(&r, f0, &sym, &anti, &out);
            ctn_solution_cable_sag(r.m, r.s, 0, &sag);
            double row[4] = { sag / 100, sym / irvine_symmetric(l2) - 1, anti / (2 * PI) - 1, out / PI - 1 };
            for (int k = 0; k < 4; k++) d[4 * n + (size_t)k] = row[k];
            n++;
            printf("| 1/%.3g | %.4g | %+.4f | %+.4f | %+.4f |\n", 100 / sag, l2, row[1], row[2], row[3]);
        }
        study_free(&r);
        if (rc) return rc;
    }
    int rc = study_data(ctx, dir, "modal_depth.dat",
                        "sag/span, FE/Irvine - 1: first symmetric, antisymmetric, out-of-plane", 4, n, d);
    ctn_plot_series s[3] = {
        { "modal_depth.dat", 1, 2, "symmetric in-plane", CTN_PLOT_LINESPOINTS, 1 },
        { "modal_depth.dat", 1, 3, "antisymmetric in-plane", CTN_PLOT_LINESPOINTS, 2 },
        { "modal_depth.dat", 1, 4, "out of plane", CTN_PLOT_LINESPOINTS, 3 },
    };
    ctn_plot_figure f = { "modal_depth", "Where the shallow theory departs (span 100 m, EA = 62 800 kN)", "sag / span",
                          "{/Symbol w}_{FE} / {/Symbol w}_{Irvine} - 1", 0, 0, "bottom left",
                          "set arrow from 0.125,graph 0 to 0.125,graph 1 nohead dashtype 3", 3, s };
    return rc ? rc : study_figure(ctx, dir, &f);
}
