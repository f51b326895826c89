/*
 * bundle.h - the scene files rank 0 read, as one broadcastable blob.
 *
 * Rank 0 parses with a reader that reads from disk and records every file
 * it serves; the recording is serialised, broadcast, and every other rank
 * parses with a reader that serves the same bytes from memory.  So only
 * rank 0 touches the file system, and every rank sees exactly the files
 * rank 0 saw even when the other ranks run on hosts without them.
 */
#ifndef ZR_PAR_BUNDLE_H
#define ZR_PAR_BUNDLE_H

#include <stddef.h>

#include "zrcube.h"

typedef struct zr_bundle_file {
  char *path;  /* exactly as the parser asked for it */
  char *bytes; /* contents, not NUL-terminated; NULL while deferred */
  size_t size;
} zr_bundle_file;

typedef struct zr_bundle {
  zr_bundle_file *files;
  size_t count;
  size_t cap;
  /* The record reader refuses a file larger than this (0: no limit),
     before reading it all: the context's file limit. */
  unsigned long long max_file_size;
  /* zr__bundle_record_observer keeps only the path and size of a file
     of this many bytes or more (0: keeps every file's bytes); the
     bytes are read again by zr__bundle_fill if they must travel. */
  size_t defer_from;
} zr_bundle;

void zr__bundle_init(zr_bundle *bundle);
void zr__bundle_free(zr_bundle *bundle);

/* Appends a copy of path and bytes. */
zr_status zr__bundle_add(zr_bundle *bundle, const char *path,
                         const char *bytes, size_t size);

/* Appends a copy of path, and size bytes to be read again from disk by
   zr__bundle_fill (bytes NULL until then). */
zr_status zr__bundle_add_deferred(zr_bundle *bundle, const char *path,
                                  size_t size);

/*
 * Reads every deferred file again from disk (at most max_file_size
 * bytes) and keeps it when check (path, bytes, size, user) accepts it:
 * the caller tells the bytes it parsed from other ones.  Stops at the
 * first file that cannot be read or is refused, with that status (the
 * check's own, ZR_EIO when the size differs) and *failed naming it;
 * that file stays deferred.
 */
zr_status zr__bundle_fill(zr_bundle *bundle, zr_read_observer_fn check,
                          void *user, const char **failed);

/* The file recorded under exactly this path, or NULL. */
const zr_bundle_file *zr__bundle_find(const zr_bundle *bundle,
                                      const char *path);

/*
 * The wire format: "ZRB1", a 64-bit little-endian file count, then per
 * file a 64-bit path length, the path, a 64-bit size and the bytes.
 * *out is malloc'ed.  ZR_EINVAL while a file is deferred.
 */
zr_status zr__bundle_serialise(const zr_bundle *bundle, char **out,
                               size_t *size);

/* Appends the files of a serialised bundle; ZR_EFORMAT when malformed. */
zr_status zr__bundle_deserialise(zr_bundle *bundle, const char *bytes,
                                 size_t size);

/*
 * A zr_read_fn (user: the zr_bundle) that reads from disk and records
 * what it read.  A path read twice is served from the recording, so the
 * parse sees one version of each file.
 */
zr_status zr__bundle_record_reader(const char *path, char **bytes,
                                   size_t *size, void *user);

/*
 * A zr_read_observer_fn (user: the zr_bundle) that records what the
 * library's own reader read, which applies the I/O restrictions (rank 0
 * parses with it).  A path read again must give the same bytes, else
 * ZR_EIO: the other ranks would see one version of it (of a deferred
 * file only the size is compared here; its bytes are the caller's to
 * check, as zr__bundle_fill's check does).
 */
zr_status zr__bundle_record_observer(const char *path, const char *bytes,
                                     size_t size, void *user);

/* A zr_read_fn (user: the zr_bundle) serving recorded files only.  Both
   readers, like the library's default one, put a NUL after the bytes
   (not counted in *size). */
zr_status zr__bundle_serve_reader(const char *path, char **bytes,
                                  size_t *size, void *user);

#endif /* ZR_PAR_BUNDLE_H */
