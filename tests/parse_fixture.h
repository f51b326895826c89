/*
 * parse_fixture.h - what the scene-language test programs share: a
 * cmocka fixture holding a context whose diagnostics are captured and
 * whose reader serves in-memory files, and the calls that parse a text
 * and assert success or an exact error.
 */
#ifndef ZR_TESTS_PARSE_FIXTURE_H
#define ZR_TESTS_PARSE_FIXTURE_H

#include "zrcube.h"

/* A file the reader serves (#include, #fopen): path and contents. */
typedef struct vfile {
  const char *path;
  const char *text;
} vfile;

/* Everything the library reported during one parse. */
typedef struct captured {
  char debug[8192]; /* every #debug message, concatenated */
  int warnings;
  char warning[2048]; /* the last warning's full text */
  int errors;
  zr_status status;   /* the last error's */
  char message[512];  /* the last error's message alone */
  char text[4096];    /* the last error's full text: location, caret */
} captured;

typedef struct fixture {
  zr_context *ctx;
  zr_scene *scene;      /* the last successful parse's */
  const vfile *files;   /* NULL-terminated; NULL: no files */
  captured diag;
} fixture;

/* cmocka group or test setup and teardown for a fixture. */
int setup(void **state);
int teardown(void **state);

/* Parses text as the scene "t.pov", clearing the last scene and
   diagnostics first. */
zr_status parse(fixture *f, const char *text);

/* Parses text that must be good and returns the scene. */
zr_scene *good(fixture *f, const char *text);

/* Parses text that must fail with exactly one error of this status and
   message, and, when full is not NULL, this full text. */
void bad(fixture *f, const char *text, zr_status status,
         const char *message, const char *full);

#endif /* ZR_TESTS_PARSE_FIXTURE_H */
