/*
 * replay.c - runs the fuzz target's entry point on saved inputs, without
 * libFuzzer, so `make check` (and the sanitizer build) replays every
 * input that once crashed, leaked or hung the parser.
 *
 * With arguments it replays those files; without, every file in
 * $ZR_SRCDIR/tests/fuzz/regress (ZR_REPLAY_DIR: another folder, for the
 * image decoders' target).  An input that still crashes takes the
 * test down with it (and AddressSanitizer names the fault in the
 * --enable-sanitizers build); one that still hangs is caught by the
 * test driver's timeout.
 */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#ifndef ZR_REPLAY_DIR
#define ZR_REPLAY_DIR "tests/fuzz/regress"
#endif

static int replay(const char *path) {
  FILE *fp = fopen(path, "rb");
  if (!fp) {
    fprintf(stderr, "replay: cannot open %s\n", path);
    return 1;
  }
  size_t cap = 4096, n = 0;
  uint8_t *data = malloc(cap);
  size_t got;
  while (data && (got = fread(data + n, 1, cap - n, fp)) > 0) {
    n += got;
    if (n == cap) {
      uint8_t *more = realloc(data, cap *= 2);
      if (!more)
        free(data);
      data = more;
    }
  }
  fclose(fp);
  if (!data) {
    fprintf(stderr, "replay: out of memory reading %s\n", path);
    return 1;
  }
  LLVMFuzzerTestOneInput(data, n);
  free(data);
  return 0;
}

int main(int argc, char **argv) {
  int failed = 0, count = 0;
  if (argc > 1) {
    for (int i = 1; i < argc; i++, count++)
      failed |= replay(argv[i]);
  } else {
    const char *src = getenv("ZR_SRCDIR");
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/" ZR_REPLAY_DIR, src ? src : ".");
    DIR *d = opendir(dir);
    if (!d) {
      fprintf(stderr, "replay: cannot open %s\n", dir);
      return 1;
    }
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      if (e->d_name[0] == '.')
        continue;
      char path[8192];
      snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
      failed |= replay(path);
      count++;
    }
    closedir(d);
    if (count == 0) {
      fprintf(stderr, "replay: no inputs in %s\n", dir);
      return 1;
    }
  }
  printf("replayed %d input%s\n", count, count == 1 ? "" : "s");
  return failed;
}
