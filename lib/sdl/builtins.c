/*
 * builtins.c - the built-in functions of the scene language that go
 * beyond arithmetic: comparisons and truth, rotations of vectors,
 * strings, random streams and arrays.
 *
 * Semantics are the reference manual's (r3_3): "Float Operators" (two
 * floats are equal when they differ by less than 1e-10, and a value
 * within 1e-10 of zero is false), "Float Functions", "Vector Functions"
 * (vrotate turns about x, then y, then z by degrees, left-handed, like
 * the rotate modifier; vaxis_rotate turns about an arbitrary axis the
 * same way), "String Functions" (str's width and precision, vstr's
 * dimension clipping, substr's one-based positions) and "Array
 * Identifiers" (up to five dimensions, row-major initialisers).
 * inside() asks the tracer's inside test (trace/intersect.c), and
 * vturbulence() the pattern code's turbulence (scene/pattern.c), whose
 * noise is zRcube's own: its values are not POV-Ray's.
 *
 * rand() streams are POV-Ray's, as measured by bench/noise/probe_rand.sh
 * (which records the values tests/test_noise.c checks): seed(n) cuts n to
 * a 32-bit signed integer (toward zero; out of range gives -2^31), and
 * each rand() steps the linear congruential generator
 * s' = 1812433253 s + 12345 mod 2^32 and returns s' / (2^32 - 1), so 1 is
 * a possible value and the stream repeats after 2^32 steps.
 *
 * Strings and arrays live in the scene's arena: they are values that
 * identifiers keep until the scene is freed.
 */
#include "config.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/strbuf.h"
#include "pov-parse.h"
#include "sdl/sdl.h"
#include "scene/pattern.h"
#include "trace/intersect.h"

/* The reference manual's epsilon for truth and equality: "Numeric
   Expressions" (3.3.1.5) calls values within about 1.0e-10 of zero false
   and of each other equal; "Operators" (3.3.1.5.3) writes A = B as
   abs(A-B) < EPSILON and A != B as abs(A-B) >= EPSILON. */
#define EPSILON 1e-10

/* The largest array the language may make: more elements than this is a
   typing mistake rather than a scene. */
#define MAX_ARRAY_ELEMENTS 100000000u

bool zr__sdl_truth(zr_sdl_parser *p, const zr_sdl_expr *e,
                   const zr_sdl_loc *loc, bool *out) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  *out = fabs(v) > EPSILON;
  return true;
}

bool zr__sdl_compare(zr_sdl_parser *p, int op, const zr_sdl_expr *a,
                     const zr_sdl_expr *b, const zr_sdl_loc *loc,
                     zr_sdl_expr *out) {
  double x, y;
  /* An infinity compares (a division by zero upstream, which POV-Ray
     lets through: tests/legacy/divzero.pov). */
  if (!zr__sdl_want_any_float(p, a, loc, &x) ||
      !zr__sdl_want_any_float(p, b, loc, &y))
    return false;
  bool r;
  switch (op) {
  case '<': r = x < y; break;
  case '>': r = x > y; break;
  case T_LE: r = x <= y; break;
  case T_GE: r = x >= y; break;
  case '=': r = fabs(x - y) < EPSILON; break;
  case T_NE: r = fabs(x - y) >= EPSILON; break;
  case '&': r = fabs(x) > EPSILON && fabs(y) > EPSILON; break;
  default: r = fabs(x) > EPSILON || fabs(y) > EPSILON; break;
  }
  *out = zr__sdl_float(r ? 1 : 0);
  return true;
}

static zr_sdl_expr from_vec3(zr_vec3 v) { return zr__sdl_vec(v.x, v.y, v.z); }

/* The tracer's inside test; a union is inside where any child is.  The
   build pushes a union's inverse down into its children (build.c), so
   each level undoes its own flip on the children's answers and applies
   it once to the union's. */
static bool object_inside(const zr_object *o, zr_vec3 p) {
  if (o->kind != ZR_OBJ_UNION)
    return zr__inside(o, p);
  bool in = false;
  for (size_t i = 0; i < o->u.csg.n_children && !in; i++)
    in = object_inside(o->u.csg.children[i], p) != o->inverse;
  return in != o->inverse;
}

bool zr__sdl_inside(zr_sdl_parser *p, const zr_object *o,
                    const zr_sdl_expr *point, const zr_sdl_loc *loc,
                    zr_sdl_expr *out) {
  zr_vec3 v;
  if (!zr__sdl_want_vector(p, point, loc, &v))
    return false;
  *out = zr__sdl_float(object_inside(o, v) ? 1 : 0);
  return true;
}

bool zr__sdl_vturbulence(zr_sdl_parser *p, const zr_sdl_expr *lambda,
                         const zr_sdl_expr *omega,
                         const zr_sdl_expr *octaves,
                         const zr_sdl_expr *point, const zr_sdl_loc *loc,
                         zr_sdl_expr *out) {
  double l, o, n;
  zr_vec3 a;
  if (!zr__sdl_want_float(p, lambda, loc, &l) ||
      !zr__sdl_want_float(p, omega, loc, &o) ||
      !zr__sdl_want_float(p, octaves, loc, &n) ||
      !zr__sdl_want_vector(p, point, loc, &a))
    return false;
  if (!(n >= 1 && n <= 10)) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "vturbulence: octaves must be from 1 to 10, not %g", n);
    return false;
  }
  *out = from_vec3(zr__dturbulence(a, (int)n, o, l));
  return true;
}

bool zr__sdl_vrotate(zr_sdl_parser *p, const zr_sdl_expr *v,
                     const zr_sdl_expr *r, const zr_sdl_loc *loc,
                     zr_sdl_expr *out) {
  zr_vec3 a, degrees;
  if (!zr__sdl_want_vector(p, v, loc, &a) ||
      !zr__sdl_want_vector(p, r, loc, &degrees))
    return false;
  zr_transform t;
  zr__transform_identity(&t);
  zr__transform_rotate(&t, degrees);
  *out = from_vec3(zr__xform_point(t.m, a));
  return true;
}

bool zr__sdl_vaxis_rotate(zr_sdl_parser *p, const zr_sdl_expr *v,
                          const zr_sdl_expr *axis, const zr_sdl_expr *deg,
                          const zr_sdl_loc *loc, zr_sdl_expr *out) {
  zr_vec3 a, k;
  double degrees;
  if (!zr__sdl_want_vector(p, v, loc, &a) ||
      !zr__sdl_want_vector(p, axis, loc, &k) ||
      !zr__sdl_want_float(p, deg, loc, &degrees))
    return false;
  if (zr_v3_len(k) == 0) {
    zr__sdl_error(p, ZR_ESCENE, loc, "vaxis_rotate: the axis is zero");
    return false;
  }
  /* Rodrigues' formula; its sense agrees with rotate's (rotate z*90
     takes x to y), so vaxis_rotate(A, y, F) = vrotate(A, y*F). */
  k = zr_v3_norm(k);
  double th = degrees * 3.14159265358979323846 / 180.0;
  double c = cos(th), s = sin(th);
  zr_vec3 r = zr_v3_add(zr_v3_add(zr_v3_scale(a, c),
                                  zr_v3_scale(zr_v3_cross(k, a), s)),
                        zr_v3_scale(k, zr_v3_dot(k, a) * (1 - c)));
  *out = from_vec3(r);
  return true;
}

/* ---- strings ---- */

const char *zr__sdl_strdup(zr_sdl_parser *p, const char *s, size_t n) {
  char *r = zr__sdl_alloc(p, n + 1);
  if (!r)
    return NULL;
  memcpy(r, s, n);
  r[n] = '\0';
  return r;
}

const char *zr__sdl_concat(zr_sdl_parser *p, const char *a, const char *b) {
  size_t na = strlen(a), nb = strlen(b);
  char *r = zr__sdl_alloc(p, na + nb + 1);
  if (!r)
    return NULL;
  memcpy(r, a, na);
  memcpy(r + na, b, nb + 1);
  return r;
}

/* Formats v as str(v, width, prec) does into sb. */
static void format_float(zr_strbuf *sb, double v, double width,
                         double prec) {
  int w = (int)fabs(width);
  int pr = prec < 0 ? 6 : (int)prec;
  if (w > 255)
    w = 255;
  if (pr > 50)
    pr = 50;
  if (width < 0)
    zr__strbuf_printf(sb, "%0*.*f", w, pr, v);
  else
    zr__strbuf_printf(sb, "%*.*f", w, pr, v);
}

static const char *take(zr_sdl_parser *p, zr_strbuf *sb) {
  const char *r = sb->failed ? NULL
                             : zr__sdl_strdup(p, zr__strbuf_cstr(sb), sb->len);
  if (sb->failed)
    zr__sdl_error(p, ZR_ENOMEM, NULL, "out of memory");
  zr__strbuf_free(sb);
  return r;
}

const char *zr__sdl_str(zr_sdl_parser *p, double v, double width,
                        double prec, const zr_sdl_loc *loc) {
  (void)loc;
  zr_strbuf sb;
  zr__strbuf_init(&sb);
  format_float(&sb, v, width, prec);
  return take(p, &sb);
}

const char *zr__sdl_vstr(zr_sdl_parser *p, double n, const zr_sdl_expr *v,
                         const char *sep, double width, double prec,
                         const zr_sdl_loc *loc) {
  (void)loc;
  /* povray 3.7 writes the first n components of a longer vector or a
     colour: vstr(2, <1,2,3>, ...) is "1,2" (measured; tiling.pov writes
     vstr(3, Colour, ...)). */
  int dims = n < 2 ? 2 : n > 5 ? 5 : (int)n;
  zr_strbuf sb;
  zr__strbuf_init(&sb);
  for (int i = 0; i < dims; i++) {
    double c = v->dim == 1 ? v->v[0] : i < v->dim ? v->v[i] : 0.0;
    if (i > 0)
      zr__strbuf_puts(&sb, sep);
    format_float(&sb, c, width, prec);
  }
  return take(p, &sb);
}

const char *zr__sdl_substr(zr_sdl_parser *p, const char *s, double start,
                           double len, const zr_sdl_loc *loc) {
  size_t n = strlen(s);
  if (start < 1 || len < 0 || start + len - 1 > (double)n) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "substr: position %g and length %g are outside the "
                  "string of %zu characters",
                  start, len, n);
    return NULL;
  }
  return zr__sdl_strdup(p, s + (size_t)start - 1, (size_t)len);
}

const char *zr__sdl_chr(zr_sdl_parser *p, double code,
                        const zr_sdl_loc *loc) {
  if (!(code >= 1 && code <= 255)) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "chr: %g is not a character code from 1 to 255", code);
    return NULL;
  }
  char c = (char)(unsigned char)code;
  return zr__sdl_strdup(p, &c, 1);
}

const char *zr__sdl_strcase(zr_sdl_parser *p, const char *s, bool upper) {
  size_t n = strlen(s);
  char *r = zr__sdl_alloc(p, n + 1);
  if (!r)
    return NULL;
  for (size_t i = 0; i <= n; i++)
    r[i] = (char)(upper ? toupper((unsigned char)s[i])
                        : tolower((unsigned char)s[i]));
  return r;
}

bool zr__sdl_string_float(zr_sdl_parser *p, int func, const char *s,
                          const zr_sdl_loc *loc, zr_sdl_expr *out) {
  (void)loc;
  switch (func) {
  case T_ASC:
    *out = zr__sdl_float((unsigned char)s[0]);
    return true;
  case T_STRLEN:
    *out = zr__sdl_float((double)strlen(s));
    return true;
  case T_VAL:
    *out = zr__sdl_float(strtod(s, NULL));
    return true;
  default:
    *out = zr__sdl_float(zr__sdl_file_exists(p, s) ? 1 : 0);
    return true;
  }
}

/* ---- random streams ---- */

const zr_sdl_rand *zr__sdl_seed(zr_sdl_parser *p, double n) {
  zr_sdl_rand *r = zr__sdl_alloc(p, sizeof *r);
  if (!r)
    return NULL;
  r->state = zr__sdl_seed_state(n);
  if (p->n_seeds == p->cap_seeds) {
    /* The arena keeps the old table until the scene is freed: at most
       as much again as the last one. */
    size_t cap = p->cap_seeds ? 2 * p->cap_seeds : 16;
    zr_sdl_rand **t = zr__sdl_alloc(p, cap * sizeof *t);
    if (!t)
      return NULL;
    if (p->n_seeds)
      memcpy(t, p->seeds, p->n_seeds * sizeof *t);
    p->seeds = t;
    p->cap_seeds = cap;
  }
  p->seeds[p->n_seeds++] = r;
  return r;
}

const zr_sdl_rand *zr__sdl_seed_numbered(zr_sdl_parser *p, double n,
                                         const zr_sdl_loc *loc) {
  /* Measured: with seeds 0 and 1 made, rand(1) is the second stream and
     rand(2.7) before any seed() is refused with this message. */
  if (!(n >= 0.0 && n < (double)p->n_seeds)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "Illegal random number generator.");
    return NULL;
  }
  return p->seeds[(size_t)n];
}

unsigned long long zr__sdl_seed_state(double n) {
  /* Measured (bench/noise/probe_rand.sh): -12.7 starts as -12, and any
     number outside the signed 32-bit range (or not a number) as -2^31. */
  long long s = n > -2147483649.0 && n < 2147483648.0 ? (long long)n
                                                       : -2147483648LL;
  return (unsigned long long)s & 0xFFFFFFFFull;
}

double zr__sdl_rand_step(unsigned long long *state) {
  /* Multiplier, increment and divisor derived from POV-Ray's output by
     bench/noise/probe_rand.sh. */
  *state = (*state * 1812433253ull + 12345ull) & 0xFFFFFFFFull;
  return (double)*state / 4294967295.0;
}

double zr__sdl_rand(const zr_sdl_rand *stream) {
  /* The stream belongs to the identifier's value, which is the one
     thing a rand() call is meant to change. */
  zr_sdl_rand *r = (zr_sdl_rand *)stream;
  return zr__sdl_rand_step(&r->state);
}

/* ---- arrays ---- */

static size_t page_count(size_t n) {
  return (n + ZR_SDL_ARRAY_PAGE - 1) / ZR_SDL_ARRAY_PAGE;
}

static zr_sdl_array *array_alloc(zr_sdl_parser *p, int n_dims,
                                 const int *dims, size_t n) {
  zr_sdl_array *a = zr__sdl_alloc(p, sizeof *a);
  if (!a)
    return NULL;
  a->n_dims = n_dims;
  memcpy(a->dims, dims, (size_t)n_dims * sizeof *dims);
  a->n = n;
  /* Zeroed by the arena: no page yet. */
  a->pages = zr__sdl_alloc(p, page_count(n) * sizeof *a->pages);
  return a->pages ? a : NULL;
}

/* The elements page k of an array of n holds. */
static size_t page_room(size_t n, size_t k) {
  size_t left = n - k * ZR_SDL_ARRAY_PAGE;
  return left < ZR_SDL_ARRAY_PAGE ? left : ZR_SDL_ARRAY_PAGE;
}

/* The bytes of a page block: the page, its values, its set flags. */
static size_t page_bytes(size_t room) {
  size_t head = (sizeof(zr_sdl_array_page) + sizeof(max_align_t) - 1) /
                sizeof(max_align_t) * sizeof(max_align_t);
  return head + room * (sizeof(struct zr_sdl_value) + sizeof(bool));
}

/* A new page of room elements, none set (the arena zeroes it). */
static zr_sdl_array_page *page_alloc(zr_sdl_parser *p, size_t room) {
  zr_sdl_array_page *pg = zr__sdl_alloc(p, page_bytes(room));
  if (!pg)
    return NULL;
  size_t head = page_bytes(0);
  pg->elems = (struct zr_sdl_value *)((char *)pg + head);
  pg->set = (bool *)(pg->elems + room);
  return pg;
}

/* The page holding element i, made when missing. */
static zr_sdl_array_page *page_for(zr_sdl_parser *p, zr_sdl_array *a,
                                   size_t i) {
  size_t k = i / ZR_SDL_ARRAY_PAGE;
  zr_sdl_array_page **slot = &a->pages[k];
  if (!*slot)
    *slot = page_alloc(p, page_room(a->n, k));
  return *slot;
}

zr_sdl_array *zr__sdl_array_new(zr_sdl_parser *p, const zr_sdl_list *dims,
                                const zr_sdl_loc *loc) {
  if (dims->n > ZR_SDL_MAX_DIMS) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "an array has at most %d dimensions",
                  ZR_SDL_MAX_DIMS);
    return NULL;
  }
  int d[ZR_SDL_MAX_DIMS];
  double n = 1;
  for (int i = 0; i < dims->n; i++) {
    if (!(dims->v[i] >= 1) || dims->v[i] > MAX_ARRAY_ELEMENTS) {
      zr__sdl_error(p, ZR_ESCENE, loc, "an array dimension must be from 1 "
                    "to %u, not %g", MAX_ARRAY_ELEMENTS, dims->v[i]);
      return NULL;
    }
    d[i] = (int)dims->v[i];
    n *= d[i];
  }
  if (n > MAX_ARRAY_ELEMENTS) {
    zr__sdl_error(p, ZR_ELIMIT, loc, "an array of more than %u elements",
                  MAX_ARRAY_ELEMENTS);
    return NULL;
  }
  return array_alloc(p, dims->n, d, (size_t)n);
}

bool zr__sdl_init_add(zr_sdl_parser *p, const zr_sdl_value *v,
                      const zr_sdl_loc *loc) {
  if (p->n_init == p->cap_init) {
    size_t cap = p->cap_init ? p->cap_init * 2 : 64;
    zr_sdl_value *init = realloc(p->init, cap * sizeof *init);
    if (!init) {
      zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
      return false;
    }
    p->init = init;
    p->cap_init = cap;
  }
  p->init[p->n_init++] = *v;
  return true;
}

bool zr__sdl_array_init(zr_sdl_parser *p, zr_sdl_array *a, size_t start,
                        const zr_sdl_loc *loc) {
  size_t count = p->n_init - start;
  if (count != a->n) {
    zr__sdl_error(p, ZR_ESCENE, loc, "the array has %zu elements but its "
                  "initialiser gives %zu", a->n, count);
    return false;
  }
  for (size_t i = 0; i < count; i++) {
    zr_sdl_array_page *pg = page_for(p, a, i);
    if (!pg)
      return false;
    pg->elems[i % ZR_SDL_ARRAY_PAGE] = p->init[start + i];
    pg->set[i % ZR_SDL_ARRAY_PAGE] = true;
  }
  p->n_init = start;
  return true;
}

zr_sdl_array *zr__sdl_array_copy(zr_sdl_parser *p, const zr_sdl_array *a) {
  zr_sdl_array *c = array_alloc(p, a->n_dims, a->dims, a->n);
  if (!c)
    return NULL;
  for (size_t k = 0; k < page_count(a->n); k++) {
    if (!a->pages[k])
      continue;
    size_t room = page_room(a->n, k);
    c->pages[k] = page_alloc(p, room);
    if (!c->pages[k])
      return NULL;
    memcpy(c->pages[k]->elems, a->pages[k]->elems,
           room * sizeof *a->pages[k]->elems);
    memcpy(c->pages[k]->set, a->pages[k]->set,
           room * sizeof *a->pages[k]->set);
  }
  return c;
}

bool zr__sdl_dimension_size(zr_sdl_parser *p, const zr_sdl_array *a,
                            double dim, const zr_sdl_loc *loc,
                            zr_sdl_expr *out) {
  if (!(dim >= 1 && dim <= a->n_dims)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "dimension_size: the array has no "
                  "dimension %g (it has %d)", dim, a->n_dims);
    return false;
  }
  *out = zr__sdl_float(a->dims[(int)dim - 1]);
  return true;
}

/* The offset of the element at the indices, or false after an error. */
static bool element_offset(zr_sdl_parser *p, const char *name,
                           const zr_sdl_array *a, const int *index, int n,
                           const zr_sdl_loc *loc, size_t *out) {
  if (n != a->n_dims) {
    zr__sdl_error(p, ZR_ESYNTAX, loc, "'%s' has %d dimension%s, not %d",
                  name, a->n_dims, a->n_dims == 1 ? "" : "s", n);
    return false;
  }
  size_t offset = 0;
  for (int i = 0; i < n; i++) {
    if (index[i] < 0 || index[i] >= a->dims[i]) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "index %d of '%s' is out of range 0 to %d", index[i],
                    name, a->dims[i] - 1);
      return false;
    }
    offset = offset * (size_t)a->dims[i] + (size_t)index[i];
  }
  *out = offset;
  return true;
}

zr_sdl_value *zr__sdl_array_at(zr_sdl_parser *p, const char *name,
                               zr_sdl_array *a, const int *index, int n,
                               const zr_sdl_loc *loc) {
  size_t i;
  if (!element_offset(p, name, a, index, n, loc, &i))
    return NULL;
  zr_sdl_array_page *pg = page_for(p, a, i);
  if (!pg)
    return NULL;
  pg->set[i % ZR_SDL_ARRAY_PAGE] = true;
  return &pg->elems[i % ZR_SDL_ARRAY_PAGE];
}

const zr_sdl_value *zr__sdl_array_get(zr_sdl_parser *p, const char *name,
                                      const zr_sdl_array *a,
                                      const int *index, int n,
                                      const zr_sdl_loc *loc, bool *set) {
  static const zr_sdl_value unset;
  size_t i;
  if (!element_offset(p, name, a, index, n, loc, &i))
    return NULL;
  const zr_sdl_array_page *pg = a->pages[i / ZR_SDL_ARRAY_PAGE];
  *set = pg && pg->set[i % ZR_SDL_ARRAY_PAGE];
  return *set ? &pg->elems[i % ZR_SDL_ARRAY_PAGE] : &unset;
}
