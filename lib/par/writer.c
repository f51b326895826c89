/*
 * writer.c - the image write on a thread of its own (writer.h).
 */
#include "par/writer.h"

#include <pthread.h>
#include <time.h>
#include <stdlib.h>

struct zr_par_writer {
  pthread_mutex_t lock;
  pthread_cond_t more; /* rows or abandon changed */
  pthread_cond_t idle_changed; /* idle became 1 */
  int rows;            /* final rows, guarded by lock */
  int abandon;         /* guarded by lock */
  /* The rows the encoder waits for (0 when it does not wait) and 1
     once the write has returned: it has nothing to do while
     waiting_for > rows or done (writer_idle; guarded by lock). */
  int waiting_for;
  int done;
  zr_image *image;
  zr_par_write_fn write;
  void *user;
  zr_status status; /* the write's, read after the join */
  pthread_t thread;
};

/* The image's rows wait (zr_image_rows_fn), on the writer's thread. */
static int wait_rows(int rows, void *user) {
  zr_par_writer *w = user;
  pthread_mutex_lock(&w->lock);
  while (w->rows < rows && !w->abandon) {
    w->waiting_for = rows;
    pthread_cond_broadcast(&w->idle_changed);
    pthread_cond_wait(&w->more, &w->lock);
  }
  w->waiting_for = 0;
  int failed = w->rows < rows;
  pthread_mutex_unlock(&w->lock);
  return failed;
}

/* Nothing to do: the encoder waits for rows not yet said final (rows
   said final since it began to wait give it work at once, before its
   thread wakes), or the write has returned.  Under w->lock. */
static int writer_idle(const zr_par_writer *w) {
  return w->done || w->waiting_for > w->rows;
}

static void *writer_main(void *arg) {
  zr_par_writer *w = arg;
  w->status = w->write(w->image, w->user);
  pthread_mutex_lock(&w->lock);
  w->done = 1;
  pthread_cond_broadcast(&w->idle_changed);
  pthread_mutex_unlock(&w->lock);
  return NULL;
}

zr_status zr__par_writer_start(zr_image *image, zr_par_write_fn write,
                               void *user, zr_par_writer **out) {
  *out = NULL;
  zr_par_writer *w = calloc(1, sizeof *w);
  if (!w)
    return ZR_ENOMEM;
  if (pthread_mutex_init(&w->lock, NULL) != 0) {
    free(w);
    return ZR_ETHREAD;
  }
  if (pthread_cond_init(&w->more, NULL) != 0) {
    pthread_mutex_destroy(&w->lock);
    free(w);
    return ZR_ETHREAD;
  }
  if (pthread_cond_init(&w->idle_changed, NULL) != 0) {
    pthread_cond_destroy(&w->more);
    pthread_mutex_destroy(&w->lock);
    free(w);
    return ZR_ETHREAD;
  }
  w->image = image;
  w->write = write;
  w->user = user;
  zr_image_set_rows_wait(image, wait_rows, w);
  if (pthread_create(&w->thread, NULL, writer_main, w) != 0) {
    zr_image_set_rows_wait(image, NULL, NULL);
    pthread_cond_destroy(&w->idle_changed);
    pthread_cond_destroy(&w->more);
    pthread_mutex_destroy(&w->lock);
    free(w);
    return ZR_ETHREAD;
  }
  *out = w;
  return ZR_OK;
}

void zr__par_writer_rows(zr_par_writer *w, int rows) {
  pthread_mutex_lock(&w->lock);
  if (rows > w->rows) {
    w->rows = rows;
    pthread_cond_broadcast(&w->more);
  }
  pthread_mutex_unlock(&w->lock);
}

int zr__par_writer_rows_done(const zr_par_writer *w) {
  zr_par_writer *m = (zr_par_writer *)w;
  pthread_mutex_lock(&m->lock);
  int rows = m->rows;
  pthread_mutex_unlock(&m->lock);
  return rows;
}

zr_status zr__par_writer_finish(zr_par_writer *w, int abandon) {
  pthread_mutex_lock(&w->lock);
  if (abandon)
    w->abandon = 1;
  else if (w->rows < zr_image_height(w->image))
    w->rows = zr_image_height(w->image);
  pthread_cond_broadcast(&w->more);
  pthread_mutex_unlock(&w->lock);
  pthread_join(w->thread, NULL);
  zr_status s = w->status;
  zr_image_set_rows_wait(w->image, NULL, NULL);
  pthread_cond_destroy(&w->idle_changed);
  pthread_cond_destroy(&w->more);
  pthread_mutex_destroy(&w->lock);
  free(w);
  return s;
}

int zr__par_writer_wait_idle(zr_par_writer *w, double seconds) {
  struct timespec until;
  clock_gettime(CLOCK_REALTIME, &until);
  long ns = until.tv_nsec + (long)(seconds * 1e9);
  until.tv_sec += ns / 1000000000L;
  until.tv_nsec = ns % 1000000000L;
  pthread_mutex_lock(&w->lock);
  int r = 0;
  while (!writer_idle(w) && r == 0)
    r = pthread_cond_timedwait(&w->idle_changed, &w->lock, &until);
  int idle = writer_idle(w);
  pthread_mutex_unlock(&w->lock);
  return idle;
}
