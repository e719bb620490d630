/* Test helpers for files and directories: a whole file read, a directory's entries
 * counted, a flat directory removed, the .cable files of example directories visited.
 * Include after check.h. */
#ifndef CTN_TEST_FILES_H
#define CTN_TEST_FILES_H

#include "check.h"

#include <dirent.h>
#include <stdlib.h>
#include <unistd.h>

/* The whole file, NUL-terminated (its length in *len unless len is NULL); NULL if it
 * cannot be read. */
static inline char *read_all_len(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (len) *len = 0;
    if (!f) return NULL;
    size_t cap = 4096, n = 0, k;
    char *s = malloc(cap);
    while (s && (k = fread(s + n, 1, cap - n - 1, f)) > 0) {
        n += k;
        if (cap - n < 2) {
            char *t = realloc(s, cap *= 2);
            if (!t) { free(s); s = NULL; }
            else s = t;
        }
    }
    fclose(f);
    if (s) s[n] = '\0';
    if (s && len) *len = n;
    return s;
}

static inline char *read_all(const char *path) { return read_all_len(path, NULL); }

/* Entries of dir other than . and ..; -1 if it cannot be read. */
static inline int count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

static inline void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return;
    for (struct dirent *e; (e = readdir(d));) {
        char path[4096];
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
    }
    closedir(d);
    rmdir(dir);
}

/* Call visit(path, data) for every .cable file of the directories (relative to the
 * project root, where the tests run); the number of files visited. */
static inline int each_example(const char *const *dirs, size_t ndirs, void (*visit)(const char *path, void *data),
                        void *data)
{
    int files = 0;
    for (size_t i = 0; i < ndirs; i++) {
        DIR *dir = opendir(dirs[i]);
        CHECK_MSG(dir != NULL, "cannot open %s (run from the project root)", dirs[i]);
        for (struct dirent *de; dir && (de = readdir(dir));) {
            size_t len = strlen(de->d_name);
            if (len < 7 || strcmp(de->d_name + len - 6, ".cable")) continue;
            char path[1024];
            snprintf(path, sizeof path, "%s/%s", dirs[i], de->d_name);
            visit(path, data);
            files++;
        }
        if (dir) closedir(dir);
    }
    return files;
}

#endif
