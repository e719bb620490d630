/* Internal: the deck, a model's lines gathered whole and run definitions first (deck.c).
 * The scanner adds each line with tokens (ctn_parse_lines), `include` reads its file's
 * lines in place; the reader runs the deck once the input is read. */
#ifndef CTN_IO_DECK_H
#define CTN_IO_DECK_H

#include "io/parse.h"

typedef struct ctn_deck_line {
    char *text;             /* its first token; the tokens are NUL-terminated in place */
    size_t len;             /* bytes from text to the end of the last token */
    const char *file;       /* the file it is in (owned by the deck, or the reader's name) */
    int line;
    unsigned char phase;    /* deck.c */
    unsigned char hoist;    /* runs at the start of its phase */
    unsigned char kind;     /* its directive's entry in deck.c's table, 255 if none */
} ctn_deck_line;

struct ctn_deck {
    CTN_ARRAY(ctn_deck_line) lines;
    CTN_ARRAY(char *) bufs;     /* the texts the lines point into, owned */
    CTN_ARRAY(char *) files;    /* the included files' paths, owned */
};

void ctn_deck_free(ctn_deck *d);
/* Keep buf (allocated by ctn_malloc) until the deck is freed; freed at once on failure. */
int ctn_deck_keep(ctn_ctx *ctx, ctn_deck *d, char *buf);
/* A copy of path the deck owns, in *out. */
int ctn_deck_file(ctn_ctx *ctx, ctn_deck *d, const char *path, const char **out);
/* Add l's line (tokens, file, line number) to l->deck. */
int ctn_deck_add(ctn_line *l);
/* Run the deck's lines by phase with l as the reader. */
int ctn_deck_run(ctn_deck *d, ctn_line *l);

#endif
