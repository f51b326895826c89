/*
 * build_surface.c - the grammar's actions for bicubic_patch,
 * sphere_sweep and julia_fractal (POV-Ray 3.7 reference, "Bicubic
 * Patch", "Sphere Sweep", "Julia Fractal").
 *
 * A bicubic_patch becomes a smooth triangle mesh (lib/trace/obj_mesh.c),
 * cut up as the manual's "Bicubic Patch" describes: at most
 * 2^u_steps * 2^v_steps pieces (u_steps 3 v_steps 3 "translates to 64
 * sub-patches (128 smooth triangles)"), each two triangles, and with a
 * flatness above 0 a piece that is already "flat enough to just
 * pretend it is a rectangle" is not split further.  We halve the 4 x 4
 * Bezier control net by de Casteljau's construction, each time in the
 * direction with more halvings to go (u on a tie), so the pieces stay
 * as square as the counts allow; a piece is flat enough when its
 * control points lie within flatness / 20 of the patch's size of
 * the plane of its corners (flat_enough, patch_tolerance).  Each piece
 * is cut along its diagonal from (u0, v0) to (u1, v1), as POV-Ray's
 * renders show (see piece), and the triangles' corner normals are the
 * patch's exact normals there, so the mesh shades smoothly
 * ("automatically smoothed using normal interpolation").  Types 0 and
 * 1 differ only in memory and speed in the manual; both give this
 * mesh.  Control point i, j (row i of four in the order written) weighs
 * B_i(u) B_j(v); uv_vectors' corners 1 to 4 belong to control points
 * 1, 4, 16 and 13, so the default <0,0>, <1,0>, <1,1>, <0,1> runs the
 * texture's u along the rows (as POV-Ray 3.7 renders a uv_mapping
 * gradient on a flat patch).  What
 * POV-Ray accepts was measured with it: the items before the points
 * (flatness after them is "No matching } in 'bicubic_patch'"), type
 * -0.999 to 1.999 without a word, -1 refused, 2 and up read as 1 with
 * a warning.
 *
 * The sphere sweep and julia fractal are checked here and traced by
 * lib/trace/obj_sweep.c and obj_julia.c.
 */
#include "config.h"

#include "sdl/build_surface.h"

#include <math.h>
#include <string.h>

#include "pov-parse.h"
#include "trace/obj_mesh.h"
#include "trace/obj_sweep.h"

/* ---- bicubic_patch ---- */

/* More subdivisions than this in either direction would make millions
   of triangles from one patch (the manual advises under 4). */
#define MAX_PATCH_STEPS 10

typedef struct patch_build {
  struct zr_mesh mesh; /* first: the object's mesh pointer leads here */
  zr_vec3 points[16];
  int n_points;
  bool have_type;
  double flatness;
  int u_steps, v_steps;
  double uv[4][2];
} patch_build;

static patch_build *patch_of(zr_object *o) {
  return (patch_build *)(void *)o->u.mesh.data;
}

zr_object *zr__sdl_patch_new(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_MESH, loc);
  patch_build *b = o ? zr__sdl_alloc(p, sizeof *b) : NULL;
  if (!b)
    return NULL;
  static const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  memcpy(b->uv, corners, sizeof corners);
  o->u.mesh.data = &b->mesh;
  return o;
}

static bool want_steps(zr_sdl_parser *p, const zr_sdl_expr *e,
                       const zr_sdl_loc *loc, const char *what, int *out) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  if (!(v >= 0.0 && v < MAX_PATCH_STEPS + 1.0)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "%s must be from 0 to %d, not %g",
                  what, MAX_PATCH_STEPS, v);
    return false;
  }
  *out = (int)v;
  return true;
}

/* POV-Ray 3.7 reads the patch's items, then its points (measured). */
static bool items_first(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr__sdl_error(p, ZR_ESYNTAX, loc, "a bicubic_patch's type, flatness, "
                "u_steps, v_steps and uv_vectors come before its points");
  return false;
}

bool zr__sdl_patch_item(zr_sdl_parser *p, zr_object *o,
                        zr_sdl_patch_item item, const zr_sdl_expr *e,
                        const zr_sdl_loc *loc) {
  patch_build *b = patch_of(o);
  double v;
  if (b->n_points > 0)
    return items_first(p, loc);
  switch (item) {
  case ZR_SDL_PATCH_TYPE:
    if (!zr__sdl_want_float(p, e, loc, &v))
      return false;
    /* As measured with POV-Ray 3.7: -0.999 to 1.999 pass, -1 is
       refused, 2 and up give this warning. */
    if (!(v > -1.0)) {
      zr__sdl_error(p, ZR_ESCENE, loc, "Undefined bicubic patch type %g "
                    "(type 0 or 1)", v);
      return false;
    }
    if (v >= 2.0)
      zr__sdl_warning(p, loc, "Patch type no longer supported. Using "
                      "type 1.");
    b->have_type = true;
    return true;
  case ZR_SDL_PATCH_FLATNESS:
    if (!zr__sdl_want_float(p, e, loc, &b->flatness))
      return false;
    return true;
  case ZR_SDL_PATCH_U_STEPS:
    return want_steps(p, e, loc, "u_steps", &b->u_steps);
  case ZR_SDL_PATCH_V_STEPS:
    return want_steps(p, e, loc, "v_steps", &b->v_steps);
  }
  return true;
}

bool zr__sdl_patch_point(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  patch_build *b = patch_of(o);
  if (b->n_points == 16) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "a bicubic_patch has 16 control points, not more");
    return false;
  }
  return zr__sdl_want_vector(p, e, loc, &b->points[b->n_points++]);
}

bool zr__sdl_patch_uv(zr_sdl_parser *p, zr_object *o,
                      const zr_sdl_expr e[4], const zr_sdl_loc at[4]) {
  patch_build *b = patch_of(o);
  if (b->n_points > 0)
    return items_first(p, &at[0]);
  for (int k = 0; k < 4; k++) {
    if (e[k].dim > 3) {
      zr__sdl_error(p, ZR_ESCENE, &at[k], "uv_vectors takes 2-D vectors");
      return false;
    }
    zr_vec3 v;
    if (!zr__sdl_want_vector(p, &e[k], &at[k], &v))
      return false;
    b->uv[k][0] = v.x;
    b->uv[k][1] = v.y;
  }
  return true;
}

typedef zr_vec3 net[4][4];

/* The point of the patch at (u, v) and its tangents along u and v. */
static void patch_eval(const net cp, double u, double v, zr_vec3 *point,
                       zr_vec3 *tu, zr_vec3 *tv) {
  double bu[4] = {(1 - u) * (1 - u) * (1 - u), 3 * u * (1 - u) * (1 - u),
                  3 * u * u * (1 - u), u * u * u};
  double bv[4] = {(1 - v) * (1 - v) * (1 - v), 3 * v * (1 - v) * (1 - v),
                  3 * v * v * (1 - v), v * v * v};
  double du[4] = {-3 * (1 - u) * (1 - u), 3 * (1 - u) * (1 - 3 * u),
                  3 * u * (2 - 3 * u), 3 * u * u};
  double dv[4] = {-3 * (1 - v) * (1 - v), 3 * (1 - v) * (1 - 3 * v),
                  3 * v * (2 - 3 * v), 3 * v * v};
  zr_vec3 pt = zr_v3(0, 0, 0), a = pt, b = pt;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) {
      pt = zr_v3_madd(pt, cp[i][j], bu[i] * bv[j]);
      a = zr_v3_madd(a, cp[i][j], du[i] * bv[j]);
      b = zr_v3_madd(b, cp[i][j], bu[i] * dv[j]);
    }
  *point = pt;
  *tu = a;
  *tv = b;
}

/* The unit normal from two tangents; false when they are parallel or
   one vanishes. */
static bool unit_normal(zr_vec3 tu, zr_vec3 tv, zr_vec3 *normal) {
  zr_vec3 n = zr_v3_cross(tu, tv);
  double nn = zr_v3_dot(n, n);
  if (!(nn > 1e-10 * zr_v3_dot(tu, tu) * zr_v3_dot(tv, tv)) ||
      !isfinite(nn))
    return false;
  *normal = zr_v3_scale(n, 1.0 / sqrt(nn));
  return true;
}

/* The point and unit normal of the patch at (u, v).  Where the normal
   vanishes (a corner whose edge collapses to a point, or a cusp) it is
   <1, 0, 0>: that is what POV-Ray 3.7 shades there, measured on a patch
   whose first row is one point (its tip is dark under a light from the
   upper left and bright under one from +x, and our renders with
   <1, 0, 0> equal POV-Ray's, SSIM 1.0000 both, where the limit normal
   from inside the patch gives 0.967). */
static void patch_value(const net cp, double u, double v, zr_vec3 *point,
                        zr_vec3 *normal) {
  zr_vec3 tu, tv;
  patch_eval(cp, u, v, point, &tu, &tv);
  if (!unit_normal(tu, tv, normal))
    *normal = zr_v3(1, 0, 0);
}

/* de Casteljau halving of four points. */
static void halve(const zr_vec3 a[4], zr_vec3 lo[4], zr_vec3 hi[4]) {
  zr_vec3 ab = zr_v3_scale(zr_v3_add(a[0], a[1]), 0.5);
  zr_vec3 bc = zr_v3_scale(zr_v3_add(a[1], a[2]), 0.5);
  zr_vec3 cd = zr_v3_scale(zr_v3_add(a[2], a[3]), 0.5);
  zr_vec3 abc = zr_v3_scale(zr_v3_add(ab, bc), 0.5);
  zr_vec3 bcd = zr_v3_scale(zr_v3_add(bc, cd), 0.5);
  zr_vec3 mid = zr_v3_scale(zr_v3_add(abc, bcd), 0.5);
  zr_vec3 l[4] = {a[0], ab, abc, mid}, h[4] = {mid, bcd, cd, a[3]};
  memcpy(lo, l, sizeof l);
  memcpy(hi, h, sizeof h);
}

/* The net split at u = 1/2 (first index) into lo and hi. */
static void split_u_net(const net n, net lo, net hi) {
  for (int j = 0; j < 4; j++) {
    zr_vec3 col[4] = {n[0][j], n[1][j], n[2][j], n[3][j]}, l[4], h[4];
    halve(col, l, h);
    for (int i = 0; i < 4; i++) {
      lo[i][j] = l[i];
      hi[i][j] = h[i];
    }
  }
}

/* The net split at v = 1/2 (second index). */
static void split_v_net(const net n, net lo, net hi) {
  for (int i = 0; i < 4; i++)
    halve(n[i], lo[i], hi[i]);
}

/*
 * Whether the piece of control net n is flat enough to be two
 * triangles: every control point within tolerance of the plane through
 * the centre of its four corners square to its diagonals (by the convex
 * hull property the surface piece then lies as near it).  A piece whose
 * diagonals give no plane is not.  The caller makes the tolerance
 * flatness / 20 of the whole patch's size (patch_tolerance).
 */
static bool flat_enough(const net n, double tolerance) {
  if (!(tolerance > 0.0))
    return false;
  zr_vec3 d1 = zr_v3_sub(n[3][3], n[0][0]), d2 = zr_v3_sub(n[3][0], n[0][3]);
  zr_vec3 nrm;
  if (!unit_normal(d1, d2, &nrm))
    return false;
  zr_vec3 centre = zr_v3_scale(zr_v3_add(zr_v3_add(n[0][0], n[0][3]),
                                         zr_v3_add(n[3][0], n[3][3])),
                               0.25);
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      if (!(fabs(zr_v3_dot(zr_v3_sub(n[i][j], centre), nrm)) < tolerance))
        return false;
  return true;
}

/*
 * How far a piece may stray from flat: flatness / 20 of the patch's
 * size, the diagonal of its control points' box.  The manual says only
 * that a smaller flatness subdivides more.  Relative, because POV-Ray
 * 3.7's flatness is: scaling the manual's patch by 10 leaves the
 * picture each flatness gives unchanged.  The scale 1/20 is measured:
 * on two views of the manual's patch, flatness 0.3, 0.1, 0.03 and 0.01
 * render nearest to uniform u_steps = v_steps of 3, 3, 4, 5 and 2, 3,
 * 4, 5 in povray, and so they do here with 1/20 (with 1/100 here they
 * were 4, 5, 5, 6 and 3, 4, 5, 6): bench/provenance/probe.py
 * patch_flatness.
 */
static double patch_tolerance(const patch_build *b) {
  zr_vec3 lo = b->points[0], hi = b->points[0];
  for (int k = 1; k < 16; k++) {
    zr_vec3 q = b->points[k];
    lo = zr_v3(fmin(lo.x, q.x), fmin(lo.y, q.y), fmin(lo.z, q.z));
    hi = zr_v3(fmax(hi.x, q.x), fmax(hi.y, q.y), fmax(hi.z, q.z));
  }
  return b->flatness / 20.0 * zr_v3_len(zr_v3_sub(hi, lo));
}

/* Where the pieces go: counted first (mesh NULL), then stored. */
typedef struct patch_sink {
  const patch_build *b;
  double tolerance; /* patch_tolerance */
  struct zr_mesh *mesh;
  size_t n_pieces;
} patch_sink;

static void add_corner(patch_sink *s, double u, double v) {
  struct zr_mesh *m = s->mesh;
  const double(*uv)[2] = s->b->uv;
  size_t k = m->n_vertices++;
  patch_value((const zr_vec3(*)[4])s->b->points, u, v, &m->vertices[k],
              &m->normals[k]);
  m->n_normals++;
  /* The uv_vectors corners sit at control points 1 (u = v = 0), 4
     (v = 1), 16 and 13 (u = 1): bilinear in (v, u). */
  double x = v, y = u;
  for (int c = 0; c < 2; c++)
    m->uvs[k][c] = (1 - x) * (1 - y) * uv[0][c] + x * (1 - y) * uv[1][c] +
                   x * y * uv[2][c] + (1 - x) * y * uv[3][c];
  m->n_uvs++;
}

static bool degenerate(const struct zr_mesh *m, uint32_t a, uint32_t b,
                       uint32_t c) {
  zr_vec3 e1 = zr_v3_sub(m->vertices[b], m->vertices[a]);
  zr_vec3 e2 = zr_v3_sub(m->vertices[c], m->vertices[a]);
  double n = zr_v3_dot(zr_v3_cross(e1, e2), zr_v3_cross(e1, e2));
  return !(n > 1e-10 * zr_v3_dot(e1, e1) * zr_v3_dot(e2, e2));
}

static void add_face(struct zr_mesh *m, uint32_t a, uint32_t b,
                     uint32_t c) {
  if (degenerate(m, a, b, c))
    return;
  uint32_t *f = m->faces[m->n_faces];
  f[0] = a;
  f[1] = b;
  f[2] = c;
  memcpy(m->face_normals[m->n_faces], f, sizeof m->faces[0]);
  memcpy(m->face_uvs[m->n_faces], f, sizeof m->faces[0]);
  m->n_faces++;
}

/* A piece of the patch: its four corners and two triangles, cut along
   the diagonal from (u0, v0) to (u1, v1).  The manual leaves the cut
   open; this one is POV-Ray 3.7's, measured: with flatness 0 our
   renders of the manual's patch at u_steps = v_steps = 2, 3 and 4 are
   then identical to POV-Ray's (SSIM 1.0000), where the other diagonal,
   or the shorter of the two, gives 0.974 at 2. */
static void piece(patch_sink *s, double u0, double u1, double v0,
                  double v1) {
  s->n_pieces++;
  struct zr_mesh *m = s->mesh;
  if (!m)
    return;
  uint32_t k = (uint32_t)m->n_vertices;
  add_corner(s, u0, v0);
  add_corner(s, u0, v1);
  add_corner(s, u1, v1);
  add_corner(s, u1, v0);
  add_face(m, k, k + 1, k + 2);
  add_face(m, k, k + 2, k + 3);
}

/* Cuts the piece [u0, u1] x [v0, v1], whose control net is n and which
   has been halved split_u times in u and split_v times in v. */
static void subdivide(patch_sink *s, const net n, double u0, double u1,
                      double v0, double v1, int split_u, int split_v) {
  const patch_build *b = s->b;
  int left_u = b->u_steps - split_u, left_v = b->v_steps - split_v;
  if ((left_u <= 0 && left_v <= 0) || flat_enough(n, s->tolerance)) {
    piece(s, u0, u1, v0, v1);
    return;
  }
  net lo, hi;
  if (left_u >= left_v) {
    double um = 0.5 * (u0 + u1);
    split_u_net(n, lo, hi);
    subdivide(s, (const zr_vec3(*)[4])lo, u0, um, v0, v1, split_u + 1,
              split_v);
    subdivide(s, (const zr_vec3(*)[4])hi, um, u1, v0, v1, split_u + 1,
              split_v);
  } else {
    double vm = 0.5 * (v0 + v1);
    split_v_net(n, lo, hi);
    subdivide(s, (const zr_vec3(*)[4])lo, u0, u1, v0, vm, split_u,
              split_v + 1);
    subdivide(s, (const zr_vec3(*)[4])hi, u0, u1, vm, v1, split_u,
              split_v + 1);
  }
}

bool zr__sdl_patch_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc) {
  patch_build *b = patch_of(o);
  if (!b->have_type) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "the bicubic_patch has no type (type 0 or type 1)");
    return false;
  }
  if (b->n_points != 16) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "a bicubic_patch needs 16 control points, not %d",
                  b->n_points);
    return false;
  }
  const zr_vec3(*cp)[4] = (const zr_vec3(*)[4])b->points;
  patch_sink s = {b, patch_tolerance(b), NULL, 0};
  subdivide(&s, cp, 0.0, 1.0, 0.0, 1.0, 0, 0);
  struct zr_mesh *m = &b->mesh;
  size_t nv = 4 * s.n_pieces, nf = 2 * s.n_pieces;
  m->vertices = zr__sdl_alloc(p, nv * sizeof *m->vertices);
  m->normals = zr__sdl_alloc(p, nv * sizeof *m->normals);
  m->uvs = zr__sdl_alloc(p, nv * sizeof *m->uvs);
  m->faces = zr__sdl_alloc(p, nf * sizeof *m->faces);
  m->face_normals = zr__sdl_alloc(p, nf * sizeof *m->faces);
  m->face_uvs = zr__sdl_alloc(p, nf * sizeof *m->faces);
  if (!m->vertices || !m->normals || !m->uvs || !m->faces ||
      !m->face_normals || !m->face_uvs)
    return false;
  m->cap_vertices = m->cap_normals = m->cap_uvs = nv;
  m->cap_faces = nf;
  s.mesh = m;
  s.n_pieces = 0;
  subdivide(&s, cp, 0.0, 1.0, 0.0, 1.0, 0, 0);
  if (m->n_faces == 0) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "the bicubic_patch's control points make no surface");
    return false;
  }
  size_t bad = 0;
  zr_status st = zr__mesh_build(m, &p->scene->arena, 1, &bad);
  if (st != ZR_OK) {
    zr__sdl_error(p, st, loc, "cannot build the bicubic_patch: %s",
                  zr_status_str(st));
    return false;
  }
  return true;
}

/* ---- sphere_sweep ---- */

/* More spheres than this are surely a mistake. */
#define MAX_SWEEP_SPHERES 10000000

static struct zr_sphere_sweep *sweep_of(zr_object *o) {
  return (struct zr_sphere_sweep *)(void *)o->u.sweep.data;
}

static const char *const spline_names[] = {"linear_spline", "b_spline",
                                           "cubic_spline"};

zr_object *zr__sdl_sweep_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                             int spline, const zr_sdl_expr *count,
                             const zr_sdl_loc *count_loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_SPHERE_SWEEP, loc);
  struct zr_sphere_sweep *s = o ? zr__sdl_alloc(p, sizeof *s) : NULL;
  double n;
  if (!s || !zr__sdl_want_float(p, count, count_loc, &n))
    return NULL;
  s->spline = (zr_sweep_spline)spline;
  s->tolerance = 1e-6;
  size_t least = spline == ZR_SWEEP_LINEAR ? 2 : 4;
  if (!(n >= (double)least && n <= MAX_SWEEP_SPHERES)) {
    zr__sdl_error(p, ZR_ESCENE, count_loc,
                  "a %s sphere_sweep needs at least %zu spheres, not %g",
                  spline_names[spline], least, n);
    return NULL;
  }
  s->n_expected = (size_t)n;
  s->centres = zr__sdl_alloc(p, s->n_expected * sizeof *s->centres);
  s->radii = zr__sdl_alloc(p, s->n_expected * sizeof *s->radii);
  if (!s->centres || !s->radii)
    return NULL;
  o->u.sweep.data = s;
  return o;
}

/* Items alternate: a centre, then its radius. */
bool zr__sdl_sweep_item(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  struct zr_sphere_sweep *s = sweep_of(o);
  size_t k = s->n_spheres;
  if (!s->centre_pending) {
    if (k == s->n_expected) {
      zr__sdl_error(p, ZR_ESCENE, loc, "the sphere_sweep has more spheres "
                    "than the %zu it announced", s->n_expected);
      return false;
    }
    if (!zr__sdl_want_vector(p, e, loc, &s->centres[k]))
      return false;
    s->centre_pending = true;
    return true;
  }
  if (!zr__sdl_want_float(p, e, loc, &s->radii[k]))
    return false;
  s->centre_pending = false;
  s->n_spheres++;
  return true;
}

bool zr__sdl_sweep_tolerance(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  struct zr_sphere_sweep *s = sweep_of(o);
  return zr__sdl_want_float(p, e, loc, &s->tolerance);
}

bool zr__sdl_sweep_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc) {
  struct zr_sphere_sweep *s = sweep_of(o);
  if (s->n_spheres < s->n_expected) {
    zr__sdl_error(p, ZR_ESCENE, loc, "the sphere_sweep has only %zu of "
                  "the %zu spheres it announced%s", s->n_spheres,
                  s->n_expected,
                  s->centre_pending ? " (the last has no radius)" : "");
    return false;
  }
  size_t n_seg = s->spline == ZR_SWEEP_LINEAR ? s->n_spheres - 1
                                              : s->n_spheres - 3;
  s->segments = zr__sdl_alloc(p, n_seg * sizeof *s->segments);
  if (!s->segments)
    return false;
  zr__sweep_build(s);
  return true;
}

/* ---- julia_fractal ---- */

/* A julia_fractal while it is read: the fractal first, so the object's
   pointer to it leads back here. */
typedef struct julia_build {
  struct zr_julia julia;
  zr_sdl_loc function_loc;
} julia_build;

static struct zr_julia *julia_of(zr_object *o) {
  return (struct zr_julia *)(void *)o->u.julia.data;
}

static julia_build *julia_build_of(zr_object *o) {
  return (julia_build *)(void *)o->u.julia.data;
}

/* A 4-D value: a float fills every component, shorter vectors get
   zeros. */
static bool want_4d(zr_sdl_parser *p, const zr_sdl_expr *e,
                    const zr_sdl_loc *loc, double out[4]) {
  if (e->dim > 4) {
    zr__sdl_error(p, ZR_ESCENE, loc, "expected a 4-D vector, not a colour");
    return false;
  }
  for (int k = 0; k < 4; k++)
    out[k] = e->dim == 1 ? e->v[0] : k < e->dim ? e->v[k] : 0.0;
  return true;
}

zr_object *zr__sdl_julia_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                             const zr_sdl_expr *param,
                             const zr_sdl_loc *param_loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_JULIA, loc);
  julia_build *b = o ? zr__sdl_alloc(p, sizeof *b) : NULL;
  struct zr_julia *j = b ? &b->julia : NULL;
  if (!j || !want_4d(p, param, param_loc, j->c))
    return NULL;
  j->algebra = ZR_JULIA_QUATERNION;
  j->function = ZR_JULIA_SQR;
  j->max_iteration = 20;
  j->precision = 20.0;
  j->slice[3] = 1.0;
  o->u.julia.data = j;
  return o;
}

void zr__sdl_julia_algebra(zr_object *o, int algebra) {
  julia_of(o)->algebra = (zr_julia_algebra)algebra;
}

bool zr__sdl_julia_function(zr_sdl_parser *p, zr_object *o, int token,
                            const zr_sdl_loc *loc) {
  static const struct {
    int token;
    zr_julia_function function;
  } functions[] = {
      {T_SQR, ZR_JULIA_SQR},     {T_CUBE, ZR_JULIA_CUBE},
      {T_RECIPROCAL, ZR_JULIA_RECIPROCAL},
      {T_EXP, ZR_JULIA_EXP},     {T_LN, ZR_JULIA_LN},
      {T_SIN, ZR_JULIA_SIN},     {T_ASIN, ZR_JULIA_ASIN},
      {T_COS, ZR_JULIA_COS},     {T_ACOS, ZR_JULIA_ACOS},
      {T_TAN, ZR_JULIA_TAN},     {T_ATAN, ZR_JULIA_ATAN},
      {T_SINH, ZR_JULIA_SINH},   {T_ASINH, ZR_JULIA_ASINH},
      {T_COSH, ZR_JULIA_COSH},   {T_ACOSH, ZR_JULIA_ACOSH},
      {T_TANH, ZR_JULIA_TANH},   {T_ATANH, ZR_JULIA_ATANH}};
  struct zr_julia *j = julia_of(o);
  for (size_t i = 0; i < sizeof functions / sizeof functions[0]; i++)
    if (functions[i].token == token) {
      j->function = functions[i].function;
      julia_build_of(o)->function_loc = *loc;
      return true;
    }
  zr__sdl_error(p, ZR_EINVAL, loc, "unknown julia_fractal function");
  return false;
}

bool zr__sdl_julia_pwr(zr_sdl_parser *p, zr_object *o, const zr_sdl_expr *x,
                       const zr_sdl_loc *x_loc, const zr_sdl_expr *y,
                       const zr_sdl_loc *y_loc) {
  struct zr_julia *j = julia_of(o);
  if (!zr__sdl_want_float(p, x, x_loc, &j->exponent[0]) ||
      !zr__sdl_want_float(p, y, y_loc, &j->exponent[1]))
    return false;
  j->function = ZR_JULIA_PWR;
  julia_build_of(o)->function_loc = *x_loc;
  return true;
}

bool zr__sdl_julia_iterations(zr_sdl_parser *p, zr_object *o,
                              const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  if (!(v >= 1.0 && v <= 1e6)) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "max_iteration must be from 1 to 1000000, not %g", v);
    return false;
  }
  julia_of(o)->max_iteration = (int)v;
  return true;
}

bool zr__sdl_julia_precision(zr_sdl_parser *p, zr_object *o,
                             const zr_sdl_expr *e, const zr_sdl_loc *loc) {
  double v;
  if (!zr__sdl_want_float(p, e, loc, &v))
    return false;
  /* The manual: values below 1 are clipped to 1. */
  julia_of(o)->precision = v < 1.0 ? 1.0 : v;
  return true;
}

bool zr__sdl_julia_slice(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *normal,
                         const zr_sdl_loc *normal_loc,
                         const zr_sdl_expr *distance,
                         const zr_sdl_loc *distance_loc) {
  struct zr_julia *j = julia_of(o);
  double n[4];
  if (!want_4d(p, normal, normal_loc, n) ||
      !zr__sdl_want_float(p, distance, distance_loc, &j->distance))
    return false;
  double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3]);
  if (!(len > 0.0) || n[3] == 0.0) {
    zr__sdl_error(p, ZR_ESCENE, normal_loc,
                  "the slice's normal must not be zero, nor its fourth "
                  "component");
    return false;
  }
  /* POV-Ray makes the normal a unit vector (the distance is then
     measured along it). */
  for (int k = 0; k < 4; k++)
    j->slice[k] = n[k] / len;
  return true;
}

bool zr__sdl_julia_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc) {
  struct zr_julia *j = julia_of(o);
  /* POV-Ray's own words; the algebra may come after the function. */
  if (j->algebra == ZR_JULIA_QUATERNION && j->function > ZR_JULIA_CUBE) {
    zr__sdl_error(p, ZR_ESCENE, &julia_build_of(o)->function_loc,
                  "Illegal function: "
                  "quaternion only supports sqr and cube");
    return false;
  }
  if (!zr__julia_prepare(j)) {
    zr__sdl_error(p, ZR_ESCENE, loc, "the julia_fractal's slice is not "
                  "valid");
    return false;
  }
  return true;
}
