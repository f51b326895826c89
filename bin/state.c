/*
 * state.c - the state file of an interrupted render (+C, "Continue
 * Trace" in POV-Ray's reference 3.2.2.5).
 *
 * POV-Ray continues from the partial image file itself; zrcube writes
 * its image once, at the end (atomically, lib/core/iopolicy.c), so it
 * keeps a separate file beside it instead, of its own design:
 *
 *   "ZRSTATE1"                      8 bytes
 *   fingerprint                     u64
 *   width height passes bands band_rows   5 x i32
 *   done flags                      passes x bands bytes
 *   centres (with 2 passes)         width x height x 3 f32
 *   image                           width x height x 3 f32
 *
 * (4 f32 a pixel, colour and alpha, with +UA, which the fingerprint
 * holds)
 *   checksum                        u64, FNV-1a of all the above
 *
 * in the host's byte order (a state file continues a render on the
 * machine that began it).  Pixels are stored as the floats the render
 * made, so a continued render writes the same bytes as one never
 * interrupted.
 */
#include "state.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char magic[8] = {'Z', 'R', 'S', 'T', 'A', 'T', 'E', '1'};

uint64_t zr__state_hash(uint64_t h, const void *bytes, size_t size) {
  const unsigned char *p = bytes;
  for (size_t i = 0; i < size; i++) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

/* FNV-1a's step on 8 bytes at a time, with the high half folded down
   after each (a multiply carries bits upwards only): 8 times fewer
   dependent multiplies than zr__state_hash, which took 5-8% of the
   whole run of a 15 MB mesh scene.  Not a checksum of the file format
   (the state file keeps FNV-1a): it only tells one scene from another. */
uint64_t zr__state_digest(const void *bytes, size_t size) {
  const unsigned char *p = bytes;
  uint64_t h = ZR_STATE_HASH_START ^ (uint64_t)size;
  for (; size >= 8; p += 8, size -= 8) {
    uint64_t w;
    memcpy(&w, p, sizeof w);
    h ^= w;
    h *= 1099511628211ULL;
    h ^= h >> 32;
  }
  return zr__state_hash(h, p, size);
}

char *zr__state_path(const char *image_path) {
  size_t n = strlen(image_path) + sizeof ".zrstate";
  char *path = malloc(n);
  if (path)
    snprintf(path, n, "%s.zrstate", image_path);
  return path;
}

/* Writes size bytes and folds them into the checksum. */
static int put(int fd, const void *bytes, size_t size, uint64_t *sum) {
  *sum = zr__state_hash(*sum, bytes, size);
  const char *p = bytes;
  while (size > 0) {
    ssize_t n = write(fd, p, size);
    if (n < 0) {
      if (errno == EINTR)
        continue;
      return -1;
    }
    p += n;
    size -= (size_t)n;
  }
  return 0;
}

int zr__state_write(const char *path, uint64_t fingerprint, int width,
                    int height, const zr_par_progress *pr) {
  size_t n = strlen(path) + 32;
  char *tmp = malloc(n);
  if (!tmp)
    return -1;
  /* One name, so a write killed half-way leaves no litter beyond the
     next write's (and zr__state_remove takes it). */
  snprintf(tmp, n, "%s.tmp", path);
  int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW, 0644);
  if (fd < 0) {
    free(tmp);
    return -1;
  }
  uint64_t sum = ZR_STATE_HASH_START;
  int32_t head[5] = {width, height, pr->passes, pr->bands, pr->band_rows};
  size_t floats = (size_t)width * (size_t)height *
                  (size_t)(pr->channels == 4 ? 4 : 3);
  int rc = put(fd, magic, sizeof magic, &sum);
  if (rc == 0)
    rc = put(fd, &fingerprint, sizeof fingerprint, &sum);
  if (rc == 0)
    rc = put(fd, head, sizeof head, &sum);
  for (int p = 0; p < pr->passes && rc == 0; p++)
    rc = put(fd, pr->done[p], (size_t)pr->bands, &sum);
  if (rc == 0 && pr->passes == 2)
    rc = put(fd, pr->centres, floats * sizeof(float), &sum);
  if (rc == 0)
    rc = put(fd, pr->image, floats * sizeof(float), &sum);
  uint64_t total = sum;
  if (rc == 0)
    rc = put(fd, &total, sizeof total, &sum);
  if (rc == 0)
    rc = fsync(fd);
  int err = errno;
  if (close(fd) != 0 && rc == 0) {
    rc = -1;
    err = errno;
  }
  if (rc == 0 && rename(tmp, path) != 0) {
    rc = -1;
    err = errno;
  }
  if (rc != 0)
    unlink(tmp);
  free(tmp);
  errno = err;
  return rc;
}

void zr__state_remove(const char *path) {
  size_t n = strlen(path) + 8;
  char *tmp = malloc(n);
  if (tmp) {
    snprintf(tmp, n, "%s.tmp", path);
    unlink(tmp);
    snprintf(tmp, n, "%s.gi", path);
    unlink(tmp);
    snprintf(tmp, n, "%s.rad", path);
    unlink(tmp);
    free(tmp);
  }
  unlink(path);
}

void zr__state_free(zr_par_progress *pr) {
  free(pr->done[0]);
  free(pr->done[1]);
  free(pr->centres);
  free(pr->image);
  memset(pr, 0, sizeof *pr);
}

/* Takes size bytes from the file's contents at *at. */
static int take(const char *bytes, size_t total, size_t *at, void *out,
                size_t size) {
  if (total - *at < size)
    return -1;
  memcpy(out, bytes + *at, size);
  *at += size;
  return 0;
}

int zr__state_read(const char *path, uint64_t fingerprint, int width,
                   int height, zr_par_progress *pr, char *err,
                   size_t err_size) {
  int channels = pr->channels == 4 ? 4 : 3;
  memset(pr, 0, sizeof *pr);
  pr->channels = channels;
  FILE *f = fopen(path, "rb");
  if (!f) {
    if (errno == ENOENT)
      return 1;
    snprintf(err, err_size, "cannot read the state file '%s': %s", path,
             strerror(errno));
    return -1;
  }
  struct stat st;
  char *bytes = NULL;
  size_t total = 0;
  if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    total = (size_t)st.st_size;
    bytes = malloc(total);
    if (bytes && fread(bytes, 1, total, f) != total) {
      free(bytes);
      bytes = NULL;
    }
  }
  fclose(f);
  const char *why = NULL;
  size_t at = 0;
  char m[8];
  uint64_t fp = 0, sum;
  int32_t head[5];
  if (!bytes)
    why = "it cannot be read";
  else if (take(bytes, total, &at, m, sizeof m) || memcmp(m, magic, 8))
    why = "it is not a zrcube state file";
  else if (total < 8 + sizeof sum ||
           (memcpy(&sum, bytes + total - sizeof sum, sizeof sum),
            zr__state_hash(ZR_STATE_HASH_START, bytes, total - sizeof sum)
                != sum))
    why = "it is damaged (its checksum does not match)";
  else if (take(bytes, total, &at, &fp, sizeof fp) ||
           take(bytes, total, &at, head, sizeof head))
    why = "it is damaged (too short)";
  else if (head[0] != width || head[1] != height)
    why = "it is of another image size";
  else if (fp != fingerprint)
    why = "it was made by another scene or other options (scene and "
          "included files, size, antialiasing, clock, quality, global "
          "illumination must all be the same)";
  /* The caller's channels: the fingerprint holds +UA. */
  size_t floats = (size_t)width * (size_t)height * (size_t)channels;
  if (!why) {
    pr->passes = head[2];
    pr->bands = head[3];
    pr->band_rows = head[4];
    if (pr->passes < 1 || pr->passes > 2 || pr->bands < 1 ||
        pr->band_rows < 1)
      why = "it is damaged (bad layout)";
  }
  for (int p = 0; !why && p < pr->passes; p++) {
    pr->done[p] = malloc((size_t)pr->bands);
    if (!pr->done[p] ||
        take(bytes, total, &at, pr->done[p], (size_t)pr->bands))
      why = "it is damaged (too short)";
  }
  if (!why && pr->passes == 2) {
    pr->centres = malloc(floats * sizeof(float));
    if (!pr->centres ||
        take(bytes, total, &at, pr->centres, floats * sizeof(float)))
      why = "it is damaged (too short)";
  }
  if (!why) {
    pr->image = malloc(floats * sizeof(float));
    if (!pr->image ||
        take(bytes, total, &at, pr->image, floats * sizeof(float)))
      why = "it is damaged (too short)";
    else if (at + sizeof sum != total)
      why = "it is damaged (wrong length)";
  }
  free(bytes);
  if (why) {
    zr__state_free(pr);
    snprintf(err, err_size, "refusing the state file '%s': %s (remove it "
             "to render from the start)", path, why);
    return -1;
  }
  return 0;
}
