/* SIGINT and SIGTERM: the process (not the library) catches them. The handler only notes
 * the signal; the library, asked through the context's interrupt callback, stops at its
 * next safe point and abandons a result set being written whole. A second signal of the
 * same kind ends the process at once (the handler is reset after the first). */
#define _POSIX_C_SOURCE 200809L
#include "app.h"

#include <signal.h>
#include <string.h>

static volatile sig_atomic_t caught;   /* the first signal caught, 0 if none */

static void note(int sig)
{
    if (!caught) caught = sig;
}

static int poll_caught(void *data)
{
    (void)data;
    return caught != 0;
}

/* A signal the process was started with ignored (nohup, a shell's background job)
 * stays ignored, as the convention for programs that catch it asks. */
static void catch(int sig)
{
    struct sigaction sa, old;
    if (sigaction(sig, NULL, &old) || old.sa_handler == SIG_IGN) return;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = note;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, NULL);
}

void ctn_app_signals_install(void)
{
    catch(SIGINT);
    catch(SIGTERM);
}

int ctn_app_ctx_create_local(ctn_ctx **ctx)
{
    int rc = ctn_ctx_create(ctx);
    if (!rc) ctn_ctx_set_interrupt(*ctx, poll_caught, NULL);
    return rc ? rc : ctn_ctx_set_threads(*ctx, 0);
}

int ctn_app_ctx_create(ctn_ctx **ctx)
{
    int rc = ctn_ctx_create(ctx);
    if (!rc) ctn_ctx_set_interrupt(*ctx, poll_caught, NULL);
    if (!rc) rc = ctn_app_mpi_attach(*ctx);
    return rc ? rc : ctn_ctx_set_threads(*ctx, ctn_app_blas_capped() ? 1 : 0);
}

int ctn_app_interrupt_code(void)
{
    return 128 + (caught ? (int)caught : SIGINT);
}
