/*
 * parse_fixture.c - the fixture the scene-language tests share (see
 * parse_fixture.h).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parse_fixture.h"

static void on_diag(const zr_diag *d, void *user) {
  captured *c = user;
  if (d->level == ZR_DIAG_DEBUG) {
    size_t n = strlen(c->debug);
    snprintf(c->debug + n, sizeof c->debug - n, "%s", d->message);
  } else if (d->level == ZR_DIAG_WARNING) {
    c->warnings++;
    snprintf(c->warning, sizeof c->warning, "%s", d->text);
  } else if (d->level == ZR_DIAG_ERROR) {
    c->errors++;
    c->status = d->status;
    snprintf(c->message, sizeof c->message, "%s", d->message);
    snprintf(c->text, sizeof c->text, "%s", d->text);
  }
}

static zr_status read_vfile(const char *path, char **bytes, size_t *size,
                            void *user) {
  fixture *f = user;
  for (const vfile *v = f->files; v && v->path; v++) {
    if (strcmp(v->path, path) == 0) {
      *size = strlen(v->text);
      *bytes = malloc(*size + 1);
      if (!*bytes)
        return ZR_ENOMEM;
      memcpy(*bytes, v->text, *size + 1);
      return ZR_OK;
    }
  }
  return ZR_ENOTFOUND;
}

int setup(void **state) {
  fixture *f = calloc(1, sizeof *f);
  assert_non_null(f);
  assert_int_equal(zr_context_new(&f->ctx), ZR_OK);
  zr_context_set_diag(f->ctx, on_diag, &f->diag);
  /* The tests write image and font files in /tmp (or $TMPDIR) and name
     them by absolute path; a string scene has no folder of its own, so
     the I/O restrictions would refuse them. */
  const char *tmp = getenv("TMPDIR");
  assert_int_equal(zr_context_add_read_path(f->ctx, "/tmp"), ZR_OK);
  if (tmp && *tmp)
    assert_int_equal(zr_context_add_read_path(f->ctx, tmp), ZR_OK);
  *state = f;
  return 0;
}

int teardown(void **state) {
  fixture *f = *state;
  zr_scene_free(f->scene);
  zr_context_free(f->ctx);
  free(f);
  return 0;
}

zr_status parse(fixture *f, const char *text) {
  zr_scene_free(f->scene);
  f->scene = NULL;
  memset(&f->diag, 0, sizeof f->diag);
  /* In-memory files when the test gives some; otherwise the reader the
     test set, or the library's own. */
  if (f->files)
    zr_context_set_reader(f->ctx, read_vfile, f);
  return zr_scene_parse_string(f->ctx, "t.pov", text, strlen(text),
                               &f->scene);
}

zr_scene *good(fixture *f, const char *text) {
  zr_status s = parse(f, text);
  if (s != ZR_OK)
    fail_msg("unexpected failure:\n%s", f->diag.text);
  assert_non_null(f->scene);
  return f->scene;
}

void bad(fixture *f, const char *text, zr_status status,
         const char *message, const char *full) {
  zr_status s = parse(f, text);
  assert_int_equal(s, status);
  assert_null(f->scene);
  assert_int_equal(f->diag.errors, 1);
  assert_int_equal(f->diag.status, status);
  assert_string_equal(f->diag.message, message);
  if (full)
    assert_string_equal(f->diag.text, full);
}

const zr_object *only(fixture *f, const char *text) {
  zr_scene *s = good(f, text);
  assert_int_equal(s->n_primitives, 1);
  return s->primitives[0];
}

int cross(const zr_object *obj, zr_vec3 o, zr_vec3 d, double tmin,
          zr_hit h[ZR_MAX_CROSSINGS]) {
  zr_ray r = {o, d};
  return zr__intersect(obj, &r, tmin, INFINITY, h);
}
