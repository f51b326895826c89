/*
 * build_shape.c - the grammar's actions for the torus, polygon,
 * superellipsoid, prism, lathe, blob and sor (POV-Ray 3.7 reference,
 * "Finite Solid Primitives" and "Polygon"); the tracer's side is in
 * lib/trace/obj_*.c.
 *
 * Most of the work is the polygon's.  Its points are kept as they come;
 * when the last one is read they are split into sub-polygons, each
 * closed where its first point comes again, and a last one left open is
 * closed with POV-Ray's own warning ("Polygon not closed. Closing it.").
 * The plane is fitted by Newell's method (the sum of the edges' cross
 * products, which is exact for planar outlines and a good average of
 * nearly planar ones), and every edge is stored in the plane's (u, v)
 * axes so the tracer's inside test is two-dimensional.  The manual says
 * the points must lie in one plane; POV-Ray 3.7 says nothing but draws
 * nothing when one lies more than 1e-10 off the plane of the first
 * three points that span one (measured at half-sizes 0.01 to 100 by
 * bench/conform/polygon_offplane_sweep.py; pictured in
 * tests/legacy/polygon_offplane.pov, forste's ex1/cylinder.pov), and
 * zRcube does the same, with a warning.
 *
 * A prism's points become cubic pieces of curve in the power basis,
 * whatever the spline ("Prism", and "Lathe" for the splines): a linear
 * piece joins two points; a quadratic one is the parabola through the
 * point before it, its start and its end; a cubic one is a Catmull-Rom
 * piece, its end slopes half the chord of the neighbours; a Bezier one
 * takes four points.  The manual describes the quadratic and cubic
 * splines only in words; these forms were measured on POV-Ray's
 * renderings of the manual's examples.  Sub-prisms end where
 * their first curve point comes again, the last linear one is closed
 * like a polygon's; the others must be closed.  A lathe's curve is the
 * same pieces over one open run of points: n - 1 linear pieces, n - 2
 * quadratic ones, n - 3 cubic ones, n / 4 Bezier ones ("Lathe").
 */
#include "sdl/build_shape.h"

#include <math.h>
#include <string.h>

#include "trace/obj_shapes.h"
#include "trace/roots.h"

zr_object *zr__sdl_torus(zr_sdl_parser *p, const zr_sdl_loc *loc,
                         const zr_sdl_expr *major,
                         const zr_sdl_loc *major_loc,
                         const zr_sdl_expr *minor,
                         const zr_sdl_loc *minor_loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_TORUS, loc);
  if (!o || !zr__sdl_want_float(p, major, major_loc, &o->u.torus.major) ||
      !zr__sdl_want_float(p, minor, minor_loc, &o->u.torus.minor))
    return NULL;
  if (!(fabs(o->u.torus.minor) > 0.0)) {
    zr__sdl_error(p, ZR_ESCENE, minor_loc,
                  "the torus's minor radius is zero");
    return NULL;
  }
  return o;
}

/* The smallest exponent kept: below it the powers in the shape's
   equation leave the range of doubles. */
#define MIN_EXPONENT 1e-3

zr_object *zr__sdl_superellipsoid(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                  const zr_sdl_expr *en,
                                  const zr_sdl_loc *en_loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_SUPERELLIPSOID, loc);
  zr_vec3 v;
  if (!o || !zr__sdl_want_vector(p, en, en_loc, &v))
    return NULL;
  if (!(v.x >= MIN_EXPONENT && v.y >= MIN_EXPONENT)) {
    zr__sdl_warning(p, en_loc,
                    "superellipsoid values below %g are taken as %g",
                    MIN_EXPONENT, MIN_EXPONENT);
    v.x = fmax(v.x, MIN_EXPONENT);
    v.y = fmax(v.y, MIN_EXPONENT);
  }
  o->u.superellipsoid.e = v.x;
  o->u.superellipsoid.n = v.y;
  return o;
}

/* More points than this are surely a mistake (and would not fit). */
#define MAX_POLYGON_POINTS 10000000

/*
 * The room for the n points that a polygon, prism, lathe or sor
 * announces (what names it in the message: "a polygon", "this prism"),
 * at least fewest of them; NULL after an error.
 */
static zr_vec3 *point_room(zr_sdl_parser *p, const char *what,
                           double fewest, double n, const zr_sdl_loc *at,
                           size_t *n_expected) {
  if (!(n >= fewest && n <= MAX_POLYGON_POINTS)) {
    zr__sdl_error(p, ZR_ESCENE, at, "%s needs at least %g points, not %g",
                  what, fewest, n);
    return NULL;
  }
  *n_expected = (size_t)n;
  return zr__sdl_alloc(p, (size_t)n * sizeof(zr_vec3));
}

zr_object *zr__sdl_polygon_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                               const zr_sdl_expr *count,
                               const zr_sdl_loc *count_loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_POLYGON, loc);
  double n;
  if (!o || !zr__sdl_want_float(p, count, count_loc, &n))
    return NULL;
  o->u.polygon.points = point_room(p, "a polygon", 3, n, count_loc,
                                   &o->u.polygon.n_expected);
  return o->u.polygon.points ? o : NULL;
}

/*
 * One point of a polygon, prism, lathe or sor, which announce their
 * number of points first: more than announced is an error, and so is a
 * point of the wrong size where the shape wants 2-D ones (want2d names
 * the components in the message; NULL takes any vector).
 */
static bool add_point(zr_sdl_parser *p, const char *shape, zr_vec3 *points,
                      size_t *n_points, size_t n_expected,
                      const char *want2d, const zr_sdl_expr *point,
                      const zr_sdl_loc *point_loc) {
  if (*n_points == n_expected) {
    zr__sdl_error(p, ZR_ESCENE, point_loc,
                  "the %s has more points than the %zu it announced", shape,
                  n_expected);
    return false;
  }
  if (want2d && point->dim != 2) {
    zr__sdl_error(p, ZR_ESCENE, point_loc,
                  "a %s's points are 2-D vectors %s", shape, want2d);
    return false;
  }
  return zr__sdl_want_vector(p, point, point_loc, &points[(*n_points)++]);
}

/* Checks that a shape got the points it announced. */
static bool all_points(zr_sdl_parser *p, const char *shape, size_t n,
                       size_t n_expected, const zr_sdl_loc *loc) {
  if (n >= n_expected)
    return true;
  zr__sdl_error(p, ZR_ESCENE, loc,
                "the %s has %zu points, not the %zu it announced", shape, n,
                n_expected);
  return false;
}

bool zr__sdl_polygon_point(zr_sdl_parser *p, zr_object *o,
                           const zr_sdl_expr *point,
                           const zr_sdl_loc *point_loc) {
  return add_point(p, "polygon", o->u.polygon.points, &o->u.polygon.n_points,
                   o->u.polygon.n_expected, NULL, point, point_loc);
}

static bool same_point(zr_vec3 a, zr_vec3 b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* Calls edge(a, b) for every edge of the polygon's outlines: a
   sub-polygon runs from its first point to where that point comes
   again, and one left open at the end gets the edge back to its first
   point.  Returns false when that happened. */
typedef void edge_fn(void *data, zr_vec3 a, zr_vec3 b);

static bool each_edge(const zr_vec3 *pt, size_t n, edge_fn *edge,
                      void *data) {
  bool closed_all = true;
  size_t first = 0;
  while (first < n) {
    size_t i = first + 1;
    while (i < n && !same_point(pt[i], pt[first]))
      i++;
    for (size_t k = first; k < i && k + 1 < n; k++)
      edge(data, pt[k], pt[k + 1]);
    if (i >= n) {
      /* Left open: the closing edge back to its first point. */
      closed_all = false;
      if (n - 1 > first)
        edge(data, pt[n - 1], pt[first]);
    }
    first = i + 1;
  }
  return closed_all;
}

static void newell_edge(void *data, zr_vec3 a, zr_vec3 b) {
  zr_vec3 *nrm = data;
  nrm->x += (a.y - b.y) * (a.z + b.z);
  nrm->y += (a.z - b.z) * (a.x + b.x);
  nrm->z += (a.x - b.x) * (a.y + b.y);
}

typedef struct edge_store {
  const zr_object *o;
  double *edges;
  size_t n;
} edge_store;

static void store_edge(void *data, zr_vec3 a, zr_vec3 b) {
  edge_store *s = data;
  const zr_object *o = s->o;
  double *e = s->edges + 4 * s->n++;
  e[0] = zr_v3_dot(a, o->u.polygon.u_axis);
  e[1] = zr_v3_dot(a, o->u.polygon.v_axis);
  e[2] = zr_v3_dot(b, o->u.polygon.u_axis);
  e[3] = zr_v3_dot(b, o->u.polygon.v_axis);
}

static void count_edge(void *data, zr_vec3 a, zr_vec3 b) {
  (void)a;
  (void)b;
  (*(size_t *)data)++;
}

/* Whether a point lies more than 1e-10 (absolute, measured) off the
   plane through the first point and the first two later points that
   span a plane with it. */
static bool off_plane(const zr_vec3 *pt, size_t n) {
  zr_vec3 nrm = zr_v3(0, 0, 0);
  for (size_t i = 1; i < n && zr_v3_dot(nrm, nrm) == 0.0; i++)
    for (size_t k = i + 1; k < n; k++) {
      zr_vec3 c = zr_v3_cross(zr_v3_sub(pt[i], pt[0]),
                              zr_v3_sub(pt[k], pt[0]));
      if (zr_v3_dot(c, c) > 0.0) {
        nrm = c;
        break;
      }
    }
  double len = zr_v3_len(nrm);
  if (!(len > 0.0))
    return false;
  nrm = zr_v3_scale(nrm, 1.0 / len);
  for (size_t i = 1; i < n; i++)
    if (fabs(zr_v3_dot(zr_v3_sub(pt[i], pt[0]), nrm)) > 1e-10)
      return true;
  return false;
}

bool zr__sdl_polygon_done(zr_sdl_parser *p, zr_object *o,
                          const zr_sdl_loc *loc) {
  const zr_vec3 *pt = o->u.polygon.points;
  size_t n = o->u.polygon.n_points;
  if (!all_points(p, "polygon", n, o->u.polygon.n_expected, loc))
    return false;
  zr_vec3 nrm = zr_v3(0, 0, 0);
  size_t n_edges = 0;
  if (!each_edge(pt, n, newell_edge, &nrm))
    zr__sdl_warning(p, loc, "Polygon not closed. Closing it.");
  each_edge(pt, n, count_edge, &n_edges);
  double len = zr_v3_len(nrm);
  if (!(len > 0.0) || !isfinite(len)) {
    /* POV-Ray 3.7 draws nothing for it, without a word (measured:
       magh's pyramid1.pov, tests/legacy/polygon_line.pov): the polygon
       becomes an empty union. */
    zr__sdl_warning(p, loc, "the polygon's points are all on one line: "
                    "it has no area and is not drawn");
    o->kind = ZR_OBJ_UNION;
    memset(&o->u, 0, sizeof o->u);
    return true;
  }
  nrm = zr_v3_scale(nrm, 1.0 / len);
  if (off_plane(pt, n)) {
    zr__sdl_warning(p, loc, "the polygon's points are not in one plane: "
                    "it is not drawn, as POV-Ray 3.7 draws nothing for it");
    o->kind = ZR_OBJ_UNION;
    memset(&o->u, 0, sizeof o->u);
    return true;
  }
  /* The plane through the points' centroid; u, v span it. */
  zr_vec3 centre = zr_v3(0, 0, 0), lo = pt[0], hi = pt[0];
  for (size_t i = 0; i < n; i++) {
    centre = zr_v3_add(centre, pt[i]);
    lo = zr_v3_min(lo, pt[i]);
    hi = zr_v3_max(hi, pt[i]);
  }
  centre = zr_v3_scale(centre, 1.0 / (double)n);
  zr_vec3 helper = fabs(nrm.x) < 0.9 ? zr_v3(1, 0, 0) : zr_v3(0, 1, 0);
  o->u.polygon.normal = nrm;
  o->u.polygon.distance = zr_v3_dot(centre, nrm);
  o->u.polygon.u_axis = zr_v3_norm(zr_v3_cross(helper, nrm));
  o->u.polygon.v_axis = zr_v3_cross(nrm, o->u.polygon.u_axis);
  edge_store store = {o, zr__sdl_alloc(p, 4 * n_edges * sizeof(double)), 0};
  if (!store.edges)
    return false;
  each_edge(pt, n, store_edge, &store);
  o->u.polygon.edges = store.edges;
  o->u.polygon.n_edges = store.n;
  o->u.polygon.lo = lo;
  o->u.polygon.hi = hi;
  return true;
}

bool zr__sdl_sturm(zr_sdl_parser *p, zr_object *o, const zr_sdl_loc *loc) {
  if (o->kind == ZR_OBJ_TORUS) {
    o->u.torus.sturm = true;
    return true;
  }
  if (o->kind == ZR_OBJ_PRISM) {
    o->u.prism.sturm = true;
    return true;
  }
  if (o->kind == ZR_OBJ_LATHE) {
    o->u.lathe.sturm = true;
    return true;
  }
  if (o->kind == ZR_OBJ_BLOB) {
    o->u.blob.sturm = true;
    return true;
  }
  if (o->kind == ZR_OBJ_SOR) {
    o->u.sor.sturm = true;
    return true;
  }
  if (o->kind == ZR_OBJ_POLY)
    return true; /* lib/trace/roots.c is as careful as Sturm's method */
  zr__sdl_error(p, ZR_ESYNTAX, loc,
                "'sturm' is for tori and the other polynomial shapes");
  return false;
}

/* ---- prism ---- */

zr_object *zr__sdl_prism_new(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  return zr__sdl_object_new(p, ZR_OBJ_PRISM, loc);
}

void zr__sdl_prism_option(zr_object *o, int option) {
  if (option <= 3)
    o->u.prism.spline = option;
  else
    o->u.prism.conic = option == 5;
}

bool zr__sdl_prism_size(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_expr e[3], const zr_sdl_loc at[3]) {
  double h0, h1, n;
  if (!zr__sdl_want_float(p, &e[0], &at[0], &h0) ||
      !zr__sdl_want_float(p, &e[1], &at[1], &h1) ||
      !zr__sdl_want_float(p, &e[2], &at[2], &n))
    return false;
  static const double fewest[4] = {3, 3, 4, 4};
  int spline = o->u.prism.spline;
  o->u.prism.y0 = fmin(h0, h1);
  o->u.prism.y1 = fmax(h0, h1);
  o->u.prism.points = point_room(p, "this prism", fewest[spline], n, &at[2],
                                 &o->u.prism.n_expected);
  return o->u.prism.points != NULL;
}

bool zr__sdl_prism_point(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *point,
                         const zr_sdl_loc *point_loc) {
  return add_point(p, "prism", o->u.prism.points, &o->u.prism.n_points,
                   o->u.prism.n_expected, "<x, z>", point, point_loc);
}

/* The pieces of curve, filled in order; seg has room for cap. */
typedef struct curve {
  double *seg;
  size_t n, cap;
} curve;

/* Appends the piece c0 + c1 s + c2 s^2 + c3 s^3 (points as (x, y):
   the 2-D vectors' u, v, which are the prism's x and z). */
static void add_piece(curve *c, zr_vec3 c0, zr_vec3 c1, zr_vec3 c2,
                      zr_vec3 c3) {
  if (c->n == c->cap)
    return;
  double *s = c->seg + 8 * c->n++;
  s[0] = c0.x;
  s[1] = c1.x;
  s[2] = c2.x;
  s[3] = c3.x;
  s[4] = c0.y;
  s[5] = c1.y;
  s[6] = c2.y;
  s[7] = c3.y;
}

static void line_piece(curve *c, zr_vec3 a, zr_vec3 b) {
  zr_vec3 zero = zr_v3(0, 0, 0);
  add_piece(c, a, zr_v3_sub(b, a), zero, zero);
}

/* Hermite data (ends a, b, slopes ta, tb) in the power basis. */
static void hermite_piece(curve *c, zr_vec3 a, zr_vec3 b, zr_vec3 ta,
                          zr_vec3 tb) {
  zr_vec3 d = zr_v3_sub(b, a);
  zr_vec3 c2 = zr_v3_sub(zr_v3_sub(zr_v3_scale(d, 3.0),
                                   zr_v3_scale(ta, 2.0)), tb);
  zr_vec3 c3 = zr_v3_add(zr_v3_scale(d, -2.0), zr_v3_add(ta, tb));
  add_piece(c, a, ta, c2, c3);
}

/* The Bezier piece of the four points b[0..3]. */
static void bezier_piece(curve *c, const zr_vec3 *b) {
  add_piece(c, b[0], zr_v3_scale(zr_v3_sub(b[1], b[0]), 3.0),
            zr_v3_scale(zr_v3_add(zr_v3_sub(b[0], zr_v3_scale(b[1], 2.0)),
                                  b[2]),
                        3.0),
            zr_v3_add(zr_v3_sub(b[3], b[0]),
                      zr_v3_scale(zr_v3_sub(b[1], b[2]), 3.0)));
}

static void edge_piece(void *data, zr_vec3 a, zr_vec3 b) {
  line_piece(data, a, b);
}

/* The pieces of the quadratic and cubic splines: after the first
   control point, pieces from point j to j + 1 until the sub-prism's
   first curve point comes again; a cubic one then has its closing
   control point.  Returns false when a sub-prism is not closed. */
static bool spline_pieces(const zr_vec3 *pt, size_t n, bool cubic,
                          curve *c) {
  size_t i = 0;
  while (i < n) {
    if (i + 2 >= n)
      return false;
    size_t start = i + 1, j = start;
    while (j + 1 < n && !same_point(pt[j + 1], pt[start])) {
      j++;
    }
    if (j + 1 >= n || (cubic && j + 2 >= n))
      return false;
    for (size_t k = start; k <= j; k++) {
      zr_vec3 prev = pt[k - 1], a = pt[k], b = pt[k + 1];
      if (cubic) {
        zr_vec3 next = pt[k + 2];
        hermite_piece(c, a, b, zr_v3_scale(zr_v3_sub(b, prev), 0.5),
                      zr_v3_scale(zr_v3_sub(next, a), 0.5));
      } else {
        /* The parabola through prev, a and b at s = -1, 0, 1: its
           slope at a is half the chord from prev to b, which matches
           POV-Ray's renderings (measured: the manual leaves it open). */
        zr_vec3 ta = zr_v3_scale(zr_v3_sub(b, prev), 0.5);
        add_piece(c, a, ta, zr_v3_sub(zr_v3_sub(b, a), ta),
                  zr_v3(0, 0, 0));
      }
    }
    i = j + (cubic ? 3 : 2);
  }
  return true;
}

/* Widens lo, hi (x in .x, z in .z) by one coordinate's cubic over
   [0, 1]: its ends and the roots of its slope. */
static void cubic_extent(const double *k, double *lo, double *hi) {
  double at[4] = {0.0, 1.0, 0.0, 0.0};
  int n = 2;
  double slope[3] = {k[1], 2.0 * k[2], 3.0 * k[3]}, r[2];
  int m = zr__poly_roots(slope, 2, 0.0, 1.0, r);
  for (int i = 0; i < m; i++)
    at[n++] = r[i];
  for (int i = 0; i < n; i++) {
    double s = at[i], v = ((k[3] * s + k[2]) * s + k[1]) * s + k[0];
    *lo = fmin(*lo, v);
    *hi = fmax(*hi, v);
  }
}

/* The boxes of the pieces, 4 doubles each (first coordinate's range,
   then the second's), made once here so that the tracer need not find
   each piece's turning points for every ray; NULL when out of memory
   (the tracer then finds them itself). */
static const double *piece_boxes(zr_sdl_parser *p, const curve *c) {
  double *box = zr__sdl_alloc(p, 4 * (c->n ? c->n : 1) * sizeof(double));
  if (!box)
    return NULL;
  for (size_t i = 0; i < c->n; i++) {
    zr__cubic_range(c->seg + 8 * i, &box[4 * i], &box[4 * i + 1]);
    zr__cubic_range(c->seg + 8 * i + 4, &box[4 * i + 2], &box[4 * i + 3]);
  }
  return box;
}

bool zr__sdl_prism_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc) {
  const zr_vec3 *pt = o->u.prism.points;
  size_t n = o->u.prism.n_points;
  if (!all_points(p, "prism", n, o->u.prism.n_expected, loc))
    return false;
  curve c = {zr__sdl_alloc(p, 8 * (n + 1) * sizeof(double)), 0, n + 1};
  if (!c.seg)
    return false;
  bool closed = true;
  switch (o->u.prism.spline) {
  case 0:
    if (!each_edge(pt, n, edge_piece, &c))
      zr__sdl_warning(p, loc, "Linear prism not closed. Closing it.");
    break;
  case 1:
  case 2:
    closed = spline_pieces(pt, n, o->u.prism.spline == 2, &c);
    break;
  default:
    if (n % 4 != 0) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "a bezier_spline prism needs 4 points a piece, not %zu "
                    "points",
                    n);
      return false;
    }
    for (size_t i = 0; i + 3 < n; i += 4)
      bezier_piece(&c, pt + i);
    break;
  }
  if (!closed) {
    zr__sdl_error(p, ZR_ESCENE, loc,
                  "a sub-prism of this spline is not closed: its first "
                  "curve point must come again");
    return false;
  }
  double lx = INFINITY, hx = -INFINITY, lz = INFINITY, hz = -INFINITY;
  for (size_t i = 0; i < c.n; i++) {
    cubic_extent(c.seg + 8 * i, &lx, &hx);
    cubic_extent(c.seg + 8 * i + 4, &lz, &hz);
  }
  o->u.prism.seg = c.seg;
  o->u.prism.n_seg = c.n;
  o->u.prism.box = piece_boxes(p, &c);
  o->u.prism.lo = zr_v3(lx, 0.0, lz);
  o->u.prism.hi = zr_v3(hx, 0.0, hz);
  signed char *side = zr__sdl_alloc(p, c.n ? c.n : 1);
  if (!side)
    return false;
  zr__prism_wall_sides(o, side);
  o->u.prism.side = side;
  return true;
}

/* ---- lathe ---- */

zr_object *zr__sdl_lathe_new(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  return zr__sdl_object_new(p, ZR_OBJ_LATHE, loc);
}

bool zr__sdl_lathe_option(zr_sdl_parser *p, zr_object *o, int option,
                          const zr_sdl_loc *loc) {
  if (option > 3) {
    zr__sdl_error(p, ZR_ESYNTAX, loc,
                  "a lathe takes a spline type, not a sweep");
    return false;
  }
  o->u.lathe.spline = option;
  return true;
}

bool zr__sdl_lathe_count(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *count, const zr_sdl_loc *at) {
  double n;
  if (!zr__sdl_want_float(p, count, at, &n))
    return false;
  static const double fewest[4] = {2, 3, 4, 4};
  int spline = o->u.lathe.spline;
  o->u.lathe.points = point_room(p, "this lathe", fewest[spline], n, at,
                                 &o->u.lathe.n_expected);
  return o->u.lathe.points != NULL;
}

bool zr__sdl_lathe_point(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_expr *point,
                         const zr_sdl_loc *point_loc) {
  return add_point(p, "lathe", o->u.lathe.points, &o->u.lathe.n_points,
                   o->u.lathe.n_expected, "<r, y>", point, point_loc);
}

bool zr__sdl_lathe_done(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_loc *loc) {
  const zr_vec3 *pt = o->u.lathe.points;
  size_t n = o->u.lathe.n_points;
  if (!all_points(p, "lathe", n, o->u.lathe.n_expected, loc))
    return false;
  curve c = {zr__sdl_alloc(p, 8 * n * sizeof(double)), 0, n};
  if (!c.seg)
    return false;
  switch (o->u.lathe.spline) {
  case 0:
    for (size_t i = 0; i + 1 < n; i++)
      line_piece(&c, pt[i], pt[i + 1]);
    break;
  case 1:
    for (size_t i = 1; i + 1 < n; i++)
      add_piece(&c, pt[i], zr_v3_scale(zr_v3_sub(pt[i + 1], pt[i - 1]), 0.5),
                zr_v3_sub(zr_v3_sub(pt[i + 1], pt[i]),
                          zr_v3_scale(zr_v3_sub(pt[i + 1], pt[i - 1]), 0.5)),
                zr_v3(0, 0, 0));
    break;
  case 2:
    for (size_t i = 1; i + 2 < n; i++)
      hermite_piece(&c, pt[i], pt[i + 1],
                    zr_v3_scale(zr_v3_sub(pt[i + 1], pt[i - 1]), 0.5),
                    zr_v3_scale(zr_v3_sub(pt[i + 2], pt[i]), 0.5));
    break;
  default:
    if (n % 4 != 0) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "a bezier_spline lathe needs 4 points a piece, not %zu "
                    "points",
                    n);
      return false;
    }
    for (size_t i = 0; i + 3 < n; i += 4)
      bezier_piece(&c, pt + i);
    break;
  }
  double lr = INFINITY, hr = -INFINITY, ly = INFINITY, hy = -INFINITY;
  for (size_t i = 0; i < c.n; i++) {
    cubic_extent(c.seg + 8 * i, &lr, &hr);
    cubic_extent(c.seg + 8 * i + 4, &ly, &hy);
  }
  o->u.lathe.seg = c.seg;
  o->u.lathe.n_seg = c.n;
  o->u.lathe.box = piece_boxes(p, &c);
  o->u.lathe.lo = zr_v3(lr, ly, 0.0);
  o->u.lathe.hi = zr_v3(hr, hy, 0.0);
  return true;
}

/* ---- blob ---- */

zr_object *zr__sdl_blob_new(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_BLOB, loc);
  if (o)
    o->u.blob.threshold = 1.0;
  return o;
}

bool zr__sdl_blob_threshold(zr_sdl_parser *p, zr_object *o,
                            const zr_sdl_expr *e, const zr_sdl_loc *at) {
  double v;
  if (!zr__sdl_want_float(p, e, at, &v))
    return false;
  if (!(v > 0.0)) {
    zr__sdl_error(p, ZR_ESCENE, at, "a blob's threshold must be positive");
    return false;
  }
  o->u.blob.threshold = v;
  return true;
}

zr_blob_component *zr__sdl_blob_component(zr_sdl_parser *p, zr_object *o,
                                          bool cylinder, bool component,
                                          const zr_sdl_expr *e,
                                          const zr_sdl_loc *at) {
  zr_blob_component c = {0};
  c.cylinder = cylinder;
  bool ok;
  if (cylinder)
    ok = zr__sdl_want_vector(p, &e[0], &at[0], &c.a) &&
         zr__sdl_want_vector(p, &e[1], &at[1], &c.b) &&
         zr__sdl_want_float(p, &e[2], &at[2], &c.radius) &&
         zr__sdl_want_float(p, &e[3], &at[3], &c.strength);
  else if (component)
    ok = zr__sdl_want_float(p, &e[0], &at[0], &c.strength) &&
         zr__sdl_want_float(p, &e[1], &at[1], &c.radius) &&
         zr__sdl_want_vector(p, &e[2], &at[2], &c.a);
  else
    ok = zr__sdl_want_vector(p, &e[0], &at[0], &c.a) &&
         zr__sdl_want_float(p, &e[1], &at[1], &c.radius) &&
         zr__sdl_want_float(p, &e[2], &at[2], &c.strength);
  if (!ok)
    return NULL;
  /* The arena cannot grow a block: a full array moves to one twice as
     large. */
  if (o->u.blob.n_components == o->u.blob.cap_components) {
    size_t cap = o->u.blob.cap_components ? 2 * o->u.blob.cap_components
                                          : 8;
    zr_blob_component *grown = zr__sdl_alloc(p, cap * sizeof *grown);
    if (!grown)
      return NULL;
    if (o->u.blob.n_components)
      memcpy(grown, o->u.blob.components,
             o->u.blob.n_components * sizeof *grown);
    o->u.blob.components = grown;
    o->u.blob.cap_components = cap;
  }
  zr_blob_component *slot =
      &o->u.blob.components[o->u.blob.n_components++];
  *slot = c;
  return slot;
}

/*
 * A component's texture items go to a stand-in object that carries its
 * texture, so they mean what they mean on an object: a pigment, finish
 * or normal changes a copy of the texture so far (or of the default
 * texture), a texture goes on top as a layer, and a transformation after
 * them moves their patterns.
 */
static bool component_texture_mod(zr_sdl_parser *p, zr_blob_component *c,
                                  const zr_sdl_mod *mod,
                                  const zr_sdl_loc *loc) {
  zr_object carrier;
  memset(&carrier, 0, sizeof carrier);
  carrier.kind = ZR_OBJ_SPHERE;
  carrier.texture = c->texture;
  if (!zr__sdl_object_mod(p, &carrier, mod, loc))
    return false;
  c->texture = carrier.texture;
  return true;
}

bool zr__sdl_blob_component_mod(zr_sdl_parser *p, zr_object *blob,
                                zr_blob_component *c, const zr_sdl_mod *mod,
                                const zr_sdl_loc *loc) {
  switch (mod->kind) {
  case ZR_SDL_MOD_TRANSFORM:
    break;
  case ZR_SDL_MOD_PIGMENT:
  case ZR_SDL_MOD_FINISH:
  case ZR_SDL_MOD_NORMAL:
  case ZR_SDL_MOD_TEXTURE:
    blob->u.blob.textured = true;
    return component_texture_mod(p, c, mod, loc);
  default:
    zr__sdl_error(p, ZR_ESYNTAX, loc,
                  "a blob component takes a texture, pigment, normal, "
                  "finish and transformations only");
    return false;
  }
  if (c->texture && !component_texture_mod(p, c, mod, loc))
    return false;
  zr_transform *t = zr__sdl_alloc(p, sizeof *t);
  if (!t)
    return false;
  if (c->transform)
    *t = *c->transform;
  else
    zr__transform_identity(t);
  zr__transform_compose(t, mod->ptr);
  c->transform = t;
  return true;
}

/* ---- sor ---- */

zr_object *zr__sdl_sor_new(zr_sdl_parser *p, const zr_sdl_loc *loc,
                           const zr_sdl_expr *count,
                           const zr_sdl_loc *count_loc) {
  zr_object *o = zr__sdl_object_new(p, ZR_OBJ_SOR, loc);
  double n;
  if (!o || !zr__sdl_want_float(p, count, count_loc, &n))
    return NULL;
  o->u.sor.points = point_room(p, "a sor", 4, n, count_loc,
                               &o->u.sor.n_expected);
  return o->u.sor.points ? o : NULL;
}

bool zr__sdl_sor_point(zr_sdl_parser *p, zr_object *o,
                       const zr_sdl_expr *point,
                       const zr_sdl_loc *point_loc) {
  return add_point(p, "sor", o->u.sor.points, &o->u.sor.n_points,
                   o->u.sor.n_expected, "<r, y>", point, point_loc);
}

/*
 * The manual's system for segment j: r^2 = A h^3 + B h^2 + C h + D
 * through P(j) and P(j + 1), with slopes d(r^2)/dh of
 * 2 r(j) (r(j+1) - r(j-1)) / (h(j+1) - h(j-1)) at P(j) and
 * 2 r(j+1) (r(j+2) - r(j)) / (h(j+2) - h(j)) at P(j + 1).  The same
 * cubic is kept in u = (h - h(j)) / (h(j+1) - h(j)) (Hermite form).
 */
bool zr__sdl_sor_done(zr_sdl_parser *p, zr_object *o,
                      const zr_sdl_loc *loc) {
  const zr_vec3 *pt = o->u.sor.points;
  size_t n = o->u.sor.n_points;
  if (!all_points(p, "sor", n, o->u.sor.n_expected, loc))
    return false;
  /* The curve's heights must rise from P(1) to P(n-2); the outer two
     points only set slopes and may share a neighbour's height (the
     manual's vase does), but not lie beyond it. */
  for (size_t i = 0; i + 1 < n; i++)
    if (!(pt[i + 1].y > pt[i].y) &&
        !((i == 0 || i + 2 == n) && pt[i + 1].y == pt[i].y)) {
      zr__sdl_error(p, ZR_ESCENE, loc,
                    "the heights of a sor's points must increase");
      return false;
    }
  double *seg = zr__sdl_alloc(p, 6 * (n - 3) * sizeof(double));
  if (!seg)
    return false;
  double fmax_all = 0.0;
  for (size_t j = 1; j + 2 < n; j++) {
    double *s = seg + 6 * (j - 1);
    double h0 = pt[j].y, h1 = pt[j + 1].y, dh = h1 - h0;
    double r0 = pt[j].x, r1 = pt[j + 1].x;
    double m0 = 2.0 * r0 * (r1 - pt[j - 1].x) / (h1 - pt[j - 1].y) * dh;
    double m1 = 2.0 * r1 * (pt[j + 2].x - r0) / (pt[j + 2].y - h0) * dh;
    double v0 = r0 * r0, v1 = r1 * r1;
    s[0] = h0;
    s[1] = h1;
    s[2] = v0;
    s[3] = m0;
    s[4] = 3.0 * (v1 - v0) - 2.0 * m0 - m1;
    s[5] = 2.0 * (v0 - v1) + m0 + m1;
    double lo = INFINITY, hi = -INFINITY;
    cubic_extent(s + 2, &lo, &hi);
    fmax_all = fmax(fmax_all, hi);
  }
  o->u.sor.seg = seg;
  o->u.sor.n_seg = n - 3;
  o->u.sor.rmax = sqrt(fmax_all);
  return true;
}
