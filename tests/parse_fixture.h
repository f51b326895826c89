/*
 * parse_fixture.h - what the scene-language test programs share: a
 * cmocka fixture holding a context whose diagnostics are captured and
 * whose reader serves in-memory files, the calls that parse a text
 * and assert success or an exact error, and the first look the shape
 * tests take at what they parsed (its one primitive, a ray's
 * crossings).
 */
#ifndef ZR_TESTS_PARSE_FIXTURE_H
#define ZR_TESTS_PARSE_FIXTURE_H

#include "scene/scene.h"
#include "trace/intersect.h"
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

/* Parses text that must be good and hold one primitive; returns it. */
const zr_object *only(fixture *f, const char *text);

/* The crossings of the ray o + t d, t from tmin on, with obj: their
   number, and the hits in h. */
int cross(const zr_object *obj, zr_vec3 o, zr_vec3 d, double tmin,
          zr_hit h[ZR_MAX_CROSSINGS]);

#endif /* ZR_TESTS_PARSE_FIXTURE_H */
