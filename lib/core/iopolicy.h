/*
 * iopolicy.h - the I/O restrictions: which files a scene may read and
 * write, and how the library opens files so that a name cannot lead it
 * somewhere else (symbolic links, devices, FIFOs).  See iopolicy.c.
 */
#ifndef ZR_CORE_IOPOLICY_H
#define ZR_CORE_IOPOLICY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <sys/stat.h>

#include "zrcube.h"

typedef enum zr_io_access {
  ZR_IO_ACCESS_READ,
  ZR_IO_ACCESS_WRITE,  /* create or truncate */
  ZR_IO_ACCESS_APPEND  /* create or add to the end */
} zr_io_access;

/* Whether the resolved path lies strictly below the resolved dir. */
bool zr__io_inside(const char *path, const char *dir);

/* "a directory", "a character device", ...: a file that is not regular;
   NULL for a regular file. */
const char *zr__io_kind(mode_t mode);

/* The resolved folder of the main scene file, malloc'ed; NULL when it
   cannot be resolved (then the scene's folder grants nothing). */
char *zr__io_scene_dir(const char *scene_path);

/*
 * Judges a path a scene names for access under ctx's restrictions:
 * resolves its symbolic links, refuses what is not a regular file and
 * what lies outside the permitted folders.  On ZR_OK *resolved is the
 * resolved path (malloc'ed) and *existed whether the file exists (writes
 * may create it).  ZR_ENOTFOUND for a read of a file that does not exist
 * (or a write into a folder that does not); ZR_EACCESS when refused;
 * both with the reason in why.
 */
zr_status zr__io_check(const zr_context *ctx, const char *path,
                       const char *scene_dir, zr_io_access access,
                       char **resolved, bool *existed, char *why,
                       size_t why_size);

/* The library's own reader for a file a scene names: zr__io_check, then
   the resolved path opened without following links and checked again
   once open.  relative: the scene named it by a relative name, which
   ZR_IO_RESTRICTED reads wherever it leads (still a regular file).
   Same results as zr__context_read_scene. */
zr_status zr__io_read_scene(zr_context *ctx, const char *path,
                            const char *scene_dir, bool relative,
                            char **bytes, size_t *size, char *why,
                            size_t why_size);

/* The library's own reader for a file the caller named: any folder,
   regular files only. */
zr_status zr__io_read_named(const char *path, char **bytes, size_t *size,
                            char *why, size_t why_size);
/* The same, refusing a file larger than limit bytes (0: no limit) with
   ZR_ELIMIT. */
zr_status zr__io_read_named_max(const char *path, unsigned long long limit,
                                char **bytes, size_t *size, char *why,
                                size_t why_size);

/* Opens a file the caller named for reading as a stdio stream: any
   folder, regular files only (why says what else it is). */
zr_status zr__io_open_named(const char *path, FILE **out, char *why,
                            size_t why_size);

/* Opens a file a scene writes (#fopen ... write or append) under ctx's
   restrictions; *out is a stdio stream on it. */
zr_status zr__io_open_scene_write(zr_context *ctx, const char *path,
                                  zr_io_access access, FILE **out,
                                  char *why, size_t why_size);

/*
 * The file an output the caller named really is: the name itself, or,
 * when it is a symbolic link, the file it leads to (so the link is kept
 * and its target replaced).  ZR_EACCESS for a name that exists and is
 * not a regular file (a device, a directory ...), with why.
 */
zr_status zr__io_output_target(const char *path, char **target, char *why,
                               size_t why_size);

/*
 * Creates a new file beside target, named target.PID.N.tmp, with O_EXCL
 * so that two writers never share one; *tmp is its malloc'ed name.
 * NULL with errno set on failure.  Writing there and renaming it over
 * the target replaces the target whole or not at all.
 */
FILE *zr__io_open_temp(const char *target, char **tmp);

/*
 * A temporary file that has no name while it is written, where the
 * system allows it (Linux's O_TMPFILE in the target's folder, named
 * through /proc/self/fd when done): a process killed while writing
 * (kill -9 under mpirun, where rank 0 writes as it renders) leaves
 * nothing behind.  Elsewhere, or where the file system refuses
 * O_TMPFILE, it is zr__io_open_temp's named file.  name is the name the
 * file has or will have (target.PID.N.tmp); named says whether it
 * exists yet.
 */
typedef struct zr_io_temp {
  FILE *f;
  char *name;
  int named;
  size_t target_len; /* name's first target_len bytes are the target */
} zr_io_temp;

/* Opens t beside target; -1 with errno set on failure. */
int zr__io_temp_open(zr_io_temp *t, const char *target);

/*
 * Ends the write: with keep, the file gets its name (t->name, to be
 * renamed over the target by the caller) and is closed; without, it is
 * closed and any name removed.  -1 with errno set if the write or the
 * naming failed (the name is then removed).  t->name stays allocated
 * until zr__io_temp_free.
 */
int zr__io_temp_close(zr_io_temp *t, int keep);
void zr__io_temp_free(zr_io_temp *t);

#endif /* ZR_CORE_IOPOLICY_H */
