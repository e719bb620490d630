/* The hand-over of assembled columns (feed.h): a counter under a mutex, a condition
 * signalled at each publication (a few hundred per assembly) and at a stop. */
#include "core/feed.h"

int ctn_feed_init(ctn_feed *f, size_t n)
{
    f->ready = 0;
    f->n = n;
    f->stop = 0;
    int rc = pthread_mutex_init(&f->lock, NULL);
    if (rc) return rc;
    if ((rc = pthread_cond_init(&f->more, NULL))) pthread_mutex_destroy(&f->lock);
    return rc;
}

void ctn_feed_destroy(ctn_feed *f)
{
    pthread_cond_destroy(&f->more);
    pthread_mutex_destroy(&f->lock);
}

void ctn_feed_publish(ctn_feed *f, size_t ready)
{
    pthread_mutex_lock(&f->lock);
    if (ready > f->ready) f->ready = ready < f->n ? ready : f->n;
    pthread_cond_signal(&f->more);
    pthread_mutex_unlock(&f->lock);
}

void ctn_feed_stop(ctn_feed *f)
{
    pthread_mutex_lock(&f->lock);
    f->stop = 1;
    pthread_cond_signal(&f->more);
    pthread_mutex_unlock(&f->lock);
}

int ctn_feed_wait(ctn_feed *f, size_t need)
{
    pthread_mutex_lock(&f->lock);
    while (!f->stop && f->ready < need && f->ready < f->n) pthread_cond_wait(&f->more, &f->lock);
    int go = !f->stop;
    pthread_mutex_unlock(&f->lock);
    return go;
}
