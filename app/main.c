/* catena: the command's process (the command itself: dispatch.c). */
#include "app.h"

#include <errno.h>
#include <string.h>

/* Whatever the command printed must reach stdout: a write error the command did not
 * report itself (it exits CTN_EXIT_IO when it did) makes the exit code CTN_EXIT_IO. */
int main(int argc, char **argv)
{
    ctn_app_signals_install();
    ctn_process_heap();                      /* the command's own choice (catena/core.h) */
    int code = ctn_app_mpi_init(&argc, &argv);
    if (!code) code = ctn_app_dispatch(argc, argv);
    if (code == CTN_EXIT_IO) {
        fclose(stdout);
        return ctn_app_mpi_finalize(code);
    }
    if (ctn_app_flush(stdout, "stdout")) return ctn_app_mpi_finalize(CTN_EXIT_IO);
    errno = 0;
    if (fclose(stdout)) {
        fprintf(stderr, "catena: stdout: close failed: %s\n", errno ? strerror(errno) : "I/O error");
        code = CTN_EXIT_IO;
    }
    return ctn_app_mpi_finalize(code);
}
