/* Internal: streaming JSON in the exact layout of cJSON 1.7.15 (the bytes
 * cJSON_Print / cJSON_PrintUnformatted give for the same document):
 *   pretty:  {\n, then per member depth tabs, "key":\tvalue, ",\n" between members,
 *            \n and depth-1 tabs before }; arrays [a, b] on one line, ", " between
 *            items, objects in them as {...}, {...}; an empty object {\n<tabs>}
 *   compact: no whitespace at all.
 * Numbers as cJSON prints them (io/fmt.h), strings escaped as cJSON does. A member has
 * a key; an array item (or the root) has key NULL. */
#ifndef CTN_IO_JSONW_H
#define CTN_IO_JSONW_H

#include "io/sink.h"

#define CTN_JW_DEPTH 32

typedef struct ctn_jw {
    ctn_wbuf *out;
    int pretty;
    int depth;                          /* open containers, cJSON's depth */
    unsigned char state[CTN_JW_DEPTH];  /* per container: 1 array, 2 has an item */
} ctn_jw;

void ctn_jw_init(ctn_jw *j, ctn_wbuf *out, int pretty);
void ctn_jw_object(ctn_jw *j, const char *key);
void ctn_jw_array(ctn_jw *j, const char *key);
void ctn_jw_end(ctn_jw *j);   /* closes the innermost object or array */
void ctn_jw_number(ctn_jw *j, const char *key, double v);
void ctn_jw_string(ctn_jw *j, const char *key, const char *s);
void ctn_jw_bool(ctn_jw *j, const char *key, int b);

#endif
