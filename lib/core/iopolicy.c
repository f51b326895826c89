/*
 * iopolicy.c - the I/O restrictions, and how the library opens files.
 *
 * A scene is a program: #include, #fopen and every keyword that names a
 * file (image_map, height_field, density_file, text fonts ...) let it
 * ask for any path.  POV-Ray for Unix answers with its "I/O
 * Restrictions" (its Unix documentation, section 1.4): a [File I/O
 * Security] setting of none, read-only or restricted, and [Permitted
 * Paths] folders for reading (read=) and for reading and writing
 * (read+write=).  zRcube keeps the three settings, adds a stricter
 * one, and closes the default: a scene reads what it names by a
 * relative name wherever that leads ("../matrices.inc", as POV-Ray 3.7
 * reads it), a name starting with '/' below its own folder, the working
 * directory, the include paths and POV-Ray's include folder only, and
 * writes below the working directory only; "strict" confines relative
 * names too; the caller adds folders (zrcube.h).
 *
 * A name is judged by where it leads, not by its text: realpath()
 * resolves every symbolic link, the resolved path must lie below a
 * permitted folder (itself resolved), and the resolved path is then
 * opened with O_NOFOLLOW, so a link made after the check is not
 * followed.  Once open, the descriptor is checked again: fstat() says
 * it is a regular file and the same one judged, and on Linux
 * /proc/self/fd names the file it really is, which must still lie below
 * a permitted folder (so swapping a folder for a link between the check
 * and the open gains nothing).  Devices, FIFOs, sockets and directories
 * are refused whatever the setting: none of them is a scene, an image or
 * a data file, and reading /dev/zero or a FIFO would never end.  Opens
 * use O_NONBLOCK, so merely opening a FIFO to look at it cannot hang.
 *
 * Reasons for a refusal name the path and the rule, never the file's
 * contents: a refused file is not read at all.
 */
#define _GNU_SOURCE /* O_TMPFILE, linkat */
#include "config.h"

#include "core/arena.h"
#include "core/budget.h"
#include "core/iopolicy.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/context.h"

static zr_status say(char *why, size_t why_size, zr_status s,
                     const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static zr_status say(char *why, size_t why_size, zr_status s,
                     const char *fmt, ...) {
  if (why && why_size) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, why_size, fmt, ap);
    va_end(ap);
  }
  return s;
}

bool zr__io_inside(const char *path, const char *dir) {
  size_t n = strlen(dir);
  while (n > 1 && dir[n - 1] == '/')
    n--;
  if (n == 1 && dir[0] == '/')
    return path[0] == '/' && path[1] != '\0';
  return n > 0 && strncmp(path, dir, n) == 0 && path[n] == '/' &&
         path[n + 1] != '\0';
}

const char *zr__io_kind(mode_t mode) {
  if (S_ISREG(mode))
    return NULL;
  if (S_ISDIR(mode))
    return "a directory";
  if (S_ISCHR(mode))
    return "a character device";
  if (S_ISBLK(mode))
    return "a block device";
  if (S_ISFIFO(mode))
    return "a FIFO";
  if (S_ISSOCK(mode))
    return "a socket";
  return "not a regular file";
}

char *zr__io_scene_dir(const char *scene_path) {
  if (!scene_path)
    return NULL;
  char *full = realpath(scene_path, NULL);
  if (!full)
    return NULL;
  char *slash = strrchr(full, '/');
  if (slash == full)
    slash[1] = '\0'; /* a scene in / */
  else if (slash)
    *slash = '\0';
  return full;
}

/* Whether resolved lies below dir once dir is resolved too. */
static bool below(const char *resolved, const char *dir) {
  if (!dir)
    return false;
  char *real = realpath(dir, NULL);
  if (!real)
    return false;
  bool in = zr__io_inside(resolved, real);
  free(real);
  return in;
}

static bool below_any(const char *resolved, char *const *dirs, size_t n) {
  for (size_t i = 0; i < n; i++)
    if (zr__io_inside(resolved, dirs[i]))
      return true;
  return false;
}

/* Whether the restrictions let a scene at resolved. */
static bool permitted(const zr_context *ctx, const char *resolved,
                      const char *scene_dir, zr_io_access access) {
  zr_io_restrictions mode = ctx ? ctx->io_mode : ZR_IO_RESTRICTED;
  if (mode == ZR_IO_NONE)
    return true;
  if (access == ZR_IO_ACCESS_READ && mode == ZR_IO_READ_ONLY)
    return true;
  if (below(resolved, "."))
    return true;
  if (ctx && below_any(resolved, ctx->write_dirs, ctx->n_write_dirs))
    return true;
  if (access != ZR_IO_ACCESS_READ)
    return false;
  if (scene_dir && zr__io_inside(resolved, scene_dir))
    return true;
  if (ctx && below_any(resolved, ctx->read_dirs, ctx->n_read_dirs))
    return true;
  for (size_t i = 0; ctx && i < ctx->n_include_paths; i++)
    if (below(resolved, ctx->include_paths[i]))
      return true;
  return below(resolved, ZR_POVRAY_INCLUDE_DIR);
}

static zr_status refuse_outside(const char *path, const char *resolved,
                                zr_io_access access, char *why,
                                size_t why_size) {
  const char *what = access == ZR_IO_ACCESS_READ
                         ? "read (the scene's folder, the working "
                           "directory, the include paths and the read "
                           "paths; --read-path=DIR adds one)"
                         : "write (the working directory and the write "
                           "paths; --write-path=DIR adds one)";
  if (strcmp(path, resolved) != 0)
    return say(why, why_size, ZR_EACCESS,
               "'%s' leads to '%s', outside the folders a scene may %s",
               path, resolved, what);
  return say(why, why_size, ZR_EACCESS,
             "'%s' is outside the folders a scene may %s", path, what);
}

static zr_status refuse_kind(const char *path, mode_t mode, char *why,
                             size_t why_size) {
  return say(why, why_size, ZR_EACCESS, "'%s' is %s, not a regular file",
             path, zr__io_kind(mode));
}

static zr_status cannot(const char *path, int err, char *why,
                        size_t why_size) {
  if (err == ENOENT || err == ENOTDIR)
    return say(why, why_size, ZR_ENOTFOUND, "'%s': %s", path,
               strerror(err));
  return say(why, why_size, ZR_EIO, "'%s': %s", path, strerror(err));
}

/* dir and base of a name to write; base is not empty, "." or "..". */
static zr_status split_name(const char *path, char **dir, const char **base,
                            char *why, size_t why_size) {
  const char *slash = strrchr(path, '/');
  *base = slash ? slash + 1 : path;
  if (!**base || !strcmp(*base, ".") || !strcmp(*base, ".."))
    return say(why, why_size, ZR_EACCESS, "'%s' names a directory, not a "
               "file", path);
  *dir = !slash          ? strdup(".")
         : slash == path ? strdup("/")
                         : strndup(path, (size_t)(slash - path));
  return *dir ? ZR_OK : ZR_ENOMEM;
}

/* The resolved name of a file to write that may not exist yet. */
static zr_status resolve_for_write(const char *path, char **resolved,
                                   bool *existed, char *why,
                                   size_t why_size) {
  struct stat st;
  if (lstat(path, &st) == 0) {
    *resolved = realpath(path, NULL);
    if (!*resolved)
      return say(why, why_size, ZR_EACCESS, "'%s' is a symbolic link "
                 "that leads nowhere (%s)", path, strerror(errno));
    if (stat(*resolved, &st) != 0 || !S_ISREG(st.st_mode)) {
      zr_status s = S_ISREG(st.st_mode) ? cannot(path, errno, why, why_size)
                                        : refuse_kind(path, st.st_mode, why,
                                                      why_size);
      free(*resolved);
      *resolved = NULL;
      return s;
    }
    *existed = true;
    return ZR_OK;
  }
  if (errno != ENOENT)
    return cannot(path, errno, why, why_size);
  char *dir = NULL;
  const char *base;
  zr_status s = split_name(path, &dir, &base, why, why_size);
  if (s != ZR_OK)
    return s;
  char *real_dir = realpath(dir, NULL);
  if (!real_dir) {
    s = say(why, why_size, errno == ENOENT || errno == ENOTDIR
                               ? ZR_ENOTFOUND : ZR_EIO,
            "'%s': no folder '%s' (%s)", path, dir, strerror(errno));
    free(dir);
    return s;
  }
  free(dir);
  size_t n = strlen(real_dir) + strlen(base) + 2;
  *resolved = malloc(n);
  if (*resolved)
    snprintf(*resolved, n, "%s%s%s", real_dir,
             strcmp(real_dir, "/") ? "/" : "", base);
  free(real_dir);
  *existed = false;
  return *resolved ? ZR_OK : ZR_ENOMEM;
}

/*
 * Whether path is a symbolic link that POV-Ray's installation put in its
 * include folder: Debian installs the TrueType fonts there as links into
 * /usr/share/fonts.  A scene cannot make links and that folder is the
 * system's, so what its links lead to is readable; links anywhere else
 * (a scene's folder unpacked from an archive) are judged by their
 * targets.
 */
static bool installed_link(const char *path) {
  struct stat st;
  if (lstat(path, &st) != 0 || !S_ISLNK(st.st_mode))
    return false;
  const char *slash = strrchr(path, '/');
  if (!slash)
    return false;
  char *dir = slash == path ? strdup("/")
                            : strndup(path, (size_t)(slash - path));
  char *real_dir = dir ? realpath(dir, NULL) : NULL;
  char *real_inc = realpath(ZR_POVRAY_INCLUDE_DIR, NULL);
  bool yes = real_dir && real_inc && strcmp(real_dir, real_inc) == 0;
  free(dir);
  free(real_dir);
  free(real_inc);
  return yes;
}

static zr_status check(const zr_context *ctx, const char *path,
                       const char *scene_dir, zr_io_access access,
                       bool relative, char **resolved, bool *existed,
                       bool *trusted, char *why, size_t why_size);

zr_status zr__io_check(const zr_context *ctx, const char *path,
                       const char *scene_dir, zr_io_access access,
                       char **resolved, bool *existed, char *why,
                       size_t why_size) {
  bool trusted;
  return check(ctx, path, scene_dir, access, false, resolved, existed,
               &trusted, why, why_size);
}

/* Whether a read of a relatively named file is open under ctx's
   setting: the default lets a scene read what its relative names lead
   to, as POV-Ray 3.7 does ("../x.inc"); "strict" does not. */
static bool relative_open(const zr_context *ctx, zr_io_access access,
                          bool relative) {
  return relative && access == ZR_IO_ACCESS_READ &&
         (!ctx || ctx->io_mode == ZR_IO_RESTRICTED);
}

static zr_status check(const zr_context *ctx, const char *path,
                       const char *scene_dir, zr_io_access access,
                       bool relative, char **resolved, bool *existed,
                       bool *trusted, char *why, size_t why_size) {
  *resolved = NULL;
  *existed = false;
  *trusted = false;
  if (!path || !*path)
    return say(why, why_size, ZR_ENOTFOUND, "an empty file name");
  zr_status s;
  if (access == ZR_IO_ACCESS_READ) {
    *resolved = realpath(path, NULL);
    if (!*resolved)
      return cannot(path, errno, why, why_size);
    struct stat st;
    if (stat(*resolved, &st) != 0)
      s = cannot(path, errno, why, why_size);
    else if (!S_ISREG(st.st_mode))
      s = refuse_kind(path, st.st_mode, why, why_size);
    else
      s = ZR_OK;
    *existed = s == ZR_OK;
  } else {
    s = resolve_for_write(path, resolved, existed, why, why_size);
  }
  if (s == ZR_OK && !permitted(ctx, *resolved, scene_dir, access)) {
    if (relative_open(ctx, access, relative) ||
        (access == ZR_IO_ACCESS_READ && installed_link(path)))
      *trusted = true;
    else
      s = refuse_outside(path, *resolved, access, why, why_size);
  }
  if (s != ZR_OK) {
    free(*resolved);
    *resolved = NULL;
  }
  return s;
}

/*
 * Checks an open descriptor: a regular file, and (when /proc tells)
 * still below a permitted folder.  Returns ZR_OK or ZR_EACCESS.
 */
static zr_status check_open(const zr_context *ctx, int fd, const char *path,
                            const char *scene_dir, zr_io_access access,
                            bool confined, char *why, size_t why_size) {
  struct stat st;
  if (fstat(fd, &st) != 0)
    return cannot(path, errno, why, why_size);
  if (!S_ISREG(st.st_mode))
    return refuse_kind(path, st.st_mode, why, why_size);
  if (!confined)
    return ZR_OK;
  char link[64], real[PATH_MAX];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  ssize_t n = readlink(link, real, sizeof real - 1);
  if (n <= 0)
    return ZR_OK; /* no /proc: the O_NOFOLLOW open is the guard */
  real[n] = '\0';
  if (!permitted(ctx, real, scene_dir, access))
    return refuse_outside(path, real, access, why, why_size);
  return ZR_OK;
}

/* Why an open of a resolved path with O_NOFOLLOW failed: ELOOP means the
   name became a symbolic link after it was judged. */
static zr_status open_failed(const char *path, int err, char *why,
                             size_t why_size) {
  if (err == ELOOP)
    return say(why, why_size, ZR_EACCESS, "'%s' changed into a symbolic "
               "link while being opened", path);
  return cannot(path, err, why, why_size);
}

/* The message for a file over the file size limit (0: no limit). */
static zr_status too_large(const char *path, unsigned long long limit,
                           char *why, size_t why_size) {
  char text[32];
  return say(why, why_size, ZR_ELIMIT,
             "'%s' is larger than the file size limit of %s (raise it "
             "with --max-file-size)", path,
             zr__budget_size_text((size_t)limit, text, sizeof text));
}

/* Reads all of fd into a malloc'ed buffer ending in a NUL, at most limit
   bytes (0: no limit): a larger regular file is refused unread. */
static zr_status read_all(int fd, const char *path, unsigned long long limit,
                          char **bytes, size_t *size, char *why,
                          size_t why_size) {
  struct stat st;
  size_t cap = 65536;
  bool have_stat = fstat(fd, &st) == 0;
  if (have_stat && limit && S_ISREG(st.st_mode) &&
      (unsigned long long)st.st_size > limit)
    return too_large(path, limit, why, why_size);
  if (have_stat && st.st_size > 0 && (uintmax_t)st.st_size < SIZE_MAX / 2)
    /* Room for the NUL and for one more read to see the end of the
       file: a buffer that fills up doubles, which a big scene cannot
       afford. */
    cap = (size_t)st.st_size + 2;
  /* A big scene file, in huge pages (core/arena.h); below a megabyte
     the pages the file will fill are filled in at once (bench/peers.sh's
     sphereflake, 518 KB: 126 pages). */
  char *buf = zr__huge_alloc(cap);
  if (!buf)
    return say(why, why_size, ZR_ENOMEM, "'%s': out of memory", path);
  if (cap < ZR__HUGE_FROM && cap >= 65536)
    zr__mem_populate(buf, cap - 2);
  size_t len = 0;
  for (;;) {
    if (len + 1 >= cap) {
      char *grown = cap > SIZE_MAX / 2 ? NULL : zr__huge_grow(buf, cap, 2 * cap);
      if (!grown) {
        free(buf);
        return say(why, why_size, ZR_ENOMEM, "'%s': out of memory", path);
      }
      buf = grown;
      cap *= 2;
    }
    ssize_t n = read(fd, buf + len, cap - 1 - len);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0) {
      int err = errno;
      free(buf);
      return say(why, why_size, ZR_EIO, "'%s': %s", path, strerror(err));
    }
    if (n == 0)
      break;
    len += (size_t)n;
    if (limit && len > limit) {
      free(buf);
      return too_large(path, limit, why, why_size);
    }
  }
  buf[len] = '\0';
  *bytes = buf;
  *size = len;
  return ZR_OK;
}

zr_status zr__io_read_scene(zr_context *ctx, const char *path,
                            const char *scene_dir, bool relative,
                            char **bytes, size_t *size, char *why,
                            size_t why_size) {
  char *resolved;
  bool existed, trusted;
  zr_status s = check(ctx, path, scene_dir, ZR_IO_ACCESS_READ, relative,
                      &resolved, &existed, &trusted, why, why_size);
  if (s != ZR_OK)
    return s;
  int fd = open(resolved, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY |
                              O_CLOEXEC);
  free(resolved);
  if (fd < 0)
    return open_failed(path, errno, why, why_size);
  bool confined = (!ctx || ctx->io_mode == ZR_IO_RESTRICTED ||
                   ctx->io_mode == ZR_IO_STRICT) &&
                  !trusted;
  s = check_open(ctx, fd, path, scene_dir, ZR_IO_ACCESS_READ, confined, why,
                 why_size);
  if (s == ZR_OK)
    s = read_all(fd, path, ctx ? ctx->file_limit : ZR_DEFAULT_FILE_LIMIT,
                 bytes, size, why, why_size);
  close(fd);
  return s;
}

zr_status zr__io_read_named(const char *path, char **bytes, size_t *size,
                            char *why, size_t why_size) {
  return zr__io_read_named_max(path, 0, bytes, size, why, why_size);
}

zr_status zr__io_read_named_max(const char *path, unsigned long long limit,
                                char **bytes, size_t *size, char *why,
                                size_t why_size) {
  int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0)
    return cannot(path, errno, why, why_size);
  zr_status s = check_open(NULL, fd, path, NULL, ZR_IO_ACCESS_READ, false,
                           why, why_size);
  if (s == ZR_OK)
    s = read_all(fd, path, limit, bytes, size, why, why_size);
  close(fd);
  return s;
}

zr_status zr__io_open_named(const char *path, FILE **out, char *why,
                            size_t why_size) {
  *out = NULL;
  int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0)
    return cannot(path, errno, why, why_size);
  zr_status s = check_open(NULL, fd, path, NULL, ZR_IO_ACCESS_READ, false,
                           why, why_size);
  if (s == ZR_OK) {
    *out = fdopen(fd, "rb");
    if (!*out)
      s = cannot(path, errno, why, why_size);
  }
  if (!*out)
    close(fd);
  return s;
}

zr_status zr__io_open_scene_write(zr_context *ctx, const char *path,
                                  zr_io_access access, FILE **out,
                                  char *why, size_t why_size) {
  *out = NULL;
  char *resolved;
  bool existed;
  zr_status s = zr__io_check(ctx, path, NULL, access, &resolved, &existed,
                             why, why_size);
  if (s != ZR_OK)
    return s;
  int flags = O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY |
              O_CLOEXEC;
  if (access == ZR_IO_ACCESS_APPEND)
    flags |= O_APPEND;
  int fd = open(resolved, flags, 0666);
  free(resolved);
  if (fd < 0)
    return open_failed(path, errno, why, why_size);
  bool confined = !ctx || ctx->io_mode != ZR_IO_NONE;
  s = check_open(ctx, fd, path, NULL, access, confined, why, why_size);
  /* Truncated only now that the file is known to be the one judged. */
  if (s == ZR_OK && access == ZR_IO_ACCESS_WRITE && ftruncate(fd, 0) != 0)
    s = cannot(path, errno, why, why_size);
  if (s == ZR_OK) {
    int fl = fcntl(fd, F_GETFL);
    if (fl != -1)
      fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    *out = fdopen(fd, access == ZR_IO_ACCESS_APPEND ? "a" : "w");
    if (!*out)
      s = cannot(path, errno, why, why_size);
  }
  if (!*out)
    close(fd);
  return s;
}

zr_status zr__io_output_target(const char *path, char **target, char *why,
                               size_t why_size) {
  *target = NULL;
  struct stat st;
  if (lstat(path, &st) != 0) {
    if (errno != ENOENT)
      return cannot(path, errno, why, why_size);
    *target = strdup(path);
    return *target ? ZR_OK : ZR_ENOMEM;
  }
  if (S_ISLNK(st.st_mode)) {
    char *real = realpath(path, NULL);
    if (!real) {
      /* A link to nothing yet: the link itself is replaced. */
      *target = strdup(path);
      return *target ? ZR_OK : ZR_ENOMEM;
    }
    if (stat(real, &st) != 0) {
      free(real);
      return cannot(path, errno, why, why_size);
    }
    if (!S_ISREG(st.st_mode)) {
      free(real);
      return refuse_kind(path, st.st_mode, why, why_size);
    }
    *target = real;
    return ZR_OK;
  }
  if (!S_ISREG(st.st_mode))
    return refuse_kind(path, st.st_mode, why, why_size);
  *target = strdup(path);
  return *target ? ZR_OK : ZR_ENOMEM;
}

FILE *zr__io_open_temp(const char *target, char **tmp) {
  *tmp = NULL;
  size_t n = strlen(target) + 64;
  char *name = malloc(n);
  if (!name) {
    errno = ENOMEM;
    return NULL;
  }
  for (int attempt = 0; attempt < 100; attempt++) {
    snprintf(name, n, "%s.%ld.%d.tmp", target, (long)getpid(), attempt);
    int fd = open(name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                  0666);
    if (fd < 0) {
      if (errno == EEXIST)
        continue;
      break;
    }
    FILE *f = fdopen(fd, "wb");
    if (!f) {
      int e = errno;
      close(fd);
      unlink(name);
      errno = e;
      break;
    }
    *tmp = name;
    return f;
  }
  int e = errno;
  free(name);
  errno = e;
  return NULL;
}

/* The folder of target ("." for a bare name), malloc'ed. */
static char *folder_of(const char *target) {
  const char *slash = strrchr(target, '/');
  if (!slash)
    return strdup(".");
  size_t n = slash == target ? 1 : (size_t)(slash - target);
  char *dir = malloc(n + 1);
  if (dir) {
    memcpy(dir, target, n);
    dir[n] = '\0';
  }
  return dir;
}

int zr__io_temp_open(zr_io_temp *t, const char *target) {
  t->f = NULL;
  t->name = NULL;
  t->named = 0;
  t->target_len = 0;
#ifdef O_TMPFILE
  /* The unnamed file is named by linking /proc/self/fd/N: without
     /proc, the named file from the start. */
  if (access("/proc/self/fd", X_OK) == 0) {
    char *dir = folder_of(target);
    size_t n = strlen(target) + 64;
    t->name = malloc(n);
    if (!dir || !t->name) {
      free(dir);
      free(t->name);
      t->name = NULL;
      errno = ENOMEM;
      return -1;
    }
    t->target_len = strlen(target);
    memcpy(t->name, target, t->target_len + 1);
    int fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    free(dir);
    if (fd >= 0) {
      t->f = fdopen(fd, "wb");
      if (t->f)
        return 0;
      int e = errno;
      close(fd);
      free(t->name);
      t->name = NULL;
      errno = e;
      return -1;
    }
    free(t->name);
    t->name = NULL;
    /* EISDIR, EOPNOTSUPP, EINVAL ...: a kernel or file system without
       O_TMPFILE; any other error, the named file says it again. */
  }
#endif
  t->f = zr__io_open_temp(target, &t->name);
  t->named = t->f != NULL;
  return t->f ? 0 : -1;
}

int zr__io_temp_close(zr_io_temp *t, int keep) {
  int rc = 0, e = 0;
  if (!t->f)
    return 0;
  if (keep && fflush(t->f) != 0) {
    rc = -1;
    e = errno;
    keep = 0;
  }
  if (keep && !t->named) {
    /* The name zr__io_open_temp would have given, target.PID.N.tmp
       (t->name holds the target and 64 bytes more). */
    char proc[64];
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", fileno(t->f));
    rc = -1;
    e = EEXIST;
    for (int attempt = 0; attempt < 100 && e == EEXIST; attempt++) {
      snprintf(t->name + t->target_len, 64, ".%ld.%d.tmp", (long)getpid(),
               attempt);
      if (linkat(AT_FDCWD, proc, AT_FDCWD, t->name, AT_SYMLINK_FOLLOW) ==
          0) {
        rc = 0;
        e = 0;
        t->named = 1;
      } else {
        e = errno;
      }
    }
    if (rc != 0)
      keep = 0;
  }
  if (fclose(t->f) != 0 && rc == 0) {
    rc = -1;
    e = errno;
  }
  t->f = NULL;
  if (rc != 0 || !keep) {
    if (t->named)
      unlink(t->name);
    t->named = 0;
  }
  if (rc != 0)
    errno = e;
  return rc;
}

void zr__io_temp_free(zr_io_temp *t) {
  free(t->name);
  t->name = NULL;
}
