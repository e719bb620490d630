/* (c) The founding paper's four cables (examples/paper/, 20 elements, Green-Lagrange,
 * their weight as mass) against Irvine's predictions; (d) a hypar net under snow, the
 * mesh convergence of its lowest frequencies to those of the membrane it discretizes. */
#include "modal_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int paper_cable(const char *root, const char *name)
{
    char path[512];
    study_run r;
    ctn_solve_options opt;
    memset(&r, 0, sizeof r);
    snprintf(path, sizeof path, "%s/examples/paper/%s.cable", root, name);
    int rc = ctn_ctx_create(&r.ctx);
    if (!rc) rc = ctn_read_file(r.ctx, path, &r.m, &opt);
    opt.modal.count = 10;
    if (!rc) rc = ctn_solve(r.ctx, r.m, &opt, &r.s);
    if (!rc && !ctn_solution_mode_count(r.s)) rc = CTN_ERR_NOCONV;
    if (rc) fprintf(stderr, "modal_study: %s: %s\n", path, ctn_ctx_message(r.ctx));
    if (!rc) {
        double l2, f0, sym, anti, out, sag = 0;
        irvine_parameters(&r, 200, 0.1, 2e8 * 3.14e-4, &l2, &f0);
        study_first_kinds(&r, f0, &sym, &anti, &out);
        ctn_solution_cable_sag(r.m, r.s, 0, &sag);
        printf("| %s | 1/%.3g | %.4g | %.4f | %.4f (%+.2f %%) | %.4f (%+.2f %%) | %.4f (%+.2f %%) |\n", name + 1,
               200 / sag, l2, f0 * out, f0 * anti, 100 * (anti / (2 * PI) - 1), f0 * sym,
               100 * (sym / irvine_symmetric(l2) - 1), f0 * out, 100 * (out / PI - 1));
    }
    study_free(&r);
    return rc;
}

int study_paper(const char *root)
{
    static const char *const names[4] = { "s200.3340", "s201.3545", "s250.8777", "s279.6157" };
    printf("\n(c) the paper's cables: first frequencies [Hz], FE (difference from Irvine)\n\n"
           "| L0 [m] | sag/span | lambda^2 | out-of-plane | antisymmetric in-plane | symmetric in-plane | "
           "out-of-plane vs pi |\n|---|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < 4; i++)
        if (paper_cable(root, names[i])) return CTN_ERR_NOCONV;
    return CTN_OK;
}

/* A K x K hypar net on a 100 m square, z = 10 (x^2 - y^2)/50^2, edges pinned; strands
 * prestressed to n0 = 10 kN per m of width (N0 = 10 h), mass 0.02 t/m^2 (m = 0.01 h t/m
 * per strand), a load of 0.05 kN/m^2 on the nodes (0.05 h^2), tension-only: the same
 * membrane at every K, taut everywhere (the load changes the tensions by about
 * q / (2 kappa) = 3 kN/m, kappa = 0.008 1/m the curvature). */
static char *net_text(int K, const char *mass)
{
    size_t cap = (size_t)(K + 1) * (K + 1) * 200 + 1024, n = 0;
    char *t = malloc(cap);
    double h = 100.0 / K;
    if (!t) return NULL;
    n += (size_t)snprintf(t + n, cap - n, "units kN m\nmaterial strand E=1.6e8 tension-only\n"
                          "section s material=strand A=1.5e-4 mass=%.17g\nmodes count=6 mass=%s\n", 0.01 * h, mass);
    for (int i = 0; i <= K; i++)
        for (int j = 0; j <= K; j++) {
            double x = -50 + i * h, y = -50 + j * h;
            n += (size_t)snprintf(t + n, cap - n, "node %d %.17g %.17g %.17g%s\n", i * (K + 1) + j + 1, x, y,
                                  10 * (x * x - y * y) / 2500, i % K && j % K ? "" : " fix=xyz");
        }
    int e = 1;
    for (int i = 0; i <= K; i++)
        for (int j = 0; j <= K; j++)
            for (int dir = 0; dir < 2; dir++) {
                int i2 = i + (dir == 0), j2 = j + (dir == 1);
                if (i2 > K || j2 > K || (dir == 1 && i % K == 0) || (dir == 0 && j % K == 0)) continue;
                n += (size_t)snprintf(t + n, cap - n, "element %d %d %d section=s N0=%.17g\n", e++,
                                      i * (K + 1) + j + 1, i2 * (K + 1) + j2 + 1, 10 * h);
            }
    for (int i = 1; i < K; i++)
        for (int j = 1; j < K; j++)
            n += (size_t)snprintf(t + n, cap - n, "load %d 0 0 %.17g\n", i * (K + 1) + j + 1, -0.05 * h * h);
    return t;
}

#define NNET 4

int study_net(ctn_ctx *ctx, const char *dir)
{
    double d[NNET * 13];
    printf("\n(d) hypar net, lowest 6 frequencies [Hz] (consistent / lumped)\n\n"
           "| K | DOFs | f_1 | f_2 | f_3 | f_4 | f_5 | f_6 |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int lev = 0; lev < NNET; lev++) {
        int K = 8 << lev;
        d[13 * lev] = K;
        for (int lumped = 0; lumped < 2; lumped++) {
            char *t = net_text(K, lumped ? "lumped" : "consistent");
            study_run r;
            int rc = t ? study_solve(&r, t) : CTN_ERR_NOMEM;
            free(t);
            for (int k = 0; k < 6 && !rc; k++) d[13 * lev + 1 + 6 * lumped + k] = study_freq(&r, (size_t)k);
            study_free(&r);
            if (rc) return rc;
        }
        printf("| %d | %d |", K, 3 * (K - 1) * (K - 1));
        for (int k = 0; k < 6; k++) printf(" %.4f / %.4f |", d[13 * lev + 1 + k], d[13 * lev + 7 + k]);
        printf("\n");
    }
    int rc = study_data(ctx, dir, "modal_net.dat", "hypar net: K, f_1..f_6 consistent, f_1..f_6 lumped [Hz]",
                        13, NNET, d);
    ctn_plot_series s[6];
    static const char *const titles[6] = { "mode 1, consistent", "mode 1, lumped", "mode 3, consistent",
                                           "mode 3, lumped", "mode 6, consistent", "mode 6, lumped" };
    static const int cols[6] = { 2, 8, 4, 10, 7, 13 };
    for (int i = 0; i < 6; i++)
        s[i] = (ctn_plot_series){ "modal_net.dat", 1, cols[i], titles[i], i % 2 ? CTN_PLOT_DASHED : CTN_PLOT_LINESPOINTS,
                                  i / 2 + 1 };
    ctn_plot_figure f = { "modal_net", "Prestressed hypar net, 100 m x 100 m: frequencies against mesh", "strands per side K",
                          "frequency [Hz]", 1, 0, "bottom right", "set xrange [6:80]\nset yrange [0.2:0.55]", 6, s };
    return rc ? rc : study_figure(ctx, dir, &f);
}
