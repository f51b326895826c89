/*
 * state.h - the state file of an interrupted render, for +C.
 *
 * zrcube keeps, beside the image it is writing, a file with the bands of
 * the render done so far (lib/par's zr_par_progress) and a fingerprint
 * of what made them: the bytes of every file the scene read and the
 * options that change pixels.  +C reads it back and the render goes on
 * from there; a state file of another scene or other options is refused
 * with a message, never half-used.
 */
#ifndef ZR_BIN_STATE_H
#define ZR_BIN_STATE_H

#include <stddef.h>
#include <stdint.h>

#include "par/par.h"

/* FNV-1a, 64 bits: h is the running value (start with
   ZR_STATE_HASH_START). */
#define ZR_STATE_HASH_START 14695981039346656037ULL
uint64_t zr__state_hash(uint64_t h, const void *bytes, size_t size);
/* A file's bytes into one value for the fingerprint, 8 bytes a step
   (host byte order, like the state file). */
uint64_t zr__state_digest(const void *bytes, size_t size);

/* "out.png" -> "out.png.zrstate", malloc'ed. */
char *zr__state_path(const char *image_path);

/*
 * Writes the state atomically: a new file beside path, flushed to disk,
 * then renamed over path, so a kill at any moment leaves the old state
 * or the new one, never a torn file.  0, or -1 with errno set.
 */
int zr__state_write(const char *path, uint64_t fingerprint, int width,
                    int height, const zr_par_progress *progress);

/*
 * Reads a state file into *progress (its arrays malloc'ed; free with
 * zr__state_free) with progress->channels floats a pixel (3 unless the
 * caller set 4).  Returns 0; 1 when there is no such file; -1 with a
 * message in err when the file is damaged or was made by another scene,
 * other options or another image size.
 */
int zr__state_read(const char *path, uint64_t fingerprint, int width,
                   int height, zr_par_progress *progress, char *err,
                   size_t err_size);
void zr__state_free(zr_par_progress *progress);

/* Removes the state file and what goes with it (a half-written copy,
   the global illumination saved beside it as path + ".gi" or
   path + ".rad"). */
void zr__state_remove(const char *path);

#endif /* ZR_BIN_STATE_H */
