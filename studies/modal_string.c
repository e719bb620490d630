/* (a) The taut string: f_j = j/(2L) sqrt(T/m'), m' the stretched mass per length, and
 * the O(h^2) convergence of both mass matrices (1 m, 0.01 kg/m, T = 100 N). */
#include "modal_study.h"

#include <math.h>
#include <stdio.h>

#define NLEV 6

/* Relative errors of modes j = 1, 2, 3 (the y of each double pair) with N elements. */
static int errors(int N, int lumped, double err[3])
{
    const double T = 100, EA = 2e11 * 1e-6, mp = 0.01 / (1 + T / EA);
    char text[512];
    study_run r;
    snprintf(text, sizeof text,
             "units N m\nmaterial steel E=2e11 strain=engineering\nsection s material=steel A=1e-6 mass=0.01\n"
             "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\n"
             "cable 1 2 section=s n=%d length=1 shape=straight N0=100\nmodes count=6 mass=%s\n", N,
             lumped ? "lumped" : "consistent");
    int rc = study_solve(&r, text);
    for (int j = 1; j <= 3 && !rc; j++) {
        double fc = j / 2.0 * sqrt(T / mp);
        err[j - 1] = (study_freq(&r, (size_t)(2 * (j - 1))) - fc) / fc;
    }
    study_free(&r);
    return rc;
}

int study_string(ctn_ctx *ctx, const char *dir)
{
    double d[NLEV * 8];
    printf("\n(a) taut string, relative error of f_j (consistent | lumped)\n\n"
           "| N | f_1 | f_2 | f_3 | f_1 | f_2 | f_3 |\n|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int lev = 0; lev < NLEV; lev++) {
        int N = 4 << lev;
        double ec[3], el[3];
        if (errors(N, 0, ec) || errors(N, 1, el)) return CTN_ERR_NOCONV;
        double row[8] = { N, ec[0], ec[1], ec[2], -el[0], -el[1], -el[2], 0.5 / ((double)N * N) };
        for (int k = 0; k < 8; k++) d[8 * lev + k] = row[k];
        printf("| %d | %+.3e | %+.3e | %+.3e | %+.3e | %+.3e | %+.3e |\n", N, ec[0], ec[1], ec[2], el[0], el[1], el[2]);
    }
    int rc = study_data(ctx, dir, "modal_string.dat",
                        "taut string: relative error of f_j against j/(2L) sqrt(T/m')\n"
                        "N  consistent j=1 2 3  lumped (negated) j=1 2 3  guide 1/(2 N^2)", 8, NLEV, d);
    ctn_plot_series s[7] = {
        { "modal_string.dat", 1, 2, "consistent, mode 1", CTN_PLOT_LINESPOINTS, 1 },
        { "modal_string.dat", 1, 3, "consistent, mode 2", CTN_PLOT_LINESPOINTS, 2 },
        { "modal_string.dat", 1, 4, "consistent, mode 3", CTN_PLOT_LINESPOINTS, 3 },
        { "modal_string.dat", 1, 5, "lumped, mode 1 (-error)", CTN_PLOT_DASHED, 1 },
        { "modal_string.dat", 1, 6, "lumped, mode 2 (-error)", CTN_PLOT_DASHED, 2 },
        { "modal_string.dat", 1, 7, "lumped, mode 3 (-error)", CTN_PLOT_DASHED, 3 },
        { "modal_string.dat", 1, 8, "slope -2", CTN_PLOT_DASHED, 8 },
    };
    ctn_plot_figure f = { "modal_string", "Taut string: frequency error against elements (T = 100 N, m = 0.01 kg/m)",
                          "elements N", "|f_{FE} - f| / f", 1, 1, "top right", "set xrange [3:200]", 7, s };
    return rc ? rc : study_figure(ctx, dir, &f);
}
