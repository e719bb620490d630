/* Progress of long phases on stderr when it is a terminal: once a phase has run for
 * CTN_APP_PROGRESS_AFTER seconds, one line (rewritten in place, at most five times a
 * second) says what it is doing; it is cleared when the phase ends. */
#include "app.h"

#include <string.h>
#include <time.h>
#include <unistd.h>

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void ctn_app_progress_init(ctn_app_progress *p)
{
    *p = (ctn_app_progress){ isatty(STDERR_FILENO), "", seconds(), 0, 0 };
}

void ctn_app_progress_phase(ctn_app_progress *p, const char *what)
{
    ctn_app_progress_done(p);
    p->what = what;
    p->start = seconds();
}

void ctn_app_progress_done(ctn_app_progress *p)
{
    if (p->shown) fputs("\r\033[K", stderr);
    p->shown = 0;
}

/* 1 when a line is due: a terminal, the phase long enough, the last line 0.2 s old. */
static int due(ctn_app_progress *p, double *elapsed)
{
    double now = seconds();
    *elapsed = now - p->start;
    if (!p->tty || *elapsed < CTN_APP_PROGRESS_AFTER || now - p->last < 0.2) return 0;
    p->last = now;
    p->shown = 1;
    return 1;
}

void ctn_app_progress_report(void *data, const char *what, double done, double total)
{
    ctn_app_progress *p = data;
    double t;
    if (what != p->what && strcmp(what, p->what)) ctn_app_progress_phase(p, what);
    if (!due(p, &t)) return;
    if (total > 0) fprintf(stderr, "\r\033[Kcatena: %s: %.0f%% (%.1f of %.1f MB, %.0f s)", what,
                           100 * done / total, 1e-6 * done, 1e-6 * total, t);
    else fprintf(stderr, "\r\033[Kcatena: %s: %.1f MB (%.0f s)", what, 1e-6 * done, t);
    fflush(stderr);
}

void ctn_app_progress_iteration(ctn_app_progress *p, const ctn_iterate *it)
{
    double t;
    if (!due(p, &t)) return;
    fprintf(stderr, "\r\033[Kcatena: solving: iteration %d, |r| = %.3e (%.0f s)", it->iteration, it->residual, t);
    fflush(stderr);
}
