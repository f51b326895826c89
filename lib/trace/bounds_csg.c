/*
 * bounds_csg.c - boxes for intersections of infinite shapes.
 *
 * An intersection lies inside every child, so its box is the overlap of
 * the children's boxes (bounds.c).  That leaves a whole class of everyday
 * objects unbounded: a hyperboloid or a cylinder quadric cut by two planes
 * (shapes.inc's Hyperboloid_Y between plane { y, 5.5 } and plane { -y,
 * -2.5 }, a chess pawn's neck), a slab of planes, a cone quadric capped by
 * a plane.  None of the children is finite, yet the object is.  The
 * manual's "Automatic Bounding" notes that POV-Ray bounds "even some
 * clipped or bounded quadrics" and CSG made of infinite parts; unbounded,
 * such an object is tested by every ray of the image (advanced/chess2.pov
 * had 38 of them, POV-Ray 4, and took 9 times POV-Ray's time).
 *
 * The box is found by interval constraint propagation, a standard method
 * of interval analysis: every plane and quadric child is written in world
 * coordinates as q(p) = p.A.p + b.p + c <= 0 (inside), and each constraint
 * in turn narrows the box: along axis i, q is a x_i^2 + B x_i + R with B
 * and R intervals over the other axes' current ranges, so x_i must satisfy
 * a x_i^2 + min(B x_i) + min(R) <= 0, whose solutions are a union of at
 * most two intervals found from the quadratic's roots.  Every step keeps
 * all points that satisfy the constraint, so the result is a superset of
 * the object (conservative); a few rounds over the children reach a box
 * that further rounds hardly change.  Finite children narrow the box by
 * their own box, unions by the hull of what each of their children
 * allows, nested intersections by all of theirs.
 */
#include "trace/bounds_csg.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "trace/intersect.h"

/* Rounds of narrowing by every child; the boxes of the stock scenes'
   intersections stop changing after two. */
#define ROUNDS 4

typedef struct ival {
  double lo, hi;
} ival;

typedef struct box3 {
  ival x[3];
  bool empty;
} box3;

/* A world-space quadratic constraint q(p) <= 0. */
typedef struct quad3 {
  double a[3][3]; /* symmetric */
  double b[3];
  double c;
} quad3;

/* a * b for the bounds of an interval product, where 0 * inf counts as 0
   (a zero coefficient means the term is absent). */
static double mul0(double a, double b) {
  return (a == 0.0 || b == 0.0) ? 0.0 : a * b;
}

static ival iv_mul(ival a, ival b) {
  double p[4] = {mul0(a.lo, b.lo), mul0(a.lo, b.hi), mul0(a.hi, b.lo),
                 mul0(a.hi, b.hi)};
  ival r = {p[0], p[0]};
  for (int k = 1; k < 4; k++) {
    r.lo = fmin(r.lo, p[k]);
    r.hi = fmax(r.hi, p[k]);
  }
  return r;
}

static ival iv_scale(ival a, double k) {
  return iv_mul(a, (ival){k, k});
}

static ival iv_add(ival a, ival b) {
  return (ival){a.lo + b.lo, a.hi + b.hi};
}

/* The range of a x^2 + b x over x, taken as one quadratic so that its
   finite minimum survives an unbounded x (x^2 and b x apart would give
   -inf: interval arithmetic's dependency problem). */
static double quad_at(double a, double b, double x) {
  if (isinf(x))
    return a != 0.0 ? copysign(INFINITY, a) : mul0(b, x);
  return (a * x + b) * x;
}

static ival iv_quad(double a, double b, ival x) {
  if (a == 0.0)
    return iv_scale(x, b);
  double f0 = quad_at(a, b, x.lo), f1 = quad_at(a, b, x.hi);
  ival r = {fmin(f0, f1), fmax(f0, f1)};
  double v = -b / (2.0 * a);
  if (v > x.lo && v < x.hi) {
    double fv = -b * b / (4.0 * a);
    r.lo = fmin(r.lo, fv);
    r.hi = fmax(r.hi, fv);
  }
  return r;
}

/* A little wider, so rounding in the coefficients never cuts a surface
   point off. */
static double widen_lo(double x) {
  return x - 1e-7 * (1.0 + fabs(x));
}
static double widen_hi(double x) {
  return x + 1e-7 * (1.0 + fabs(x));
}

/* The hull of {x in [u, v] : a x^2 + b x + c <= 0}; false when empty. */
static bool quadratic_hull(double a, double b, double c, double u, double v,
                           ival *out) {
  if (u > v)
    return false;
  if (!isfinite(b) || !isfinite(c) || !isfinite(a)) {
    /* An unbounded range elsewhere: no limit here (c = +inf cannot arise,
       a lower bound of a sum being at most finite or -inf). */
    *out = (ival){u, v};
    return true;
  }
  if (a == 0.0) {
    if (b == 0.0) {
      *out = (ival){u, v};
      return c <= 0.0;
    }
    double r = -c / b;
    if (b > 0.0)
      v = fmin(v, widen_hi(r));
    else
      u = fmax(u, widen_lo(r));
    *out = (ival){u, v};
    return u <= v;
  }
  double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) {
    /* Never negative (a > 0), or always (a < 0). */
    *out = (ival){u, v};
    return a < 0.0;
  }
  double s = sqrt(disc);
  /* The stable pair of roots. */
  double qq = -0.5 * (b + copysign(s, b));
  double r1 = qq / a, r2 = qq != 0.0 ? c / qq : r1;
  if (r1 > r2) {
    double t = r1;
    r1 = r2;
    r2 = t;
  }
  r1 = widen_lo(r1);
  r2 = widen_hi(r2);
  if (a > 0.0) {
    *out = (ival){fmax(u, r1), fmin(v, r2)};
    return out->lo <= out->hi;
  }
  /* a < 0: outside the roots. */
  bool left = u <= r1, right = v >= r2;
  if (!left && !right)
    return false;
  *out = (ival){left ? u : fmax(u, r2), right ? v : fmin(v, r1)};
  return true;
}

/* Narrows box axis i by q <= 0. */
static bool narrow_axis(const quad3 *q, box3 *box, int i) {
  ival lin = {q->b[i], q->b[i]}, rest = {q->c, q->c};
  for (int j = 0; j < 3; j++) {
    if (j == i)
      continue;
    lin = iv_add(lin, iv_scale(box->x[j], 2.0 * q->a[i][j]));
    rest = iv_add(rest, iv_quad(q->a[j][j], q->b[j], box->x[j]));
    for (int k = j + 1; k < 3; k++)
      if (k != i && q->a[j][k] != 0.0)
        rest = iv_add(rest, iv_scale(iv_mul(box->x[j], box->x[k]),
                                     2.0 * q->a[j][k]));
  }
  double a = q->a[i][i];
  ival cur = box->x[i], pos, neg;
  /* x >= 0: the smallest B x is lin.lo x; x < 0: lin.hi x. */
  bool has_pos = quadratic_hull(a, lin.lo, rest.lo, fmax(cur.lo, 0.0),
                                cur.hi, &pos);
  bool has_neg = quadratic_hull(a, lin.hi, rest.lo, cur.lo,
                                fmin(cur.hi, 0.0), &neg);
  if (!has_pos && !has_neg)
    return false;
  if (has_pos && has_neg)
    box->x[i] = (ival){neg.lo, pos.hi};
  else
    box->x[i] = has_pos ? pos : neg;
  return true;
}

/* The form of a plane or quadric leaf in the coordinates of frame (NULL:
   world); false for other kinds. */
static bool frame_form(const zr_object *o, const zr_transform *frame,
                       quad3 *q) {
  double al[3][3] = {{0}}, bl[3] = {0}, cl = 0.0;
  if (o->kind == ZR_OBJ_PLANE) {
    bl[0] = o->u.plane.normal.x;
    bl[1] = o->u.plane.normal.y;
    bl[2] = o->u.plane.normal.z;
    cl = -o->u.plane.distance;
  } else if (o->kind == ZR_OBJ_QUADRIC) {
    const double *k = o->u.quadric.coef;
    al[0][0] = k[0];
    al[1][1] = k[1];
    al[2][2] = k[2];
    al[0][1] = al[1][0] = 0.5 * k[3];
    al[0][2] = al[2][0] = 0.5 * k[4];
    al[1][2] = al[2][1] = 0.5 * k[5];
    bl[0] = k[6];
    bl[1] = k[7];
    bl[2] = k[8];
    cl = k[9];
  } else {
    return false;
  }
  /* p_local = R p + t, with R and t from the frame-to-object matrix:
     the frame's own map to world, then the object's from world. */
  zr_transform to_local;
  zr__transform_identity(&to_local);
  if (frame)
    to_local = *frame;
  if (o->transform) {
    zr_transform from_world = *o->transform;
    zr__transform_invert(&from_world);
    zr__transform_compose(&to_local, &from_world);
  }
  double r[3][3], t[3];
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++)
      r[i][j] = to_local.m[i][j];
    t[i] = to_local.m[i][3];
  }
  double at[3] = {0}; /* A_l t */
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      at[i] += al[i][j] * t[j];
  q->c = cl;
  for (int i = 0; i < 3; i++)
    q->c += t[i] * at[i] + bl[i] * t[i];
  for (int i = 0; i < 3; i++) {
    q->b[i] = 0.0;
    for (int k = 0; k < 3; k++)
      q->b[i] += r[k][i] * (2.0 * at[k] + bl[k]);
    for (int j = 0; j < 3; j++) {
      double s = 0.0;
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++)
          s += r[k][i] * al[k][l] * r[l][j];
      q->a[i][j] = s;
    }
  }
  /* Terms that are zero in exact arithmetic come out of the matrix
     products as rounding residue (1e-17): against an unbounded range they
     would block every narrowing, so terms below 1e-12 of the largest are
     dropped; at any finite extent their effect is far below the widening
     of the roots. */
  double big = 0.0;
  for (int i = 0; i < 3; i++) {
    big = fmax(big, fabs(q->b[i]));
    for (int j = 0; j < 3; j++)
      big = fmax(big, fabs(q->a[i][j]));
  }
  for (int i = 0; i < 3; i++) {
    if (fabs(q->b[i]) < 1e-12 * big)
      q->b[i] = 0.0;
    for (int j = 0; j < 3; j++)
      if (fabs(q->a[i][j]) < 1e-12 * big)
        q->a[i][j] = 0.0;
  }
  if (o->inverse) {
    for (int i = 0; i < 3; i++) {
      q->b[i] = -q->b[i];
      for (int j = 0; j < 3; j++)
        q->a[i][j] = -q->a[i][j];
    }
    q->c = -q->c;
  }
  return true;
}

static void narrow(const zr_object *o, const zr_transform *frame,
                   box3 *box);

void zr__box_through(const double map[4][4], zr_vec3 *lo, zr_vec3 *hi) {
  zr_vec3 l = zr_v3(INFINITY, INFINITY, INFINITY), h = zr_v3_neg(l);
  for (int c = 0; c < 8; c++) {
    zr_vec3 p = zr__xform_point(map, zr_v3(c & 1 ? hi->x : lo->x,
                                           c & 2 ? hi->y : lo->y,
                                           c & 4 ? hi->z : lo->z));
    l = zr_v3_min(l, p);
    h = zr_v3_max(h, p);
  }
  *lo = l;
  *hi = h;
}

/* Narrows by one leaf: its box when finite, its constraint when a plane
   or quadric. */
static void narrow_leaf(const zr_object *o, const zr_transform *frame,
                        box3 *box) {
  quad3 q;
  if (frame_form(o, frame, &q)) {
    for (int i = 0; i < 3 && !box->empty; i++)
      box->empty = !narrow_axis(&q, box, i);
    return;
  }
  /* A height field holds points below its box (zr__box_holds_inside),
     where the other parts' surfaces then count: no limit from it.  A
     disc's box does limit the intersection's box although the disc
     holds a half-space: POV-Ray 3.7 skips such an intersection for the
     rays that miss the disc's flat box (tests/csg_inside.pov: it draws
     intersection { sphere { -0.5*y, 1 } disc { 0, -y, 1.5 } }, seen from
     above, as the cap cut off where the rays pass the disc's plane
     outside its radius, and zRcube's picture is now the same pixels). */
  zr_vec3 lo, hi;
  if (o->kind == ZR_OBJ_HEIGHT_FIELD || !zr__object_bounds(o, &lo, &hi))
    return;
  if (frame)
    zr__box_through(frame->inv, &lo, &hi);
  double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
  for (int i = 0; i < 3; i++) {
    box->x[i].lo = fmax(box->x[i].lo, l[i]);
    box->x[i].hi = fmin(box->x[i].hi, h[i]);
    if (box->x[i].lo > box->x[i].hi)
      box->empty = true;
  }
}

/* Narrows box (in frame coordinates) to the points of it that object o
   may hold. */
static void narrow(const zr_object *o, const zr_transform *frame,
                   box3 *box) {
  if (box->empty)
    return;
  if (o->kind == ZR_OBJ_INTERSECTION && !o->inverse) {
    for (int r = 0; r < 2; r++)
      for (size_t i = 0; i < o->u.csg.n_children && !box->empty; i++)
        narrow(o->u.csg.children[i], frame, box);
  } else if ((o->kind == ZR_OBJ_UNION || o->kind == ZR_OBJ_MERGE) &&
             !o->inverse) {
    box3 hull = {.empty = true};
    for (size_t i = 0; i < o->u.csg.n_children; i++) {
      box3 part = *box;
      narrow(o->u.csg.children[i], frame, &part);
      if (part.empty)
        continue;
      if (hull.empty) {
        hull = part;
        continue;
      }
      for (int k = 0; k < 3; k++) {
        hull.x[k].lo = fmin(hull.x[k].lo, part.x[k].lo);
        hull.x[k].hi = fmax(hull.x[k].hi, part.x[k].hi);
      }
    }
    *box = hull;
  } else if (zr__is_csg(o->kind)) {
    return; /* an inverted node: no limit */
  } else {
    narrow_leaf(o, frame, box);
  }
  if (o->clip && !box->empty)
    narrow(o->clip, frame, box);
}

/*
 * Planes alone: narrowing one axis at a time cannot bound a solid whose
 * faces all lie across the axes (shapes2.inc's Dodecahedron, twelve
 * planes none of them along an axis: every ray of stock textures/
 * pigments/dodec2.pov tested all five of them, sixty planes).  The
 * planes among an intersection's children (and its nested
 * intersections') hold a convex polyhedron that holds the object.  It
 * is bounded exactly when no direction v != 0 has n.v <= 0 for every
 * plane normal n (its recession cone is {0}); such a direction, if
 * there is one, can be taken along an edge of the cone, where two of
 * the planes' boundaries through the origin meet: along +-(n_a x n_b).
 * A bounded polyhedron's box is the box of its vertices, the points
 * where three planes meet that lie inside all the others.  Every test
 * leans toward "unbounded" and "inside" by a margin far above rounding,
 * so the box found is never smaller than the polyhedron's, with one
 * exception left: a vertex where three faces meet so nearly along one
 * line that their normals' determinant is below 1e-10 is not placed
 * (rounding would put it anywhere; parallel faces give such triples).
 */
#define POLY_MAX 48

typedef struct halfspace {
  double n[3]; /* n . p <= d inside */
  double d;
} halfspace;

/* The plane leaves of intersection node and of the intersections in it
   into h (from n on, at most POLY_MAX); their new count. */
static int collect_planes(const zr_object *node, halfspace *h, int n) {
  for (size_t i = 0; i < node->u.csg.n_children && n < POLY_MAX; i++) {
    const zr_object *o = node->u.csg.children[i];
    if (o->kind == ZR_OBJ_INTERSECTION && !o->inverse) {
      n = collect_planes(o, h, n);
      continue;
    }
    quad3 q;
    if (o->kind != ZR_OBJ_PLANE || !frame_form(o, NULL, &q))
      continue;
    double len = sqrt(q.b[0] * q.b[0] + q.b[1] * q.b[1] + q.b[2] * q.b[2]);
    if (!(len > 0.0) || !isfinite(len) || !isfinite(q.c))
      continue;
    /* Unit normals, so that the margins below are distances. */
    for (int k = 0; k < 3; k++)
      h[n].n[k] = q.b[k] / len;
    h[n++].d = -q.c / len;
  }
  return n;
}

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Whether the polyhedron of h[0 .. n) is bounded (see above). */
static bool polyhedron_bounded(const halfspace *h, int n) {
  bool spans = false;
  for (int a = 0; a < n; a++)
    for (int b = a + 1; b < n; b++) {
      double v[3];
      cross3(h[a].n, h[b].n, v);
      double len = sqrt(dot3(v, v));
      if (!(len > 1e-9))
        continue; /* (anti)parallel normals: no edge of the cone */
      spans = true;
      for (int sign = -1; sign <= 1; sign += 2) {
        bool all = true;
        for (int k = 0; k < n && all; k++)
          all = sign * dot3(h[k].n, v) <= 1e-9 * len;
        if (all)
          return false;
      }
    }
  /* Normals along one line leave a whole plane of directions free. */
  return spans;
}

/* The box of the polyhedron of h[0 .. n) when it is bounded and has a
   vertex; false otherwise. */
static bool polyhedron_box(const halfspace *h, int n, box3 *box) {
  if (n < 4 || !polyhedron_bounded(h, n))
    return false;
  double scale = 1.0;
  for (int k = 0; k < n; k++)
    scale = fmax(scale, fabs(h[k].d));
  double lo[3] = {INFINITY, INFINITY, INFINITY};
  double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int a = 0; a < n; a++)
    for (int b = a + 1; b < n; b++)
      for (int c = b + 1; c < n; c++) {
        /* Cramer's rule: p = (d_a (n_b x n_c) + d_b (n_c x n_a) +
           d_c (n_a x n_b)) / (n_a . (n_b x n_c)), whose rounding grows
           as 1 / |det| (the planes meet at a shallow angle): the margin
           m grows with it. */
        double x_bc[3], x_ca[3], x_ab[3];
        cross3(h[b].n, h[c].n, x_bc);
        cross3(h[c].n, h[a].n, x_ca);
        cross3(h[a].n, h[b].n, x_ab);
        double det = dot3(h[a].n, x_bc);
        /* Unit normals this close to one plane meet nowhere worth
           placing (two parallel faces give rounding residue here, and
           a point 1e17 away). */
        if (!(fabs(det) > 1e-10))
          continue;
        double p[3];
        for (int k = 0; k < 3; k++)
          p[k] = (h[a].d * x_bc[k] + h[b].d * x_ca[k] + h[c].d * x_ab[k]) /
                 det;
        double size = fmax(scale, fmax(fabs(p[0]),
                                       fmax(fabs(p[1]), fabs(p[2]))));
        double m = 1e-13 * size / fabs(det);
        bool inside = isfinite(size) && isfinite(m);
        for (int k = 0; k < n && inside; k++)
          inside = dot3(h[k].n, p) <= h[k].d + 1e-9 * size + 4.0 * m;
        if (!inside)
          continue;
        for (int k = 0; k < 3; k++) {
          lo[k] = fmin(lo[k], p[k] - m);
          hi[k] = fmax(hi[k], p[k] + m);
        }
      }
  /* No vertex: a bounded polyhedron without one is empty, but the
     narrowing is left to say so. */
  if (!(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]))
    return false;
  for (int k = 0; k < 3; k++)
    box->x[k] = (ival){widen_lo(lo[k]), widen_hi(hi[k])};
  return true;
}

/* Narrows in frame (NULL: world) and intersects the world box [lo, hi]
   with the result; false when that frame finds nothing finite.  In the
   world frame the narrowing starts from the box of the planes'
   polyhedron, when that is bounded. */
static bool narrow_in(const zr_object *node, const zr_transform *frame,
                      zr_vec3 *lo, zr_vec3 *hi, bool *empty) {
  box3 box = {.empty = false};
  for (int i = 0; i < 3; i++)
    box.x[i] = (ival){-INFINITY, INFINITY};
  if (!frame) {
    halfspace h[POLY_MAX];
    polyhedron_box(h, collect_planes(node, h, 0), &box);
  }
  for (int r = 0; r < ROUNDS && !box.empty; r++)
    for (size_t i = 0; i < node->u.csg.n_children && !box.empty; i++)
      narrow(node->u.csg.children[i], frame, &box);
  if (box.empty) {
    *empty = true;
    return true;
  }
  for (int i = 0; i < 3; i++)
    if (!isfinite(box.x[i].lo) || !isfinite(box.x[i].hi))
      return false;
  zr_vec3 l = zr_v3(box.x[0].lo, box.x[1].lo, box.x[2].lo);
  zr_vec3 h = zr_v3(box.x[0].hi, box.x[1].hi, box.x[2].hi);
  if (frame)
    zr__box_through(frame->m, &l, &h);
  *lo = zr_v3_max(*lo, l);
  *hi = zr_v3_min(*hi, h);
  return true;
}

/* The frames worth narrowing in besides the world's: those of the
   quadric children (and of quadrics in their unions), where a rotated
   quadric and planes cut across it are axis-aligned. */
#define MAX_FRAMES 3

static int quadric_frames(const zr_object *o, const zr_transform **frames,
                          int n, int depth) {
  if (n >= MAX_FRAMES || depth > 2)
    return n;
  if (zr__is_csg(o->kind)) {
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      n = quadric_frames(o->u.csg.children[i], frames, n, depth + 1);
    return n;
  }
  if (o->kind != ZR_OBJ_QUADRIC || !o->transform)
    return n;
  for (int k = 0; k < n; k++)
    if (!memcmp(frames[k]->m, o->transform->m, sizeof o->transform->m))
      return n;
  frames[n] = o->transform;
  return n + 1;
}

bool zr__intersection_bounds(const zr_object *node, zr_vec3 *lo,
                             zr_vec3 *hi) {
  zr_vec3 l = zr_v3(-INFINITY, -INFINITY, -INFINITY), h = zr_v3_neg(l);
  bool empty = false, finite = narrow_in(node, NULL, &l, &h, &empty);
  const zr_transform *frames[MAX_FRAMES];
  int n = quadric_frames(node, frames, 0, 0);
  for (int k = 0; k < n && !empty; k++)
    finite |= narrow_in(node, frames[k], &l, &h, &empty);
  if (empty || (finite && (l.x > h.x || l.y > h.y || l.z > h.z))) {
    /* Nothing can be inside all children: a point box keeps the object
       in the hierarchy (it has no surface anyway). */
    *lo = *hi = zr_v3(0.0, 0.0, 0.0);
    return true;
  }
  if (!finite)
    return false;
  *lo = l;
  *hi = h;
  return true;
}
