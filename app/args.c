/* The options shared by `solve` and `compare`: MODEL [--json] [-o DIR] [-q]. */
#include "app.h"

#include <string.h>

int ctn_app_model_args(const char *cmd, int argc, char **argv, ctn_model_args *a)
{
    memset(a, 0, sizeof *a);
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--json")) a->json = 1;
        else if (!strcmp(argv[i], "-q") || !strcmp(argv[i], "--quiet")) a->quiet = 1;
        else if (!strcmp(argv[i], "-o") && i + 1 < argc) a->outdir = argv[++i];
        else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "catena %s: unknown or incomplete option '%s'\n", cmd, argv[i]);
            return 1;
        } else if (!a->model) a->model = argv[i];
        else {
            fprintf(stderr, "catena %s: more than one model given ('%s')\n", cmd, argv[i]);
            return 1;
        }
    }
    if (!a->model) fprintf(stderr, "usage: catena %s MODEL [--json] [-o DIR] [-q]\n", cmd);
    return a->model ? 0 : 1;
}

