/* Internal: the .cable reader's line state and token helpers shared by the directive
 * handlers. */
#ifndef CTN_IO_PARSE_H
#define CTN_IO_PARSE_H

#include "model/model.h"
#include "catena/solve.h"

#define CTN_MAX_TOKENS 64

/* The files being read, innermost first (`include`, include.c). */
typedef struct ctn_incl {
    const char *path;             /* as opened */
    char *real;                   /* its canonical path (realpath), owned */
    int line;                     /* the line of the include that opened the next one in */
    const struct ctn_incl *up;
} ctn_incl;

typedef struct ctn_deck ctn_deck;   /* the lines gathered before they run (deck.h) */

typedef struct ctn_line {
    ctn_model *m;
    ctn_deck *deck;               /* where the scanner puts the lines (reader.c) */
    const ctn_incl *incl;         /* the include chain; NULL in the top file */
    ctn_solve_options *opt;       /* where the `solve` line goes */
    const char *file;
    int line;
    char *tok[CTN_MAX_TOKENS];
    int ntok;
    unsigned long long used;      /* bit k: key/value token k was consumed */
} ctn_line;

/* Error at this line: "file:line: ..." */
int ctn_parse_error(const ctn_line *l, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A token made printable and short for messages (static per-line buffer in *buf). */
const char *ctn_parse_show(const char *tok, char *buf, size_t size);

/* Positional arguments: exactly n (after the directive) before any key=value. */
int ctn_parse_positional(ctn_line *l, int n, const char *usage);
/* 1 if tok is a decimal number whose value is exactly an integer ("20", "+20", "20.0",
 * "2e1", "2000e-2"; not "20.5", "0x14", "inf"), the value in *out (beyond
 * +-(INT_MAX + 1) saturated there); 0 otherwise. The one rule for every integer. */
int ctn_parse_integral(const char *tok, long long *out);
/* An id (or other integer from 1 to INT_MAX) by that rule. */
int ctn_parse_int(const ctn_line *l, const char *what, const char *tok, int *out);
/* A real number; one the value may carry a unit converted to the model's units
 * (`200GPa`), when `what` names a quantity with a dimension (unit_keys.c). */
int ctn_parse_num(const ctn_line *l, const char *what, const char *tok, double *out);
/* The dimension force^f length^l second^t of the value named `what` (t = 2: a mass);
 * 0 if it takes no unit. */
int ctn_parse_unit_dim(const char *what, int *f, int *l, int *t);
/* key=value lookup among tokens from index `from`; NULL if absent (marks it used). */
const char *ctn_parse_key(ctn_line *l, int from, const char *key);
/* A flag token (no '='), e.g. "tension-only"; 1 if present (marks it used). */
int ctn_parse_flag(ctn_line *l, int from, const char *flag);
/* Required / optional numeric key. */
int ctn_parse_key_num(ctn_line *l, int from, const char *key, int required, double *out);
/* After a handler took what it knows: any token left is an unknown key. */
int ctn_parse_leftovers(const ctn_line *l, int from, const char *directive);
/* The error for a required key that is missing: when an unused key of the line (from
 * token `from`) is a misspelling of it (within two edits, or another case), the message
 * names that unknown key and the one meant ("unknown key 'lenght' for directive 'cable'
 * (did you mean 'length='?)"); else "WHAT: missing required key 'KEY='" and `more`
 * (NULL, or a hint such as " (or a target H=, sag= or tension=)"), WHAT the directive's
 * name, or `what` when given ("catenary 1"). */
int ctn_parse_missing(const ctn_line *l, int from, const char *what, const char *key, const char *more);

/* The reader's pieces (reader.c), shared with the form-finding writer, which walks the
 * same lines. Split one line (modified in place) into tokens; comments start with '#'. */
int ctn_read_tokenize(ctn_line *l, char *s);
/* The tokens of the line at text + *pos, in place (scan.c): blanks after a token and a
 * comment's '#' become NULs, *pos moves to the next line; the line ends with a break
 * before len, or at len where text[len] is a NUL. */
int ctn_parse_scan_line(ctn_line *l, char *text, size_t len, size_t *pos);
/* End of the line starting at `start`: the index of its LF, CR or CRLF (len if none);
 * *next gets the start of the next line. */
size_t ctn_read_line_end(const char *text, size_t start, size_t len, size_t *next);
/* A whole file into memory (*data allocated, *len bytes; at most 2 GiB). */
int ctn_read_all(ctn_ctx *ctx, const char *path, char **data, size_t *len);
/* Scan the lines of text[0 .. len) in place into l->deck (scan.c), counting lines on
 * from l->line: an unknown directive is an error at once, `include` reads its file's
 * lines in its place; the deck runs them later (deck.c). The last line ends with a line
 * break, or at len where text[len] must be a NUL; the text must live as long as the deck. */
int ctn_parse_lines(ctn_line *l, char *text, size_t len);
/* The length of the complete lines at the start of text[0 .. len): up to the last line
 * break that is known to end its line (a CR at len - 1 may be half a CRLF); 0 if none. */
size_t ctn_parse_complete(const char *text, size_t len);

/* The directive handlers (directives.c). */
int ctn_parse_directive(ctn_line *l);
/* 1 if word names a directive. */
int ctn_parse_known(const char *word);
/* At most one of l0=, N0=, s0=, eps0= (from token `from`; without l0= when l0 is NULL):
 * the prestress into *kind and *value; *l0 is set when l0= is given. */
int ctn_parse_prestress(ctn_line *l, int from, const char *what, double *l0, ctn_prestress *kind, double *value);
/* The element families with a length: catenary, pulley (directives_span.c). */
/* The end of an element's line: no key left from token `from` on (unless rc already
 * failed), then the element of family `type` with that id and nodes added from spec. */
int ctn_parse_add_element(ctn_line *l, int rc, int from, const char *type, int id, int nnodes, const int *nodes,
                          ctn_element_spec *spec);
int ctn_parse_catenary(ctn_line *l);
int ctn_parse_pulley(ctn_line *l);
int ctn_parse_beam(ctn_line *l);      /* directives_beam.c */
/* A section's shape keys (d= t=, b= h= t=, b= h= tf= tw=) into s's A, Iy, Iz, J;
 * *shaped = 1 if some were given (section_shapes.c). */
int ctn_parse_section_shape(ctn_line *l, ctn_section_spec *s, int *shaped);
/* After the keys of a shaped section line: an Iy= or Iz= given (I differing from the
 * shape's I) keeps the shape's extreme fibre, W = I / (I_shape / W_shape), unless Wy= /
 * Wz= is given too (section_shapes.c). */
void ctn_parse_section_moduli(ctn_line *l, const double I[2], const double W[2], ctn_section_spec *s);
/* Loads and cases (directives_loads.c). */
int ctn_parse_lineload(ctn_line *l);
int ctn_parse_case(ctn_line *l);
int ctn_parse_combination(ctn_line *l);
int ctn_parse_ice(ctn_line *l);
int ctn_parse_wind(ctn_line *l);
/* Dynamics (directives_dynamics.c). */
int ctn_parse_dynamics(ctn_line *l);
int ctn_parse_damping(ctn_line *l);
int ctn_parse_record(ctn_line *l);
int ctn_parse_function(ctn_line *l);
int ctn_parse_remove(ctn_line *l);
/* Selection and generation (directives_sets.c, include.c). */
int ctn_parse_set(ctn_line *l);
int ctn_parse_load_sel(ctn_line *l);     /* load set=NAME ... | load cable=A-B at=T ... */
int ctn_parse_include(ctn_line *l);
int ctn_parse_net(ctn_line *l);          /* directives_net.c */
int ctn_parse_sagtension(ctn_line *l);   /* directives_chart.c */

#endif
