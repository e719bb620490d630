/* The .cable scanner: lines into tokens in place, in one pass over the bytes, each
 * line into the deck (deck.c), which runs them once the model is read. Lines end in LF, CRLF or a lone CR; '#' starts a comment. */
#include "io/deck.h"

#include <stdio.h>
#include <string.h>

/* Classes of the bytes. */
enum { TOK, BLANK, BREAK, HASH, NUL };
static const unsigned char byte_class[256] = {
    [0] = NUL, ['\t'] = BLANK, ['\v'] = BLANK, ['\f'] = BLANK, [' '] = BLANK,
    ['\n'] = BREAK, ['\r'] = BREAK, ['#'] = HASH,
};

static int cls(const char *p) { return byte_class[(unsigned char)*p]; }

/* The tokens of the line that starts at text + *pos: blanks after a token and the '#'
 * of a comment become NULs; *pos moves to the start of the next line. The line must end
 * with a line break before len, or at len where text[len] is a NUL. A NUL byte on the
 * line is binary data; more than CTN_MAX_TOKENS fields is an error. */
int ctn_parse_scan_line(ctn_line *l, char *text, size_t len, size_t *pos)
{
    size_t i = *pos;
    int many = 0, c;
    l->ntok = 0;
    l->used = 0;
    for (;;) {
        c = cls(text + i);
        if (c == BLANK) {
            i++;
        } else if (c == TOK) {
            if (l->ntok == CTN_MAX_TOKENS) many = 1;
            else l->tok[l->ntok++] = text + i;
            while (cls(text + ++i) == TOK) {}
            if (cls(text + i) == BLANK) text[i++] = '\0';
        } else {
            break;
        }
    }
    if (c == HASH) {                                /* a comment, to the end of the line */
        text[i++] = '\0';
        while ((c = cls(text + i)) != BREAK && c != NUL) i++;
    }
    if (c == NUL && i < len) return ctn_parse_error(l, "binary data (a NUL byte) in the model file");
    *pos = i + (i + 1 < len && text[i] == '\r' && text[i + 1] == '\n' ? 2 : 1);
    text[i] = '\0';
    if (many) return ctn_parse_error(l, "too many fields on one line (more than %d)", CTN_MAX_TOKENS);
    return CTN_OK;
}

/* A line with tokens: `include` reads its file now (its lines join the deck here), an
 * unknown directive is an error at once (in the file's order), any other line joins the
 * deck. */
static int gather(ctn_line *l)
{
    char b[64];
    if (!strcmp(l->tok[0], "include")) {
        l->m->line = l->line;
        return ctn_parse_include(l);
    }
    if (!ctn_parse_known(l->tok[0]))
        return ctn_parse_error(l, "unknown directive '%s'", ctn_parse_show(l->tok[0], b, sizeof b));
    return ctn_deck_add(l);
}

int ctn_parse_lines(ctn_line *l, char *text, size_t len)
{
    for (size_t pos = 0; pos < len; l->line++) {
        int rc = ctn_parse_scan_line(l, text, len, &pos);
        if (!rc && l->ntok) rc = gather(l);
        if (rc == CTN_ERR_NOMEM) {
            char msg[CTN_MSG_MAX];
            snprintf(msg, sizeof msg, "%s", ctn_ctx_message(l->m->ctx));
            ctn_error_at(l->m->ctx, rc, l->file, l->line, "%s", msg);
        }
        if (rc) return rc;
    }
    l->m->line = 0;
    return CTN_OK;
}

size_t ctn_parse_complete(const char *text, size_t len)
{
    size_t j = len;
    if (j && text[j - 1] == '\r') j--;              /* may be the CR of a CRLF */
    while (j && text[j - 1] != '\n' && text[j - 1] != '\r') j--;
    return j;
}
