/* Rendering a figure: run gnuplot on its script, in the script's directory. */
#include "plot/plot_int.h"
#include "catena/plot.h"

#include <errno.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

extern char **environ;

/* The gnuplot command "cd 'DIR'" (single quotes doubled inside gnuplot's '...'). */
static char *cd_command(ctn_ctx *ctx, const char *dir)
{
    size_t n = strlen(dir), k = 0;
    char *s = ctn_malloc(ctx, 2 * n + 8, 1);
    if (!s) return NULL;
    memcpy(s, "cd '", 4);
    k = 4;
    for (size_t i = 0; i < n; i++) {
        if (dir[i] == '\'') s[k++] = '\'';
        s[k++] = dir[i];
    }
    s[k++] = '\'';
    s[k] = '\0';
    return s;
}

/* Wait for the child; CTN_OK if it exited with status 0. */
static int wait_child(ctn_ctx *ctx, pid_t pid, const char *prog, const char *script)
{
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return ctn_error(ctx, CTN_ERR_IO, "%s: waitpid failed: %s", prog, strerror(errno));
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return CTN_OK;
    return ctn_error(ctx, CTN_ERR_IO, "%s %s failed (%s %d)", prog, script,
                     WIFEXITED(status) ? "exit status" : "signal",
                     WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
}

int ctn_plot_render(ctn_ctx *ctx, const char *dir, const char *name, int *rendered)
{
    if (!dir || !ctn_plot_name_ok(name) || !rendered || strlen(name) > 60)
        return ctn_error(ctx, CTN_ERR_INVALID, "ctn_plot_render: bad arguments");
    *rendered = 0;
    const char *prog = getenv("CATENA_GNUPLOT");
    if (!prog || !*prog) prog = "gnuplot";
    char script[72];
    snprintf(script, sizeof script, "%s.gp", name);
    char *cd = cd_command(ctx, dir);
    if (!cd) return CTN_ERR_NOMEM;
    char *argv[] = { (char *)prog, "-e", cd, script, NULL };
    pid_t pid;
    int err = posix_spawnp(&pid, prog, NULL, NULL, argv, environ), rc = CTN_OK;
    if (err == ENOENT || err == EACCES || err == ENOTDIR) rc = CTN_OK;   /* no gnuplot */
    else if (err) rc = ctn_error(ctx, CTN_ERR_IO, "cannot run %s: %s", prog, strerror(err));
    else {
        rc = wait_child(ctx, pid, prog, script);
        *rendered = rc == CTN_OK;
    }
    ctn_free(cd);
    return rc;
}
