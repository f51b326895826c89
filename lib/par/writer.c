/*
 * writer.c - the image write on a thread of its own (writer.h).
 */
#include "par/writer.h"

#include <pthread.h>
#include <stdlib.h>

struct zr_par_writer {
  pthread_mutex_t lock;
  pthread_cond_t more; /* rows or abandon changed */
  int rows;            /* final rows, guarded by lock */
  int abandon;         /* guarded by lock */
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
  while (w->rows < rows && !w->abandon)
    pthread_cond_wait(&w->more, &w->lock);
  int failed = w->rows < rows;
  pthread_mutex_unlock(&w->lock);
  return failed;
}

static void *writer_main(void *arg) {
  zr_par_writer *w = arg;
  w->status = w->write(w->image, w->user);
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
  w->image = image;
  w->write = write;
  w->user = user;
  zr_image_set_rows_wait(image, wait_rows, w);
  if (pthread_create(&w->thread, NULL, writer_main, w) != 0) {
    zr_image_set_rows_wait(image, NULL, NULL);
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
  pthread_cond_destroy(&w->more);
  pthread_mutex_destroy(&w->lock);
  free(w);
  return s;
}
