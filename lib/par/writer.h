/*
 * writer.h - rank 0 writes the image while the last rows are rendered.
 *
 * Under mpirun rank 0 alone encodes the picture, after every rank has
 * rendered it: at 2048x2048 a PNG takes 0.19 s of rank 0 after a
 * 1.8 s render of each of two ranks, 9% of the run that the other rank
 * spends waiting or gone.  Here the encoder runs on a thread of its
 * own, started before the render, and reads each row as soon as it is
 * final (zr_image_set_rows_wait); zr__par_render lets the other ranks
 * render the last bands without rank 0 (job->writer), so that the
 * encoder has rank 0's processor while they do, and rank 0 takes rows
 * of those bands beside them as soon as the encoder has nothing to do
 * (zr__par_writer_wait_idle).  The bytes written are
 * those of the same write after the render: the encoder is the same
 * code reading the same rows, only sooner.  One process of several
 * threads uses it too: its pool tells the rows as they are finished.
 */
#ifndef ZR_PAR_WRITER_H
#define ZR_PAR_WRITER_H

#include "zrcube.h"

typedef struct zr_par_writer zr_par_writer;

/* The write: encodes image (to a file) and returns its status. */
typedef zr_status (*zr_par_write_fn)(zr_image *image, void *user);

/*
 * Starts write(image, user) on a new thread, the image's rows gated: the
 * encoder waits until zr__par_writer_rows has said they are final.
 * ZR_ETHREAD when no thread starts (the caller then writes after the
 * render, as before).
 */
zr_status zr__par_writer_start(zr_image *image, zr_par_write_fn write,
                               void *user, zr_par_writer **out);

/* Rows 0 .. rows - 1 of the image are final (rows never decreases). */
void zr__par_writer_rows(zr_par_writer *w, int rows);

/* The rows said final so far. */
int zr__par_writer_rows_done(const zr_par_writer *w);

/*
 * 1 as soon as the encoder has nothing to do - it waits for rows not yet
 * said final, or the write has returned - and 0 when seconds pass
 * first (rank 0 then looks again at what the other ranks left it).
 */
int zr__par_writer_wait_idle(zr_par_writer *w, double seconds);

/*
 * Ends the write: with abandon, the encoder's wait fails (the render
 * failed: the write returns ZR_ECANCELLED and leaves no file); waits for
 * the thread, frees w, ungates the image and returns the write's status.
 */
zr_status zr__par_writer_finish(zr_par_writer *w, int abandon);

#endif /* ZR_PAR_WRITER_H */
