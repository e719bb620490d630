/* The table of catena's commands: name, entry point, synopsis and help text, and the
 * `catena help` / `catena COMMAND --help` printers built from it. */
#include "app.h"

#include <string.h>

#define EXIT_CODES_NOTE "exit codes: 0 converged, 1 usage, 2 bad model, 3 not converged, 4 I/O or other error\n"

static const ctn_app_command commands[] = {
    { "solve", ctn_cmd_solve, "MODEL [--json] [-o DIR] [-q] [--reactions N|all]", "MODEL [--json] [-o DIR] [-q]",
      "solve a .cable model (docs/format.md)",
      "Solve a .cable model (docs/format.md) with the options of its `solve` directive and\n"
      "print the Newton iteration log and a summary of the result.\n"
      "\n"
      "options (in any order):\n"
      "  MODEL          the model file\n"
      "  --json         print the result as JSON on stdout instead of the log and summary\n"
      "  -o DIR         write result.json, nodes.csv, elements.csv and result.vtu (ParaView) into\n"
      "                 DIR (created if missing); several steps: also result_K.vtu and result.pvd;\n"
      "                 modes.csv when the model has a `modes` line, buckling.csv a `buckling` line\n"
      "  -q, --quiet    print nothing on stdout (--json still prints the JSON)\n"
      "  --reactions N|all  list at most N reactions in the summary (default 20), or all\n"
      "  -h, --help     print this help and exit\n"
      "\n"
      "A `modes count=N [mass=consistent|lumped] [shift=HZ] [solver=auto|block|arpack]` line in\n"
      "the model adds the N natural modes about the solved state: a table in the summary,\n"
      "\"modal\" and \"modes\" in the JSON (frequencies, periods, shapes, participation),\n"
      "modes.csv with -o. solver= picks the shift-invert eigen-solver: block Lanczos,\n"
      "ARPACK's Lanczos, or auto (the default: ARPACK below 100000 free DOFs, block above).\n"
      "A `buckling count=N` line adds the N lowest linear buckling load factors on the last\n"
      "step's loads about the solved state (at most 2000 free DOFs): a table in the summary,\n"
      "\"buckling\" in the JSON, buckling.csv with -o, buckling_K shapes in result.vtu.\n"
      "On a terminal, reading, solving and writing that take over 2 s show their progress on stderr.\n"
      "\n"
      "exit codes: 0 converged, 1 usage, 2 bad model (the message names file:line),\n"
      "            3 not converged (the last converged state is still written) or the\n"
      "            eigen-solver did not converge, 4 I/O or other error,\n"
      "            130/143 interrupted by SIGINT/SIGTERM (no output replaced)\n" },
    { "batch", ctn_cmd_batch, "LIST -o DIR [-q]", "LIST -o DIR", "solve many models over the ranks of an MPI job",
      "Solve the models listed in LIST (one path a line; blank lines and # comments skipped),\n"
      "each serially with its own solve options (CHOLMOD), and write each one's result set\n"
      "(result.json, nodes.csv, elements.csv, result.vtu) into DIR/NNNNN_NAME/ (NNNNN its\n"
      "place in the list). Under mpirun (docs/parallel.md) rank r of N solves the models\n"
      "r, r + N, r + 2N, ...: a parametric study over the ranks of a job.\n"
      "\n"
      "options (in any order):\n"
      "  LIST           the file of model paths\n"
      "  -o DIR         the results' directory (created if missing)\n"
      "  -q, --quiet    print nothing on stdout\n"
      "  -h, --help     print this help and exit\n"
      "\n"
      "exit codes: 0 every model converged, 1 usage, 2 a bad model, 3 a model did not\n"
      "            converge, 4 I/O or other error (the largest over the models and ranks)\n" },
    { "compare", ctn_cmd_compare, "MODEL [--json] [-o DIR] [-q]", "MODEL [--json] [-o DIR] [-q]", "FEA of a single span against the closed forms",
      "Solve a single-span model (a `cable` directive or a chain of elements between two\n"
      "fully fixed nodes) with its own solver options and compare the FEA with the closed\n"
      "forms that apply: catenaries and parabolas, funicular polygons (docs/validation.md).\n"
      "\n"
      "options (in any order):\n"
      "  MODEL          the model file: one span\n"
      "  --json         print the compared values as JSON on stdout instead of the table\n"
      "  -o DIR         write the figures compare_shape, compare_stress into DIR (gnuplot scripts,\n"
      "                 data, and SVG when gnuplot is installed)\n"
      "  -q, --quiet    print nothing on stdout (--json still prints the JSON)\n"
      "  -h, --help     print this help and exit\n"
      "\n"
      "exit codes: 0 compared, 1 usage, 2 bad model or not a single span, 3 the FEA did not\n"
      "            converge, 4 I/O or other error\n" },
    { "study", ctn_cmd_study,
      "MODEL... [--lengths LIST] [--sweep N] [--from L] [--to L] [--levels LIST]\n"
      "                    [--claims S:E,...] [--claims-title TEXT] [--element mesh|catenary]\n"
      "                    [--json] [-o DIR] [-q]",
      "MODEL... [options]", "FEA against the catenary over cable lengths",
      "The founding paper's study: the span of the first MODEL re-solved over a sweep of\n"
      "unstressed lengths L0, FEA against the inextensible catenary; the lengths of every\n"
      "MODEL and of --lengths are marked (docs/validation.md). LIST: numbers separated by ','.\n"
      "\n"
      "options (in any order):\n"
      "  MODEL...             models of one span (only the cable length may differ)\n"
      "  --lengths LIST       more marked unstressed lengths [model length unit]\n"
      "  --sweep N            number of sweep lengths, geometric in L0 - chord (default 64; 0: none)\n"
      "  --from L             smallest sweep length, above the chord (default 1.0002 chord)\n"
      "  --to L               largest sweep length (default 1.5 chord)\n"
      "  --levels LIST        stress levels of the error table in MPa (default 50,100,...,300)\n"
      "  --claims S:E,...     reference points, stress level S [MPa] : error E [%], on the table and figure\n"
      "  --claims-title TEXT  legend of the reference points (default \"reference points\")\n"
      "  --element KIND       what each length is solved on: mesh (default: the span's n cable\n"
      "                       elements, or its one catenary element) or catenary (one exact\n"
      "                       catenary element per length, the row's FEA; the mesh is solved\n"
      "                       beside it and shown in a second table and the figures)\n"
      "  --json               print the study as JSON on stdout instead of the tables\n"
      "  -o DIR               write the figures study_stress_max, study_stress_min, study_sag and\n"
      "                       study_error into DIR (gnuplot scripts, data, SVG when gnuplot is installed),\n"
      "                       with --element catenary also study_element (the mesh against the element)\n"
      "  -q, --quiet          print nothing on stdout (--json still prints the JSON)\n"
      "  -h, --help           print this help and exit\n"
      "\n"
      "exit codes: 0 done (lengths that do not converge are rows, not failures), 1 usage (also a\n"
      "            bad length or sweep), 2 bad model or not the same span, 4 I/O or other error\n" },
    { "convergence", ctn_cmd_convergence, "MODEL [--n LIST] [--json] [-o DIR] [-q]",
      "MODEL [--n LIST] [...]", "mesh convergence to the elastic catenary",
      "The span of MODEL (loaded by its self-weight only) meshed with n elements, engineering\n"
      "strain, solved for each n and compared with the elastic catenary: errors of the sag,\n"
      "the support tension and H, and their observed orders (docs/validation.md).\n"
      "\n"
      "options (in any order):\n"
      "  MODEL          the model file: one span\n"
      "  --n LIST       element counts, integers 2 to 50000000 separated by ','\n"
      "                 (default 10,20,50,100,200,500,1000,2000,5000,10000)\n"
      "  --json         print the table as JSON on stdout instead\n"
      "  -o DIR         write the figure convergence into DIR (gnuplot script, data, SVG when\n"
      "                 gnuplot is installed)\n"
      "  -q, --quiet    print nothing on stdout (--json still prints the JSON)\n"
      "  -h, --help     print this help and exit\n"
      "\n"
      "exit codes: 0 every n converged, 1 usage, 2 bad model or not a span under self-weight,\n"
      "            3 some n did not converge, 4 I/O or other error\n" },
    { "formfind", ctn_cmd_formfind, "MODEL [-o OUT] [--tol T] [--maxit N] [-q]", "MODEL [-o OUT] [...]",
      "form finding by force density (Schek)",
      "Find the shape of a cable net from the force density q= (force/length) or the target\n"
      "force force= of every member (docs/format.md): nodes with fix= are anchors, the free\n"
      "ones go where the members and the loads of the first step balance (self-weight and\n"
      "hload computed from the shape found). The linear equilibrium of the free nodes is\n"
      "solved by sparse Cholesky; targeted members iterate q <- force / l until every force\n"
      "matches its target and the loads have settled (docs/theory.md). OUT is a complete\n"
      "model: the source with the found coordinates, each member's l0= (the unstressed\n"
      "length that carries q l there) in place of q=/force=, cables expanded into nodes and\n"
      "elements, every other line copied. `catena solve OUT` stays where it is.\n"
      "\n"
      "options (in any order):\n"
      "  MODEL          the model file\n"
      "  -o OUT         write the found model to OUT (atomically; only when it converged)\n"
      "  --tol T        stop when the largest relative force mismatch and load change are\n"
      "                 both <= T (default 1e-10)\n"
      "  --maxit N      most iterations, 1 to 1000000 (default 1000)\n"
      "  -q, --quiet    print nothing on stdout\n"
      "  -h, --help     print this help and exit\n"
      "\n"
      "exit codes: 0 found (and written), 1 usage, 2 bad model (the message names file:line: a\n"
      "            member without q= or force=, a free node no member joins to an anchor,\n"
      "            targets no shape can balance, ...), 3 not converged (nothing written),\n"
      "            4 I/O or other error\n" },
};

const ctn_app_command *ctn_app_command_find(const char *name)
{
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        if (!strcmp(commands[i].name, name)) return &commands[i];
    return NULL;
}

/* One line of the command list: "  NAME ARGS" padded, then the summary. */
static void list_line(FILE *f, const char *name, const char *args, const char *summary)
{
    int n = fprintf(f, "  %s%s%s", name, *args ? " " : "", args);
    fprintf(f, "%*s %s\n", n < 40 ? 40 - n : 0, "", summary);
}

void ctn_app_usage(FILE *f)
{
    fprintf(f, "usage: catena COMMAND [options]\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        list_line(f, commands[i].name, commands[i].args, commands[i].summary);
    list_line(f, "help", "[COMMAND]", "this text, or the help of COMMAND");
    list_line(f, "version", "", "print the version (also: catena --version)");
    fprintf(f, "\n'catena COMMAND --help' (or -h) prints the options and exit codes of COMMAND;\n"
               "'catena --version' prints the version.\n"
               "\n" EXIT_CODES_NOTE);
}

void ctn_app_command_help(FILE *f, const ctn_app_command *c)
{
    fprintf(f, "usage: catena %s %s\n\n%s", c->name, c->synopsis, c->help);
}

int ctn_app_wants_help(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return 1;
    return 0;
}
