/* Internal: columns of a matrix handed from the thread that assembles them to the thread
 * that factorizes them, in the pattern's order (solve/overlap.c). The producer publishes
 * how many leading columns are complete; the consumer waits until the columns it needs
 * are, or until the owner stops it (the factorization is no longer wanted). */
#ifndef CTN_CORE_FEED_H
#define CTN_CORE_FEED_H

#include <pthread.h>
#include <stddef.h>

typedef struct ctn_feed {
    pthread_mutex_t lock;
    pthread_cond_t more;
    size_t ready;              /* columns 0 .. ready - 1 are complete */
    size_t n;                  /* all of them */
    int stop;                  /* the consumer is to give up */
} ctn_feed;

/* 0, or an error number of pthread's (then nothing to destroy). */
int ctn_feed_init(ctn_feed *f, size_t n);
void ctn_feed_destroy(ctn_feed *f);
/* Columns 0 .. ready - 1 are complete (ready only grows; n when the producer ends,
 * whether it succeeded or not). */
void ctn_feed_publish(ctn_feed *f, size_t ready);
/* Tell the consumer to give up. */
void ctn_feed_stop(ctn_feed *f);
/* Wait until at least `need` columns are complete: 1, or 0 if told to give up. */
int ctn_feed_wait(ctn_feed *f, size_t need);

#endif
