/*
 * bundle.c - recording, serialising and serving the scene files.
 *
 * ARCHITECTURE.md asks that rank 0 alone read the scene and broadcast its
 * bytes (the way Tachyon's parallel front end keeps I/O on one node).  The
 * library reads every file through a zr_read_fn, so the bundle is just a
 * pair of readers around a list of (path, bytes): one that records what
 * the disk gave rank 0, one that replays it on the other ranks.  Misses
 * are not recorded: a path absent from the bundle is reported as
 * ZR_ENOTFOUND, which is what rank 0 saw for it, so an include search
 * over several directories takes the same turns on every rank.
 *
 * The wire format uses fixed-width little-endian lengths so that ranks on
 * machines of different word size or byte order could share it.
 */
#include "par/bundle.h"

#include "core/hugepage.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char magic[4] = {'Z', 'R', 'B', '1'};

void zr__bundle_init(zr_bundle *bundle) {
  memset(bundle, 0, sizeof *bundle);
}

void zr__bundle_free(zr_bundle *bundle) {
  if (!bundle)
    return;
  for (size_t i = 0; i < bundle->count; i++) {
    free(bundle->files[i].path);
    free(bundle->files[i].bytes);
  }
  free(bundle->files);
  zr__bundle_init(bundle);
}

/*
 * Room for a file's bytes, freed with free.  Rank 0 of several ranks
 * copies every file it reads into the bundle while it parses (the copy
 * is sent only when another rank could not read the same bytes), so
 * the copy is on the path of every multi-rank run: on this project's
 * virtual machine first touching a 4 KiB page costs about 14 us, and
 * bench/peers.sh's 15 MB terrain is 3,700 such pages.  From one huge
 * page on the room is whole 2 MiB pages advised to huge pages
 * (core/hugepage.h), a fault each.  (Its share of session 13's parse
 * gain, bench/results/split-2026-12-03-s13.md, was not measured apart
 * from the mesh's shared build.)  malloc(0) may return NULL, so an
 * empty file still gets one byte.
 */
static char *file_room(size_t size) {
  if (size < ZR__HUGE_PAGE || size > SIZE_MAX - ZR__HUGE_PAGE)
    return malloc(size ? size : 1);
  size_t room = (size + ZR__HUGE_PAGE - 1) & ~(ZR__HUGE_PAGE - 1);
  void *p = NULL;
  if (posix_memalign(&p, ZR__HUGE_PAGE, room) != 0)
    return NULL;
  zr__mem_advise_huge(p, room);
  return p;
}

/* A new entry at the end of the bundle for path, its bytes still
   NULL and its size 0; NULL when memory runs out. */
static zr_bundle_file *append_file(zr_bundle *bundle, const char *path) {
  if (bundle->count == bundle->cap) {
    size_t cap = bundle->cap ? 2 * bundle->cap : 8;
    zr_bundle_file *files = realloc(bundle->files, cap * sizeof *files);
    if (!files)
      return NULL;
    bundle->files = files;
    bundle->cap = cap;
  }
  zr_bundle_file *f = &bundle->files[bundle->count];
  if (!(f->path = strdup(path)))
    return NULL;
  f->bytes = NULL;
  f->size = 0;
  bundle->count++;
  return f;
}

zr_status zr__bundle_add(zr_bundle *bundle, const char *path,
                         const char *bytes, size_t size) {
  char *room = file_room(size);
  zr_bundle_file *f = room ? append_file(bundle, path) : NULL;
  if (!f) {
    free(room);
    return ZR_ENOMEM;
  }
  if (size)
    memcpy(room, bytes, size);
  f->bytes = room;
  f->size = size;
  return ZR_OK;
}

zr_status zr__bundle_add_deferred(zr_bundle *bundle, const char *path,
                                  size_t size) {
  zr_bundle_file *f = append_file(bundle, path);
  if (!f)
    return ZR_ENOMEM;
  f->size = size;
  return ZR_OK;
}

static int deferred(const zr_bundle_file *f) { return !f->bytes && f->size; }

static zr_status read_disk(const char *path, unsigned long long limit,
                           char **bytes, size_t *size);

zr_status zr__bundle_fill(zr_bundle *bundle, zr_read_observer_fn check,
                          void *user, const char **failed) {
  *failed = NULL;
  for (size_t i = 0; i < bundle->count; i++) {
    zr_bundle_file *f = &bundle->files[i];
    if (!deferred(f))
      continue;
    char *bytes = NULL;
    size_t size = 0;
    zr_status s = read_disk(f->path, bundle->max_file_size, &bytes, &size);
    if (s == ZR_OK && size != f->size)
      s = ZR_EIO;
    if (s == ZR_OK)
      s = check(f->path, bytes, size, user);
    if (s != ZR_OK) {
      free(bytes);
      *failed = f->path;
      return s;
    }
    f->bytes = bytes;
  }
  return ZR_OK;
}

const zr_bundle_file *zr__bundle_find(const zr_bundle *bundle,
                                      const char *path) {
  for (size_t i = 0; i < bundle->count; i++)
    if (strcmp(bundle->files[i].path, path) == 0)
      return &bundle->files[i];
  return NULL;
}

static void put_u64(unsigned char *p, uint64_t v) {
  for (int i = 0; i < 8; i++)
    p[i] = (unsigned char)(v >> (8 * i));
}

static uint64_t get_u64(const unsigned char *p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; i++)
    v |= (uint64_t)p[i] << (8 * i);
  return v;
}

zr_status zr__bundle_serialise(const zr_bundle *bundle, char **out,
                               size_t *size) {
  size_t total = sizeof magic + 8;
  for (size_t i = 0; i < bundle->count; i++) {
    if (deferred(&bundle->files[i]))
      return ZR_EINVAL; /* zr__bundle_fill first */
    size_t len = strlen(bundle->files[i].path);
    size_t add = 16 + len + bundle->files[i].size;
    if (add < len || total + add < total)
      return ZR_ELIMIT;
    total += add;
  }
  unsigned char *buf = malloc(total);
  if (!buf)
    return ZR_ENOMEM;
  unsigned char *p = buf;
  memcpy(p, magic, sizeof magic);
  p += sizeof magic;
  put_u64(p, bundle->count);
  p += 8;
  for (size_t i = 0; i < bundle->count; i++) {
    const zr_bundle_file *f = &bundle->files[i];
    size_t len = strlen(f->path);
    put_u64(p, len);
    p += 8;
    memcpy(p, f->path, len);
    p += len;
    put_u64(p, f->size);
    p += 8;
    if (f->size)
      memcpy(p, f->bytes, f->size);
    p += f->size;
  }
  *out = (char *)buf;
  *size = total;
  return ZR_OK;
}

/* Reads a 64-bit length at *pos that must fit in the rest of the blob. */
static int take_length(const unsigned char *bytes, size_t size, size_t *pos,
                       size_t *len) {
  if (size - *pos < 8)
    return 0;
  uint64_t v = get_u64(bytes + *pos);
  *pos += 8;
  if (v > size - *pos)
    return 0;
  *len = (size_t)v;
  return 1;
}

zr_status zr__bundle_deserialise(zr_bundle *bundle, const char *bytes,
                                 size_t size) {
  const unsigned char *b = (const unsigned char *)bytes;
  if (size < sizeof magic + 8 || memcmp(b, magic, sizeof magic) != 0)
    return ZR_EFORMAT;
  size_t pos = sizeof magic;
  uint64_t count = get_u64(b + pos);
  pos += 8;
  zr_bundle parsed;
  zr__bundle_init(&parsed);
  for (uint64_t i = 0; i < count; i++) {
    size_t path_len, data_len;
    if (!take_length(b, size, &pos, &path_len)) {
      zr__bundle_free(&parsed);
      return ZR_EFORMAT;
    }
    const char *path = bytes + pos;
    pos += path_len;
    if (memchr(path, '\0', path_len) ||
        !take_length(b, size, &pos, &data_len)) {
      zr__bundle_free(&parsed);
      return ZR_EFORMAT;
    }
    char *name = malloc(path_len + 1);
    if (!name) {
      zr__bundle_free(&parsed);
      return ZR_ENOMEM;
    }
    memcpy(name, path, path_len);
    name[path_len] = '\0';
    zr_status s = zr__bundle_add(&parsed, name, bytes + pos, data_len);
    free(name);
    if (s != ZR_OK) {
      zr__bundle_free(&parsed);
      return s;
    }
    pos += data_len;
  }
  if (pos != size) {
    zr__bundle_free(&parsed);
    return ZR_EFORMAT;
  }
  /* Only a well-formed blob changes the caller's bundle. */
  for (size_t i = 0; i < parsed.count; i++) {
    zr_bundle_file *f = &parsed.files[i];
    zr_status s = zr__bundle_add(bundle, f->path, f->bytes, f->size);
    if (s != ZR_OK) {
      zr__bundle_free(&parsed);
      return s;
    }
  }
  zr__bundle_free(&parsed);
  return ZR_OK;
}

/*
 * A malloc'ed copy for the library, which frees what a reader returns.
 * Like the library's own stdio reader, it ends in a NUL that size does
 * not count, so a scanner may treat the text as a C string.
 */
static zr_status serve(const zr_bundle_file *f, char **bytes, size_t *size) {
  if (deferred(f))
    return ZR_EIO; /* not read again (zr__bundle_fill) */
  if (f->size == SIZE_MAX)
    return ZR_ENOMEM;
  char *copy = malloc(f->size + 1);
  if (!copy)
    return ZR_ENOMEM;
  if (f->size)
    memcpy(copy, f->bytes, f->size);
  copy[f->size] = '\0';
  *bytes = copy;
  *size = f->size;
  return ZR_OK;
}

static zr_status read_disk(const char *path, unsigned long long limit,
                           char **bytes, size_t *size) {
  FILE *file = fopen(path, "rb");
  if (!file)
    return errno == ENOENT || errno == ENOTDIR ? ZR_ENOTFOUND : ZR_EIO;
  /* A regular file over the limit is refused unread; a device or a
     pipe (/dev/zero) when it has given more than the limit. */
  struct stat st;
  if (limit && fstat(fileno(file), &st) == 0 && S_ISREG(st.st_mode) &&
      (unsigned long long)st.st_size > limit) {
    fclose(file);
    return ZR_ELIMIT;
  }
  size_t cap = 65536, len = 0;
  char *buf = malloc(cap);
  zr_status status = buf ? ZR_OK : ZR_ENOMEM;
  while (status == ZR_OK) {
    /* One byte is kept free for the terminating NUL. */
    if (len + 1 >= cap) {
      char *grown = cap > SIZE_MAX / 2 ? NULL : realloc(buf, 2 * cap);
      if (!grown) {
        status = ZR_ENOMEM;
        break;
      }
      buf = grown;
      cap *= 2;
    }
    size_t n = fread(buf + len, 1, cap - 1 - len, file);
    len += n;
    if (limit && len > limit) {
      status = ZR_ELIMIT;
      break;
    }
    if (n == 0) {
      /* A directory opens on Linux and then fails to read: EIO. */
      if (ferror(file))
        status = ZR_EIO;
      break;
    }
  }
  fclose(file);
  if (status != ZR_OK) {
    free(buf);
    return status;
  }
  buf[len] = '\0';
  *bytes = buf;
  *size = len;
  return ZR_OK;
}

zr_status zr__bundle_record_reader(const char *path, char **bytes,
                                   size_t *size, void *user) {
  zr_bundle *bundle = user;
  const zr_bundle_file *seen = zr__bundle_find(bundle, path);
  if (seen)
    return serve(seen, bytes, size);
  zr_status s = read_disk(path, bundle->max_file_size, bytes, size);
  if (s != ZR_OK)
    return s;
  s = zr__bundle_add(bundle, path, *bytes, *size);
  if (s != ZR_OK) {
    free(*bytes);
    *bytes = NULL;
  }
  return s;
}

zr_status zr__bundle_serve_reader(const char *path, char **bytes,
                                  size_t *size, void *user) {
  const zr_bundle_file *f = zr__bundle_find(user, path);
  return f ? serve(f, bytes, size) : ZR_ENOTFOUND;
}

zr_status zr__bundle_record_observer(const char *path, const char *bytes,
                                     size_t size, void *user) {
  zr_bundle *bundle = user;
  const zr_bundle_file *seen = zr__bundle_find(bundle, path);
  if (seen)
    return seen->size == size &&
                   (size == 0 || deferred(seen) ||
                    memcmp(seen->bytes, bytes, size) == 0)
               ? ZR_OK
               : ZR_EIO;
  if (bundle->defer_from && size >= bundle->defer_from)
    return zr__bundle_add_deferred(bundle, path, size);
  return zr__bundle_add(bundle, path, bytes, size);
}
