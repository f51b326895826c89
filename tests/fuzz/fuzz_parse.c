/*
 * fuzz_parse.c - a libFuzzer target for the scene language front end.
 *
 * Each input is parsed as a whole scene with zr_scene_parse_string(),
 * the path every user scene takes (lexer, directive engine, grammar,
 * function compiler, scene building and finishing).  The context's
 * reader refuses every file, so "#include" and friends never touch the
 * disk and a run depends on nothing but its input.  Diagnostics go to a
 * callback that only touches the formatted text, so the message and
 * caret formatting are exercised too.  The work budget is 20,000 steps
 * (directives, macro calls and loop passes; zr_context_set_work_limit),
 * so that an endless "#while" or a macro tree ends with its error in
 * milliseconds rather than after the default budget's minute, which the
 * fuzzer would report as a hang; the memory budget is 512 MiB, below
 * libFuzzer's default RSS limit of 2 GiB.
 * The parse runs on a thread of its own with a 64 MiB stack: nested
 * parses stop at ZR_SDL_MAX_NESTED_PARSE levels, which an ordinary build
 * reaches in under 2 MiB, but the sanitizers' frames are several times
 * larger and overflowed libFuzzer's 8 MiB main stack first.
 * Built with --enable-fuzz and
 * clang (tests/fuzz/local.mk); tests/fuzz/replay.c calls the same entry
 * point on the saved regression inputs in every `make check`.
 */
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "zrcube.h"

/* No file may be read: includes fail as "not found". */
static zr_status refuse(const char *path, char **bytes, size_t *size,
                        void *user) {
  (void)path;
  (void)user;
  *bytes = NULL;
  *size = 0;
  return ZR_ENOTFOUND;
}

/* Reads every byte of the message so a bad pointer or a missing NUL in
   the formatting shows up under AddressSanitizer. */
static void on_diag(const zr_diag *d, void *user) {
  size_t *sum = user;
  if (d->text)
    *sum += strlen(d->text);
  if (d->message)
    *sum += strlen(d->message);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct job {
  const uint8_t *data;
  size_t size;
} job;

static void *parse_one(void *arg) {
  const job *j = arg;
  const uint8_t *data = j->data;
  size_t size = j->size;
  zr_context *ctx = NULL;
  if (zr_context_new(&ctx) != ZR_OK)
    return NULL;
  size_t sum = 0;
  zr_context_set_reader(ctx, refuse, NULL);
  zr_context_set_work_limit(ctx, 20000);
  zr_context_set_memory_limit(ctx, 512ULL << 20);
  zr_context_set_diag(ctx, on_diag, &sum);
  zr_scene *scene = NULL;
  if (zr_scene_parse_string(ctx, "fuzz.pov", (const char *)data, size,
                            &scene) == ZR_OK) {
    zr_scene_info info;
    zr_scene_get_info(scene, &info);
  }
  zr_scene_free(scene);
  zr_context_free(ctx);
  return NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  job j = {data, size};
  pthread_attr_t attr;
  pthread_t t;
  if (pthread_attr_init(&attr) != 0)
    return 0;
  pthread_attr_setstacksize(&attr, (size_t)64 << 20);
  if (pthread_create(&t, &attr, parse_one, &j) == 0)
    pthread_join(t, NULL);
  pthread_attr_destroy(&attr);
  return 0;
}
