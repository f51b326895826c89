/*
 * test_iopolicy.c - the I/O restrictions' path rules (lib/core/iopolicy.c)
 * and their context setters: which resolved paths lie below a folder,
 * reads and writes judged after symbolic links, devices, FIFOs and
 * folders refused by name, the three settings, added folders, output
 * targets, and a scene parsed from disk that names a file outside.
 *
 * Every test works in a fresh temporary folder:
 *   work/      the working directory while the test runs
 *   scene/     a scene's folder
 *   outside/   neither: secret.txt
 *   extra/     a folder the tests add as a read or write path
 */
#define _GNU_SOURCE /* O_TMPFILE */
#include "config.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/context.h"
#include "core/iopolicy.h"

typedef struct fixture {
  char top[PATH_MAX];
  char old_cwd[PATH_MAX];
  zr_context *ctx;
  char message[2048]; /* the last error's message */
  unsigned errors;
} fixture;

static void catch_diag(const zr_diag *d, void *user) {
  fixture *fx = user;
  if (d->level == ZR_DIAG_ERROR) {
    fx->errors++;
    snprintf(fx->message, sizeof fx->message, "%s", d->message);
  }
}

/* top/rel, in one of 16 static buffers used in turn. */
static const char *at(const fixture *fx, const char *rel) {
  static char buf[16][PATH_MAX + 64];
  static int k;
  k = (k + 1) % 16;
  snprintf(buf[k], sizeof buf[k], "%s/%s", fx->top, rel);
  return buf[k];
}

static void put(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  assert_non_null(f);
  fputs(text, f);
  fclose(f);
}

static int setup(void **state) {
  fixture *fx = calloc(1, sizeof *fx);
  if (!fx)
    return -1;
  const char *tmp = getenv("TMPDIR");
  char made[PATH_MAX];
  snprintf(made, sizeof made, "%s/zr-iopolicy-XXXXXX",
           tmp && *tmp ? tmp : "/tmp");
  if (!mkdtemp(made) || !realpath(made, fx->top) ||
      !getcwd(fx->old_cwd, sizeof fx->old_cwd))
    return -1;
  const char *dirs[] = {"work", "scene", "outside", "extra"};
  for (size_t i = 0; i < 4; i++)
    if (mkdir(at(fx, dirs[i]), 0777) != 0)
      return -1;
  put(at(fx, "scene/a.inc"), "#declare A = 1;\n");
  put(at(fx, "outside/secret.txt"), "secret-first-line\n");
  put(at(fx, "extra/e.txt"), "extra\n");
  if (chdir(at(fx, "work")) != 0 ||
      zr_context_new(&fx->ctx) != ZR_OK)
    return -1;
  zr_context_set_diag(fx->ctx, catch_diag, fx);
  *state = fx;
  return 0;
}

static int teardown(void **state) {
  fixture *fx = *state;
  zr_context_free(fx->ctx);
  if (chdir(fx->old_cwd) != 0)
    return -1;
  char cmd[PATH_MAX + 16];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", fx->top);
  int rc = system(cmd);
  free(fx);
  return rc == 0 ? 0 : -1;
}

/* zr__io_check for a read, with the scene folder of the fixture. */
static zr_status check_read(fixture *fx, const char *path, char *why,
                            size_t n) {
  char *resolved = NULL;
  bool existed;
  zr_status s = zr__io_check(fx->ctx, path, at(fx, "scene"),
                             ZR_IO_ACCESS_READ, &resolved, &existed, why, n);
  if (s == ZR_OK) {
    assert_non_null(resolved);
    assert_true(existed);
  } else {
    assert_null(resolved);
  }
  free(resolved);
  return s;
}

static zr_status check_write(fixture *fx, const char *path, char *why,
                             size_t n) {
  char *resolved = NULL;
  bool existed;
  zr_status s = zr__io_check(fx->ctx, path, NULL, ZR_IO_ACCESS_WRITE,
                             &resolved, &existed, why, n);
  free(resolved);
  return s;
}

static void test_iopolicy_inside(void **state) {
  (void)state;
  assert_true(zr__io_inside("/a/b", "/a"));
  assert_true(zr__io_inside("/a/b/c", "/a/"));
  assert_false(zr__io_inside("/ab", "/a"));
  assert_false(zr__io_inside("/a", "/a"));
  assert_false(zr__io_inside("/a/", "/a"));
  assert_true(zr__io_inside("/x", "/"));
  assert_false(zr__io_inside("/", "/"));
  assert_false(zr__io_inside("a/b", "/a"));
}

static void test_iopolicy_kind(void **state) {
  (void)state;
  assert_null(zr__io_kind(S_IFREG));
  assert_string_equal(zr__io_kind(S_IFDIR), "a directory");
  assert_string_equal(zr__io_kind(S_IFCHR), "a character device");
  assert_string_equal(zr__io_kind(S_IFBLK), "a block device");
  assert_string_equal(zr__io_kind(S_IFIFO), "a FIFO");
  assert_string_equal(zr__io_kind(S_IFSOCK), "a socket");
}

static void test_iopolicy_read_default_folders(void **state) {
  fixture *fx = *state;
  char why[1024];
  /* The scene's folder, the working directory. */
  assert_int_equal(check_read(fx, at(fx, "scene/a.inc"), why, sizeof why),
                   ZR_OK);
  put("here.txt", "x");
  assert_int_equal(check_read(fx, "here.txt", why, sizeof why), ZR_OK);
  /* Outside: refused, named, never read. */
  const char *secret = at(fx, "outside/secret.txt");
  assert_int_equal(check_read(fx, secret, why, sizeof why), ZR_EACCESS);
  char want[2048];
  snprintf(want, sizeof want, "'%s' is outside the folders a scene may "
           "read (the scene's folder, the working directory, the include "
           "paths and the read paths; --read-path=DIR adds one)", secret);
  assert_string_equal(why, want);
  assert_null(strstr(why, "secret-first-line"));
  /* ".." out of the working directory: resolved, then refused. */
  assert_int_equal(check_read(fx, "../outside/secret.txt", why, sizeof why),
                   ZR_EACCESS);
  snprintf(want, sizeof want, "'../outside/secret.txt' leads to '%s', "
           "outside", secret);
  assert_non_null(strstr(why, want));
  /* A file that is not there: ZR_ENOTFOUND, so a search goes on. */
  assert_int_equal(check_read(fx, "nothing.inc", why, sizeof why),
                   ZR_ENOTFOUND);
  assert_int_equal(check_read(fx, "", why, sizeof why), ZR_ENOTFOUND);
  /* POV-Ray's include folder is always readable (when installed). */
  struct stat st;
  if (stat(ZR_POVRAY_INCLUDE_DIR "/colors.inc", &st) == 0)
    assert_int_equal(check_read(fx, ZR_POVRAY_INCLUDE_DIR "/colors.inc",
                                why, sizeof why),
                     ZR_OK);
}

static void test_iopolicy_read_links(void **state) {
  fixture *fx = *state;
  char why[1024];
  /* A link in the scene's folder to a file outside is judged by where
     it leads; one to a file inside is fine. */
  assert_int_equal(symlink("../outside/secret.txt",
                           at(fx, "scene/out.inc")), 0);
  assert_int_equal(symlink("a.inc", at(fx, "scene/in.inc")), 0);
  assert_int_equal(check_read(fx, at(fx, "scene/out.inc"), why, sizeof why),
                   ZR_EACCESS);
  assert_non_null(strstr(why, "leads to '"));
  assert_non_null(strstr(why, "/outside/secret.txt', outside"));
  assert_int_equal(check_read(fx, at(fx, "scene/in.inc"), why, sizeof why),
                   ZR_OK);
  /* A link to a folder outside, then a file in it. */
  assert_int_equal(symlink(at(fx, "outside"), at(fx, "scene/dir")), 0);
  assert_int_equal(check_read(fx, at(fx, "scene/dir/secret.txt"), why,
                              sizeof why),
                   ZR_EACCESS);
  /* A dangling link: not there. */
  assert_int_equal(symlink("nowhere", at(fx, "scene/dangling.inc")), 0);
  assert_int_equal(check_read(fx, at(fx, "scene/dangling.inc"), why,
                              sizeof why),
                   ZR_ENOTFOUND);
}

static void test_iopolicy_read_not_regular(void **state) {
  fixture *fx = *state;
  char why[1024];
  /* Refused whatever the setting, without blocking on the FIFO. */
  assert_int_equal(mkfifo(at(fx, "scene/fifo"), 0666), 0);
  zr_io_restrictions modes[] = {ZR_IO_RESTRICTED, ZR_IO_READ_ONLY,
                                ZR_IO_NONE, ZR_IO_STRICT};
  for (size_t i = 0; i < 4; i++) {
    assert_int_equal(zr_context_set_io_restrictions(fx->ctx, modes[i]),
                     ZR_OK);
    assert_int_equal(check_read(fx, at(fx, "scene/fifo"), why, sizeof why),
                     ZR_EACCESS);
    assert_non_null(strstr(why, "' is a FIFO, not a regular file"));
    assert_int_equal(check_read(fx, at(fx, "scene"), why, sizeof why),
                     ZR_EACCESS);
    assert_non_null(strstr(why, "' is a directory, not a regular file"));
    char *bytes = NULL;
    size_t size = 0;
    assert_int_equal(zr__io_read_scene(fx->ctx, "/dev/zero", NULL, false,
                                       &bytes, &size, why, sizeof why),
                     ZR_EACCESS);
    assert_null(bytes);
    assert_string_equal(why, "'/dev/zero' is a character device, not a "
                             "regular file");
  }
}

static void test_iopolicy_read_modes_and_paths(void **state) {
  fixture *fx = *state;
  char why[1024];
  const char *e = at(fx, "extra/e.txt");
  assert_int_equal(check_read(fx, e, why, sizeof why), ZR_EACCESS);
  /* An include path, a read path, a write path each open the folder. */
  assert_int_equal(zr_context_add_include_path(fx->ctx, at(fx, "extra")),
                   ZR_OK);
  assert_int_equal(check_read(fx, e, why, sizeof why), ZR_OK);
  zr_context_free(fx->ctx);
  assert_int_equal(zr_context_new(&fx->ctx), ZR_OK);
  /* Relative to the working directory, resolved when added. */
  assert_int_equal(zr_context_add_read_path(fx->ctx, "../extra"), ZR_OK);
  assert_int_equal(check_read(fx, e, why, sizeof why), ZR_OK);
  zr_context_free(fx->ctx);
  assert_int_equal(zr_context_new(&fx->ctx), ZR_OK);
  assert_int_equal(zr_context_add_write_path(fx->ctx, "../extra"), ZR_OK);
  assert_int_equal(check_read(fx, e, why, sizeof why), ZR_OK);
  /* read-only and none read anywhere. */
  const char *secret = at(fx, "outside/secret.txt");
  assert_int_equal(check_read(fx, secret, why, sizeof why), ZR_EACCESS);
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx, ZR_IO_READ_ONLY),
                   ZR_OK);
  assert_int_equal(check_read(fx, secret, why, sizeof why), ZR_OK);
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx, ZR_IO_NONE),
                   ZR_OK);
  assert_int_equal(check_read(fx, secret, why, sizeof why), ZR_OK);
  /* Setter errors. */
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx,
                                                  (zr_io_restrictions)7),
                   ZR_EINVAL);
  assert_int_equal(zr_context_add_read_path(fx->ctx, "no/such/dir"),
                   ZR_ENOTFOUND);
  assert_int_equal(zr_context_add_read_path(fx->ctx, e), ZR_EINVAL);
  assert_int_equal(zr_context_add_write_path(fx->ctx, NULL), ZR_EINVAL);
}

static void test_iopolicy_read_bytes(void **state) {
  fixture *fx = *state;
  char why[1024];
  char *bytes = NULL;
  size_t size = 0;
  assert_int_equal(zr__io_read_scene(fx->ctx, at(fx, "scene/a.inc"),
                                     at(fx, "scene"), false, &bytes, &size,
                                     why, sizeof why),
                   ZR_OK);
  assert_int_equal(size, 16);
  assert_string_equal(bytes, "#declare A = 1;\n");
  free(bytes);
  /* Not the scene's folder when the scene has none. */
  assert_int_equal(zr__io_read_scene(fx->ctx, at(fx, "scene/a.inc"), NULL,
                                     false, &bytes, &size, why, sizeof why),
                   ZR_EACCESS);
  /* A file the caller names: any folder, regular files only. */
  assert_int_equal(zr__io_read_named(at(fx, "outside/secret.txt"), &bytes,
                                     &size, why, sizeof why),
                   ZR_OK);
  assert_string_equal(bytes, "secret-first-line\n");
  free(bytes);
  assert_int_equal(zr__io_read_named("/dev/null", &bytes, &size, why,
                                     sizeof why),
                   ZR_EACCESS);
  assert_int_equal(zr__io_read_named("no-such-file", &bytes, &size, why,
                                     sizeof why),
                   ZR_ENOTFOUND);
}

static void test_iopolicy_write(void **state) {
  fixture *fx = *state;
  char why[1024];
  FILE *f = NULL;
  /* Below the working directory: created, then truncated on reopen. */
  assert_int_equal(zr__io_open_scene_write(fx->ctx, "new.txt",
                                           ZR_IO_ACCESS_WRITE, &f, why,
                                           sizeof why),
                   ZR_OK);
  fputs("one\n", f);
  fclose(f);
  assert_int_equal(zr__io_open_scene_write(fx->ctx, "new.txt",
                                           ZR_IO_ACCESS_APPEND, &f, why,
                                           sizeof why),
                   ZR_OK);
  fputs("two\n", f);
  fclose(f);
  char *bytes;
  size_t size;
  assert_int_equal(zr__io_read_named("new.txt", &bytes, &size, why,
                                     sizeof why),
                   ZR_OK);
  assert_string_equal(bytes, "one\ntwo\n");
  free(bytes);
  /* Outside, through "..", through a link, through a device: refused
     and the file outside untouched. */
  assert_int_equal(check_write(fx, "../outside/new.txt", why, sizeof why),
                   ZR_EACCESS);
  assert_non_null(strstr(why, "outside the folders a scene may write"));
  assert_int_equal(symlink("../outside/secret.txt", "link.txt"), 0);
  assert_int_equal(zr__io_open_scene_write(fx->ctx, "link.txt",
                                           ZR_IO_ACCESS_WRITE, &f, why,
                                           sizeof why),
                   ZR_EACCESS);
  assert_null(f);
  assert_int_equal(zr__io_read_named(at(fx, "outside/secret.txt"), &bytes,
                                     &size, why, sizeof why),
                   ZR_OK);
  assert_string_equal(bytes, "secret-first-line\n");
  free(bytes);
  assert_int_equal(check_write(fx, "/dev/null", why, sizeof why),
                   ZR_EACCESS);
  assert_string_equal(why, "'/dev/null' is a character device, not a "
                           "regular file");
  assert_int_equal(check_write(fx, "sub/", why, sizeof why), ZR_EACCESS);
  assert_int_equal(check_write(fx, "no/such/dir/x.txt", why, sizeof why),
                   ZR_ENOTFOUND);
  /* The scene's folder and read paths do not open writing. */
  assert_int_equal(zr_context_add_read_path(fx->ctx, "../extra"), ZR_OK);
  assert_int_equal(check_write(fx, "../extra/w.txt", why, sizeof why),
                   ZR_EACCESS);
  /* read-only still confines writes; a write path or none opens them. */
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx, ZR_IO_READ_ONLY),
                   ZR_OK);
  assert_int_equal(check_write(fx, "../outside/new.txt", why, sizeof why),
                   ZR_EACCESS);
  assert_int_equal(zr_context_add_write_path(fx->ctx, "../extra"), ZR_OK);
  assert_int_equal(check_write(fx, "../extra/w.txt", why, sizeof why),
                   ZR_OK);
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx, ZR_IO_NONE),
                   ZR_OK);
  assert_int_equal(check_write(fx, "../outside/new.txt", why, sizeof why),
                   ZR_OK);
}

static void test_iopolicy_output_target(void **state) {
  fixture *fx = *state;
  (void)fx;
  char why[1024];
  char *target = NULL;
  assert_int_equal(zr__io_output_target("fresh.png", &target, why,
                                        sizeof why),
                   ZR_OK);
  assert_string_equal(target, "fresh.png");
  free(target);
  /* A link: its file, so the link stays. */
  put("real.png", "x");
  assert_int_equal(symlink("real.png", "link.png"), 0);
  assert_int_equal(zr__io_output_target("link.png", &target, why,
                                        sizeof why),
                   ZR_OK);
  char want[PATH_MAX + 16];
  snprintf(want, sizeof want, "%s/work/real.png", fx->top);
  assert_string_equal(target, want);
  free(target);
  assert_int_equal(zr__io_output_target("/dev/full", &target, why,
                                        sizeof why),
                   ZR_EACCESS);
  assert_string_equal(why, "'/dev/full' is a character device, not a "
                           "regular file");
  assert_int_equal(zr__io_output_target(".", &target, why, sizeof why),
                   ZR_EACCESS);
  /* The temporary file sits beside the target and is new. */
  char *tmp = NULL;
  FILE *f = zr__io_open_temp("real.png", &tmp);
  assert_non_null(f);
  assert_non_null(strstr(tmp, "real.png."));
  fclose(f);
  assert_int_equal(unlink(tmp), 0);
  free(tmp);
}

/* Entries of the working folder whose name holds ".tmp". */
static int temp_names(void) {
  DIR *d = opendir(".");
  assert_non_null(d);
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d)) != NULL)
    n += strstr(e->d_name, ".tmp") != NULL;
  closedir(d);
  return n;
}

/* Whether this folder's file system makes unnamed files. */
static int folder_has_tmpfile(void) {
#if defined(O_TMPFILE)
  if (access("/proc/self/fd", X_OK) != 0)
    return 0;
  int fd = open(".", O_TMPFILE | O_WRONLY, 0600);
  if (fd < 0)
    return 0;
  close(fd);
  return 1;
#else
  return 0;
#endif
}

/* zr__io_temp_open: the file has no name while written (where the file
   system allows), gets target.PID.N.tmp when kept, and leaves nothing
   when dropped or when the process is killed while writing. */
static void test_iopolicy_temp_unnamed(void **state) {
  (void)state;
  int unnamed = folder_has_tmpfile();
  zr_io_temp t;
  assert_int_equal(zr__io_temp_open(&t, "pic.png"), 0);
  assert_int_equal(t.named, !unnamed);
  assert_int_equal(temp_names(), t.named);
  assert_int_equal(fputs("picture", t.f) >= 0, 1);
  assert_int_equal(zr__io_temp_close(&t, 1), 0);
  assert_int_equal(t.named, 1);
  assert_non_null(strstr(t.name, "pic.png."));
  assert_int_equal(temp_names(), 1);
  assert_int_equal(rename(t.name, "pic.png"), 0);
  zr__io_temp_free(&t);
  FILE *f = fopen("pic.png", "rb");
  assert_non_null(f);
  char got[16] = {0};
  assert_int_equal(fread(got, 1, sizeof got, f), 7);
  fclose(f);
  assert_string_equal(got, "picture");
  /* Its mode is a new file's (0666 less the umask), as a named one. */
  mode_t mask = umask(0);
  umask(mask);
  struct stat st;
  assert_int_equal(stat("pic.png", &st), 0);
  assert_int_equal(st.st_mode & 0777, 0666 & ~mask);

  /* Dropped: nothing left. */
  assert_int_equal(zr__io_temp_open(&t, "pic.png"), 0);
  fputs("half", t.f);
  assert_int_equal(zr__io_temp_close(&t, 0), 0);
  zr__io_temp_free(&t);
  assert_int_equal(temp_names(), 0);

  /* Killed while writing (kill -9 under mpirun). */
  pid_t child = fork();
  assert_true(child >= 0);
  if (child == 0) {
    zr_io_temp c;
    if (zr__io_temp_open(&c, "pic.png") != 0)
      _exit(3);
    fputs("half", c.f);
    fflush(c.f);
    raise(SIGKILL);
    _exit(4);
  }
  int status = 0;
  assert_int_equal(waitpid(child, &status, 0), child);
  assert_true(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  assert_int_equal(temp_names(), unnamed ? 0 : 1);
}

/* The observer sees what the library's reader read, and may veto it. */
typedef struct seen {
  char path[PATH_MAX];
  size_t size;
  int calls;
  zr_status answer;
} seen;

static zr_status observe(const char *path, const char *bytes, size_t size,
                         void *user) {
  (void)bytes;
  seen *s = user;
  snprintf(s->path, sizeof s->path, "%s", path);
  s->size = size;
  s->calls++;
  return s->answer;
}

static void test_iopolicy_observer(void **state) {
  fixture *fx = *state;
  seen s = {{0}, 0, 0, ZR_OK};
  zr_context_set_read_observer(fx->ctx, observe, &s);
  char why[512];
  char *bytes = NULL;
  size_t size = 0;
  const char *a = at(fx, "scene/a.inc");
  assert_int_equal(zr__context_read_scene(fx->ctx, a, at(fx, "scene"),
                                          false, &bytes, &size, why,
                                          sizeof why),
                   ZR_OK);
  free(bytes);
  assert_int_equal(s.calls, 1);
  assert_string_equal(s.path, a);
  assert_int_equal(s.size, 16);
  /* Refused files are not read, so not observed. */
  assert_int_equal(zr__context_read_scene(fx->ctx,
                                          at(fx, "outside/secret.txt"),
                                          at(fx, "scene"), false, &bytes,
                                          &size, why, sizeof why),
                   ZR_EACCESS);
  assert_int_equal(s.calls, 1);
  s.answer = ZR_EIO;
  bytes = NULL;
  assert_int_equal(zr__context_read(fx->ctx, a, &bytes, &size), ZR_EIO);
  assert_null(bytes);
}

/* A scene on disk under "strict": the refusal is located at the name
   and never shows the file; file_exists() says no. */
static void test_iopolicy_scene_on_disk(void **state) {
  fixture *fx = *state;
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx, ZR_IO_STRICT),
                   ZR_OK);
  assert_int_equal(symlink("../outside/secret.txt",
                           at(fx, "scene/secret.inc")), 0);
  put(at(fx, "scene/s.pov"),
      "#declare E = file_exists(\"secret.inc\");\n"
      "#if (E) #error \"seen\" #end\n"
      "#include \"a.inc\"\n"
      "  #include \"secret.inc\"\n");
  zr_scene *scene = NULL;
  assert_int_equal(zr_scene_parse_file(fx->ctx, at(fx, "scene/s.pov"),
                                       &scene),
                   ZR_EACCESS);
  assert_null(scene);
  assert_int_equal(fx->errors, 1);
  assert_non_null(strstr(fx->message, "cannot read include file: '"));
  assert_non_null(strstr(fx->message, "/scene/secret.inc' leads to '"));
  assert_null(strstr(fx->message, "secret-first-line"));
  assert_null(strstr(zr_context_last_error(fx->ctx), "secret-first-line"));
  assert_non_null(strstr(zr_context_last_error(fx->ctx), "s.pov:4:12: "));
  /* With the folder added the same scene reads the file (and stops on
     its text, an undefined name). */
  assert_int_equal(zr_context_add_read_path(fx->ctx, at(fx, "outside")),
                   ZR_OK);
  assert_int_equal(zr_scene_parse_file(fx->ctx, at(fx, "scene/s.pov"),
                                       &scene),
                   ZR_ESCENE);
  assert_non_null(strstr(fx->message, "seen"));
}

/* The default reads what a scene names by a relative name wherever it
   leads ("../x.inc", as POV-Ray 3.7 does); strict does not; absolute
   names and writes stay confined; devices stay refused. */
static void test_iopolicy_relative_reads(void **state) {
  fixture *fx = *state;
  char why[1024];
  char *bytes = NULL;
  size_t size = 0;
  /* The name the parser joined: the scene's folder and "../outside/..". */
  const char *joined = at(fx, "scene/../outside/secret.txt");
  assert_int_equal(zr__io_read_scene(fx->ctx, joined, at(fx, "scene"), true,
                                     &bytes, &size, why, sizeof why),
                   ZR_OK);
  assert_string_equal(bytes, "secret-first-line\n");
  free(bytes);
  bytes = NULL;
  assert_int_equal(zr__io_read_scene(fx->ctx, joined, at(fx, "scene"),
                                     false, &bytes, &size, why, sizeof why),
                   ZR_EACCESS);
  assert_null(bytes);
  assert_int_equal(zr__io_read_scene(fx->ctx, "/dev/zero", NULL, true,
                                     &bytes, &size, why, sizeof why),
                   ZR_EACCESS);
  assert_int_equal(check_write(fx, at(fx, "outside/new.txt"), why,
                               sizeof why),
                   ZR_EACCESS);
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx, ZR_IO_STRICT),
                   ZR_OK);
  assert_int_equal(zr__io_read_scene(fx->ctx, joined, at(fx, "scene"), true,
                                     &bytes, &size, why, sizeof why),
                   ZR_EACCESS);
  assert_null(bytes);
  assert_non_null(strstr(why, "outside the folders a scene may read"));
  /* Strict still reads the scene's folder. */
  assert_int_equal(zr__io_read_scene(fx->ctx, at(fx, "scene/a.inc"),
                                     at(fx, "scene"), true, &bytes, &size,
                                     why, sizeof why),
                   ZR_OK);
  free(bytes);
  /* A whole scene: "../outside" by a relative name is read under the
     default, and the same file by its absolute name is refused. */
  assert_int_equal(zr_context_set_io_restrictions(fx->ctx, ZR_IO_RESTRICTED),
                   ZR_OK);
  put(at(fx, "outside/o.inc"), "#declare O = 2;\n");
  put(at(fx, "scene/r.pov"),
      "#include \"../outside/o.inc\"\n"
      "#if (O != 2) #error \"not read\" #end\n"
      "#if (!file_exists(\"../outside/o.inc\")) #error \"no file\" #end\n");
  zr_scene *scene = NULL;
  assert_int_equal(zr_scene_parse_file(fx->ctx, at(fx, "scene/r.pov"),
                                       &scene),
                   ZR_OK);
  zr_scene_free(scene);
  char text[PATH_MAX + 64];
  snprintf(text, sizeof text, "#include \"%s\"\n", at(fx, "outside/o.inc"));
  put(at(fx, "scene/abs.pov"), text);
  scene = NULL;
  assert_int_equal(zr_scene_parse_file(fx->ctx, at(fx, "scene/abs.pov"),
                                       &scene),
                   ZR_EACCESS);
  assert_null(scene);
  assert_non_null(strstr(fx->message, "outside the folders a scene may read"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)
      T(test_iopolicy_inside),
      T(test_iopolicy_kind),
      T(test_iopolicy_read_default_folders),
      T(test_iopolicy_read_links),
      T(test_iopolicy_read_not_regular),
      T(test_iopolicy_read_modes_and_paths),
      T(test_iopolicy_read_bytes),
      T(test_iopolicy_write),
      T(test_iopolicy_output_target),
      T(test_iopolicy_observer),
      T(test_iopolicy_scene_on_disk),
      T(test_iopolicy_relative_reads),
      T(test_iopolicy_temp_unnamed),
#undef T
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
