/*
 * csg.c - constructive solid geometry kept as one primitive: intersection,
 * difference, merge, and unions nested in them (POV-Ray 3.7 reference,
 * "Constructive Solid Geometry": "Inside and Outside", "Union",
 * "Intersection", "Difference", "Merge"; and "Clipped_By").
 *
 * The surface of a CSG object is made of pieces of its children's
 * surfaces, chosen by inside tests on the other children:
 *   - union keeps every crossing of every child (inner surfaces too);
 *   - merge keeps a child's crossing where no other child contains it;
 *   - intersection keeps it where every other child contains it;
 *   - a difference A - B - C is the intersection of A with B and C
 *     inverted, as the manual defines it, so the parser builds it so and
 *     the tracer never sees one.
 * Inverting a CSG node follows De Morgan's laws (lib/sdl/build.c): the
 * children are inverted and intersection and merge trade places (an
 * inverted union becomes an intersection of the inverted children, which
 * drops its inner surfaces).  So inverse flags live on the leaf
 * primitives only, and every crossing's normal, flipped by its leaf's
 * flag, points out of the whole solid: a ray entering the solid sees a
 * normal against it, which is what refraction and media tracking need.
 *
 * The crossings are collected bottom-up: each node gathers the surviving
 * crossings of its children in (tmin, tmax) and filters them, then the
 * nearest two are reported, each with its leaf as the hit object so that
 * it is shaded with that leaf's texture.  A leaf yields at most two
 * crossings per query; one that yields two is asked again beyond the
 * second, so non-convex leaves lose nothing.
 */
#include "trace/intersect.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "trace/obj_shapes.h" /* zr__ray_box_span */
#include "trace/shape.h"

/* The most crossings one CSG primitive gathers along a ray; more are
   dropped (a ray through over a hundred child surfaces at once). */
#define CSG_MAX_GATHER 256


typedef struct gather {
  const zr_ray *ray;
  double tmax;
  bool want_normals;
  /* The top node, and how many of its nearest crossings the caller
     wants (1 or ZR_MAX_CROSSINGS): see shrink(). */
  const zr_object *top;
  int wanted;
  /* For slack_span: 1 / ray->dir, and 1 + the origin's largest
     coordinate. */
  zr_vec3 inv_dir;
  double origin_size;
  zr_hit hit[CSG_MAX_GATHER];
  int n;
} gather;

static zr_vec3 point_at(const zr_ray *ray, double t) {
  return zr_v3_madd(ray->origin, ray->dir, t);
}

/* Whether the ray may meet something inside the box lo, hi within
   (tmin, tmax).  The box's span along the ray (obj_torus.c) is left
   empty when the ray runs beside the box parallel to an axis.  A box
   that holds another gets a span that holds the other's (each slab's
   ends move out, and rounding is monotonic), which the tree below
   relies on. */
static bool ray_meets_box(zr_vec3 lo, zr_vec3 hi, const zr_ray *ray,
                          double tmin, double tmax) {
  double s0 = 0.0, s1 = -1.0;
  zr__ray_box_span(lo, hi, ray->origin, ray->dir, &s0, &s1);
  return (s0 > tmin ? s0 : tmin) <= (s1 < tmax ? s1 : tmax);
}

/* The same for a child's box: an unbounded child always may. */
static bool ray_meets(const struct zr_csg_box *b, const zr_ray *ray,
                      double tmin, double tmax) {
  return !b->bounded || ray_meets_box(b->lo, b->hi, ray, tmin, tmax);
}

static bool box_holds(zr_vec3 lo, zr_vec3 hi, zr_vec3 p) {
  return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y &&
         p.z >= lo.z && p.z <= hi.z;
}

/*
 * The tree over a part's children (a union of a hundred bubbles inside
 * a merge, as in advanced/grenadine, tested a hundred boxes for every
 * ray through it): a binary tree of boxes, split at the median of the
 * children's box centres along the widest spread of them, with runs of
 * at most LEAF_RUN children at its leaves.  Queries only choose which
 * children to look at; each chosen child is still tested against its
 * own box as without the tree, and the ones a ray meets are visited in
 * their written order, so the crossings and their order are the same.
 * Children with no box (or a box that is not finite) are always chosen.
 */
#define LEAF_RUN 4
/* The most children a ray query collects; a ray meeting more boxes
   than this falls back to testing every child. */
#define QUERY_MAX 256

typedef struct csg_tree_node {
  zr_vec3 lo, hi;
  uint32_t right;        /* inner node: the second subtree (first: next) */
  uint32_t first, count; /* leaf: children order[first ..], count > 0 */
} csg_tree_node;

struct zr_csg_tree {
  csg_tree_node *nodes;
  uint32_t *order;      /* the boxed children, as the leaves hold them */
  uint32_t *unbounded;  /* the others, always visited */
  uint32_t n_unbounded;
  /* The boxed children that hold what lies outside their boxes (parts
     cut out): in the tree for rays, but every point query asks them. */
  uint32_t *outside;
  uint32_t n_outside;
};

typedef struct tree_item {
  double centre[3];
  uint32_t child;
} tree_item;

static int by_x(const void *a, const void *b) {
  double u = ((const tree_item *)a)->centre[0];
  double v = ((const tree_item *)b)->centre[0];
  return (u > v) - (u < v);
}
static int by_y(const void *a, const void *b) {
  double u = ((const tree_item *)a)->centre[1];
  double v = ((const tree_item *)b)->centre[1];
  return (u > v) - (u < v);
}
static int by_z(const void *a, const void *b) {
  double u = ((const tree_item *)a)->centre[2];
  double v = ((const tree_item *)b)->centre[2];
  return (u > v) - (u < v);
}

/* Fills nodes from *used on with the tree of items[0 .. n); returns the
   index of its root. */
static uint32_t build_node(struct zr_csg_tree *t, const zr_object *node,
                           tree_item *items, uint32_t n, uint32_t offset,
                           uint32_t *used) {
  uint32_t at = (*used)++;
  csg_tree_node *nd = &t->nodes[at];
  const struct zr_csg_box *b = node->u.csg.boxes;
  zr_vec3 lo = b[items[0].child].lo, hi = b[items[0].child].hi;
  double clo[3], chi[3];
  for (int k = 0; k < 3; k++)
    clo[k] = chi[k] = items[0].centre[k];
  for (uint32_t i = 1; i < n; i++) {
    lo = zr_v3_min(lo, b[items[i].child].lo);
    hi = zr_v3_max(hi, b[items[i].child].hi);
    for (int k = 0; k < 3; k++) {
      clo[k] = fmin(clo[k], items[i].centre[k]);
      chi[k] = fmax(chi[k], items[i].centre[k]);
    }
  }
  nd->lo = lo;
  nd->hi = hi;
  if (n <= LEAF_RUN) {
    nd->first = offset;
    nd->count = n;
    nd->right = 0;
    for (uint32_t i = 0; i < n; i++)
      t->order[offset + i] = items[i].child;
    return at;
  }
  int axis = 0;
  for (int k = 1; k < 3; k++)
    if (chi[k] - clo[k] > chi[axis] - clo[axis])
      axis = k;
  static int (*const cmp[3])(const void *, const void *) = {by_x, by_y,
                                                            by_z};
  qsort(items, n, sizeof *items, cmp[axis]);
  uint32_t half = n / 2;
  nd->count = 0;
  nd->first = 0;
  build_node(t, node, items, half, offset, used);
  uint32_t right = build_node(t, node, items + half, n - half,
                              offset + half, used);
  t->nodes[at].right = right;
  return at;
}

static bool finite_box(const struct zr_csg_box *b) {
  return b->bounded && isfinite(b->lo.x) && isfinite(b->lo.y) &&
         isfinite(b->lo.z) && isfinite(b->hi.x) && isfinite(b->hi.y) &&
         isfinite(b->hi.z);
}

zr_status zr__csg_tree_build(zr_arena *arena, zr_object *node) {
  node->u.csg.tree = NULL;
  size_t n = node->u.csg.n_children;
  const struct zr_csg_box *b = node->u.csg.boxes;
  if (!b || n < ZR_CSG_TREE_MIN || n > UINT32_MAX / 2)
    return ZR_OK;
  uint32_t n_boxed = 0;
  for (size_t i = 0; i < n; i++)
    n_boxed += finite_box(&b[i]);
  if (n_boxed < ZR_CSG_TREE_MIN)
    return ZR_OK;
  struct zr_csg_tree *t = zr__arena_alloc(arena, sizeof *t);
  tree_item *items = malloc(n_boxed * sizeof *items);
  if (!t || !items) {
    free(items);
    return ZR_ENOMEM;
  }
  t->nodes = zr__arena_alloc(arena, 2 * n_boxed * sizeof *t->nodes);
  t->order = zr__arena_alloc(arena, n_boxed * sizeof *t->order);
  t->n_unbounded = (uint32_t)(n - n_boxed);
  t->unbounded = zr__arena_alloc(
      arena, (t->n_unbounded ? t->n_unbounded : 1) * sizeof *t->unbounded);
  t->outside = zr__arena_alloc(arena, n_boxed * sizeof *t->outside);
  if (!t->nodes || !t->order || !t->unbounded || !t->outside) {
    free(items);
    return ZR_ENOMEM;
  }
  uint32_t k = 0, u = 0;
  t->n_outside = 0;
  for (size_t i = 0; i < n; i++) {
    if (!finite_box(&b[i])) {
      t->unbounded[u++] = (uint32_t)i;
      continue;
    }
    if (b[i].holds_outside)
      t->outside[t->n_outside++] = (uint32_t)i;
    zr_vec3 c = zr_v3_scale(zr_v3_add(b[i].lo, b[i].hi), 0.5);
    items[k].centre[0] = c.x;
    items[k].centre[1] = c.y;
    items[k].centre[2] = c.z;
    items[k++].child = (uint32_t)i;
  }
  uint32_t used = 0;
  build_node(t, node, items, n_boxed, 0, &used);
  free(items);
  node->u.csg.tree = t;
  return ZR_OK;
}

static int by_index(const void *a, const void *b) {
  uint32_t u = *(const uint32_t *)a, v = *(const uint32_t *)b;
  return (u > v) - (u < v);
}

/* The children of node whose boxes the ray may meet in (tmin, tmax),
   in written order, into out[QUERY_MAX]; -1 when there are more. */
static int tree_ray(const struct zr_csg_tree *t, const zr_ray *ray,
                    double tmin, double tmax, uint32_t *out) {
  int n = 0;
  if (t->n_unbounded > QUERY_MAX)
    return -1;
  for (uint32_t i = 0; i < t->n_unbounded; i++)
    out[n++] = t->unbounded[i];
  uint32_t stack[64];
  int sp = 0;
  stack[sp++] = 0;
  while (sp > 0) {
    const csg_tree_node *nd = &t->nodes[stack[--sp]];
    if (!ray_meets_box(nd->lo, nd->hi, ray, tmin, tmax))
      continue;
    if (nd->count > 0) {
      if (n + (int)nd->count > QUERY_MAX)
        return -1;
      for (uint32_t i = 0; i < nd->count; i++)
        out[n++] = t->order[nd->first + i];
      continue;
    }
    if (sp + 2 > 64)
      return -1;
    stack[sp++] = nd->right;
    stack[sp++] = (uint32_t)(nd - t->nodes) + 1;
  }
  if (n > 1)
    qsort(out, (size_t)n, sizeof *out, by_index);
  return n;
}

/* Whether some child of node other than self holds p, as zr__inside
   finds (merge and union). */
static bool some_other_holds(const zr_object *node, size_t self, zr_vec3 p);

/*
 * Planes are most of what polyhedra are made of (shapes2.inc's
 * Dodecahedron: twelve planes, each turned by its own transform; stock
 * textures/pigments/dodec2.pov spent 70% of its time in them), and a
 * plane's test is a dot product: for a plane without a clip the two
 * functions below do what intersect.c and obj_plane.c do (the same
 * arithmetic in the same order, so the same bits) without the table's
 * calls, the crossing list and the matrix product as a call.
 */
static inline zr_vec3 plane_local(const zr_object *o, zr_vec3 p) {
  if (!o->transform)
    return p;
  const double(*m)[4] = o->transform->inv; /* as zr__xform_point */
  return zr_v3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
               m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
               m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

static inline bool plain_plane(const zr_object *o) {
  return o->kind == ZR_OBJ_PLANE && !o->clip;
}

/* zr__inside() of a plain_plane. */
static inline bool plane_holds(const zr_object *o, zr_vec3 p) {
  zr_vec3 q = plane_local(o, p);
  return (zr_v3_dot(q, o->u.plane.normal) <= o->u.plane.distance) !=
         o->inverse;
}

/* zr__intersect_all() of a plain_plane without normals: its one
   crossing in (tmin, tmax), if any, into h. */
static int plane_crossing(const zr_object *o, const zr_ray *ray,
                          double tmin, double tmax, zr_hit *h) {
  zr_vec3 org = ray->origin, dir = ray->dir;
  if (o->transform) {
    const double(*m)[4] = o->transform->inv; /* as zr__xform_dir */
    org = plane_local(o, org);
    dir = zr_v3(m[0][0] * dir.x + m[0][1] * dir.y + m[0][2] * dir.z,
                m[1][0] * dir.x + m[1][1] * dir.y + m[1][2] * dir.z,
                m[2][0] * dir.x + m[2][1] * dir.y + m[2][2] * dir.z);
  }
  zr_vec3 n = o->u.plane.normal;
  double dn = zr_v3_dot(n, dir);
  if (zr__plane_parallel(dn, dir))
    return 0;
  double t = (o->u.plane.distance - zr_v3_dot(n, org)) / dn;
  if (!isfinite(t) || !(t > tmin && t < tmax))
    return 0;
  h->t = t;
  h->normal = zr_v3(0, 0, 0);
  h->object = o;
  h->u = h->v = 0.0;
  return 1;
}

/* zr__inside() of child j of a CSG node, with its box first: outside
   it the child holds nothing, or (a part cut out) everything. */
static bool child_inside(const zr_object *node, size_t j, zr_vec3 p) {
  const struct zr_csg_box *b = node->u.csg.boxes;
  if (b && b[j].bounded && !box_holds(b[j].lo, b[j].hi, p))
    return b[j].holds_outside;
  const zr_object *c = node->u.csg.children[j];
  if (plain_plane(c))
    return plane_holds(c, p);
  return zr__inside(c, p);
}

/* Every crossing of a leaf primitive in (tmin, tmax).  A leaf is asked
   again beyond its last crossing unless it said it had no more: the
   corpus' complexity.pov asked its boxes and cylinders twice each, 20.7
   million askings for 10.4 million CSG tests. */
static void gather_leaf(gather *g, const zr_object *leaf, double tmin) {
  zr_hit h[ZR_MAX_CROSSINGS];
  if (!g->want_normals && plain_plane(leaf)) {
    if (g->n < CSG_MAX_GATHER)
      g->n += plane_crossing(leaf, g->ray, tmin, g->tmax, &g->hit[g->n]);
    return;
  }
  for (;;) {
    bool all;
    int k = zr__intersect_all(leaf, g->ray, tmin, g->tmax, g->want_normals,
                              h, &all);
    for (int i = 0; i < k && g->n < CSG_MAX_GATHER; i++)
      g->hit[g->n++] = h[i];
    if (all || k < ZR_MAX_CROSSINGS || !(h[k - 1].t > tmin))
      return;
    tmin = h[k - 1].t;
  }
}

/* Whether a point on child `self`'s surface is on node's surface, as far
   as node's other children decide. */
static bool keep(const zr_object *node, size_t self, zr_vec3 p) {
  if (node->kind == ZR_OBJ_UNION)
    return true;
  if (node->kind == ZR_OBJ_MERGE && node->u.csg.tree)
    return !some_other_holds(node, self, p);
  bool want_inside = node->kind == ZR_OBJ_INTERSECTION;
  for (size_t j = 0; j < node->u.csg.n_children; j++)
    if (j != self && child_inside(node, j, p) != want_inside)
      return false;
  return true;
}

/*
 * The top node's crossings are final once kept (no node above it can
 * drop them), so when the caller wants only its nearest `wanted`, a
 * crossing beyond the wanted-th nearest kept so far cannot be reported:
 * the search interval ends there for the children still to come, whose
 * boxes then often miss it (a difference of a box and fifty cylinders
 * asks few of them once the box's face is kept).  The kept crossings
 * and their order stay what they were: a crossing at the new tmax ties
 * with an earlier one, which the selection in zr__csg_crossings prefers.
 * Not with a clip on the top node, which may still drop them.
 */
static void shrink(gather *g, int start) {
  double best[ZR_MAX_CROSSINGS];
  int n = 0;
  for (int k = start; k < g->n; k++) {
    double t = g->hit[k].t;
    int j = n < g->wanted ? n++ : g->wanted;
    if (j == g->wanted) {
      if (t >= best[j - 1])
        continue;
      j--;
    }
    while (j > 0 && best[j - 1] > t) {
      best[j] = best[j - 1];
      j--;
    }
    best[j] = t;
  }
  if (n == g->wanted && best[n - 1] < g->tmax)
    g->tmax = best[n - 1];
}

/*
 * An intersection keeps a crossing only where every other child holds
 * it, so never outside another child's box: a child's crossings that
 * matter lie where the ray is in all the other children's boxes, and it
 * is asked for those alone.  The corpus' complexity.pov (a tall
 * cylinder minus another, cut by a box, in each of 800 tiles) passed
 * half of its 20 million crossings to the inside tests only for the
 * box's inside test to drop them.  Each span is taken of the box grown
 * by a hair and then widened by another, more than the rounding of
 * point_at() and of the slab divisions, so that a crossing that the
 * inside tests keep is always in the interval: the crossings kept are
 * the same, only fewer are tried.
 */
#define NARROW_MAX 8

typedef struct narrowed {
  double lo[NARROW_MAX], hi[NARROW_MAX];
} narrowed;

/* One axis of slack_span: narrows (*a, *c) to the slab [l, h] of the
   ray o + t d (inv = 1 / d); false when a ray parallel to it is
   outside. */
static inline bool slack_slab(double o, double d, double inv, double l,
                              double h, double *a, double *c) {
  if (d == 0.0)
    return o >= l && o <= h;
  double t0 = (l - o) * inv, t1 = (h - o) * inv;
  if (t0 > t1) {
    double tt = t0;
    t0 = t1;
    t1 = tt;
  }
  *a = t0 > *a ? t0 : *a;
  *c = t1 < *c ? t1 : *c;
  return true;
}

/* The span of the ray in box b grown by a hair, widened by another;
   (-inf, inf) for a child with no box, and an empty one (lo > hi) when
   it misses. */
static void slack_span(const gather *g, const struct zr_csg_box *b,
                       double *lo, double *hi) {
  *lo = -INFINITY;
  *hi = INFINITY;
  if (!b->bounded)
    return;
  double big = g->origin_size +
               zr_v3_max_comp(zr_v3_max(zr_v3_neg(b->lo), b->hi));
  double pad = 1e-9 * big;
  const zr_vec3 o = g->ray->origin, d = g->ray->dir, inv = g->inv_dir;
  double a = -INFINITY, c = INFINITY;
  if (!(big < INFINITY) ||
      !slack_slab(o.x, d.x, inv.x, b->lo.x - pad, b->hi.x + pad, &a, &c) ||
      !slack_slab(o.y, d.y, inv.y, b->lo.y - pad, b->hi.y + pad, &a, &c) ||
      !slack_slab(o.z, d.z, inv.z, b->lo.z - pad, b->hi.z + pad, &a, &c)) {
    if (big < INFINITY) {
      *lo = INFINITY;
      *hi = -INFINITY;
    }
    return;
  }
  if (!(a <= c)) {
    *lo = INFINITY;
    *hi = -INFINITY;
    return;
  }
  double m = 1e-9 * (fabs(a) + fabs(c));
  *lo = a - m;
  *hi = c + m;
}

/* For each child i of intersection o, the interval (tmin, tmax)
   narrowed to its own span and the other children's (but for parts cut
   out, whose inside is outside their box); false when o has too many
   children for this (or none with a box). */
static bool narrow_children(const gather *g, const zr_object *o,
                            double tmin, narrowed *nw) {
  size_t n = o->u.csg.n_children;
  if (o->kind != ZR_OBJ_INTERSECTION || !o->u.csg.boxes || n > NARROW_MAX ||
      n < 2)
    return false;
  double lo[NARROW_MAX], hi[NARROW_MAX];
  bool any = false;
  for (size_t i = 0; i < n; i++) {
    slack_span(g, &o->u.csg.boxes[i], &lo[i], &hi[i]);
    any = any || o->u.csg.boxes[i].bounded;
  }
  if (!any)
    return false;
  for (size_t i = 0; i < n; i++) {
    double a = tmin, b = g->tmax;
    for (size_t j = 0; j < n; j++) {
      /* A part cut out holds everything outside its box: its box
         bounds its own crossings only. */
      if (j == i || o->u.csg.boxes[j].holds_outside)
        continue;
      a = lo[j] > a ? lo[j] : a;
      b = hi[j] < b ? hi[j] : b;
    }
    /* The child's own crossings lie in its own box, as the test of
       each child's box below assumes. */
    nw->lo[i] = lo[i] > a ? lo[i] : a;
    nw->hi[i] = hi[i] < b ? hi[i] : b;
  }
  return true;
}

static void gather_node(gather *g, const zr_object *o, double tmin) {
  int start = g->n;
  if (!zr__is_csg(o->kind)) {
    gather_leaf(g, o, tmin);
    return; /* a leaf's own clip is applied by zr__intersect */
  }
  narrowed nw;
  bool narrow = !o->u.csg.tree && narrow_children(g, o, tmin, &nw);
  uint32_t chosen[QUERY_MAX];
  int n_chosen = -1;
  if (o->u.csg.tree)
    n_chosen = tree_ray(o->u.csg.tree, g->ray, tmin, g->tmax, chosen);
  size_t n_loop = n_chosen >= 0 ? (size_t)n_chosen : o->u.csg.n_children;
  for (size_t c = 0; c < n_loop; c++) {
    size_t i = n_chosen >= 0 ? chosen[c] : c;
    if (narrow ? !(nw.lo[i] < nw.hi[i])
               : o->u.csg.boxes &&
                     !ray_meets(&o->u.csg.boxes[i], g->ray, tmin, g->tmax))
      continue;
    int first = g->n;
    if (narrow) {
      /* Only this node's children see the narrowed end: no shrink()
         happens below the top node, and an intersection has none. */
      double tmax = g->tmax;
      g->tmax = nw.hi[i];
      gather_node(g, o->u.csg.children[i], nw.lo[i]);
      g->tmax = tmax;
    } else {
      gather_node(g, o->u.csg.children[i], tmin);
    }
    /* Compact the child's crossings to those on this node's surface. */
    int kept = first;
    for (int k = first; k < g->n; k++)
      if (keep(o, i, point_at(g->ray, g->hit[k].t)))
        g->hit[kept++] = g->hit[k];
    g->n = kept;
    if (o == g->top && !o->clip && kept > first &&
        o->kind != ZR_OBJ_INTERSECTION)
      shrink(g, start); /* an intersection's later ties win (below) */
  }
  if (o->clip) {
    int kept = start;
    for (int k = start; k < g->n; k++)
      if (zr__inside(o->clip, point_at(g->ray, g->hit[k].t)))
        g->hit[kept++] = g->hit[k];
    g->n = kept;
  }
}

int zr__csg_crossings(const zr_object *object, const zr_ray *ray,
                      double tmin, double tmax, bool want_normals,
                      int wanted, zr_hit hits[ZR_MAX_CROSSINGS]) {
  gather g;
  g.ray = ray;
  g.tmax = tmax;
  g.want_normals = want_normals;
  g.top = object;
  g.wanted = wanted < 1 ? 1 : wanted > ZR_MAX_CROSSINGS ? ZR_MAX_CROSSINGS
                                                        : wanted;
  g.n = 0;
  g.inv_dir = zr_v3(1.0 / ray->dir.x, 1.0 / ray->dir.y, 1.0 / ray->dir.z);
  g.origin_size = 1.0 + zr_v3_max_comp(zr_v3_max(zr_v3_neg(ray->origin),
                                                  ray->origin));
  gather_node(&g, object, tmin);
  /* The nearest ZR_MAX_CROSSINGS, sorted, by selection: lists are
     short and only two are wanted.  Of crossings at the same distance
     (a face two children share) a union or merge shows its earlier
     child's and an intersection or difference its later child's, as
     POV-Ray 3.7 does (tests/legacy/csg_shared_face.pov). */
  bool later = object->kind == ZR_OBJ_INTERSECTION;
  int n = 0;
  for (; n < ZR_MAX_CROSSINGS; n++) {
    int best = -1;
    for (int k = n; k < g.n; k++)
      if (best < 0 || g.hit[k].t < g.hit[best].t ||
          (later && g.hit[k].t == g.hit[best].t))
        best = k;
    if (best < 0)
      break;
    zr_hit t = g.hit[n];
    g.hit[n] = g.hit[best];
    g.hit[best] = t;
    hits[n] = g.hit[n];
  }
  return n;
}

static bool some_other_holds(const zr_object *node, size_t self,
                             zr_vec3 p) {
  const struct zr_csg_tree *t = node->u.csg.tree;
  const struct zr_csg_box *b = node->u.csg.boxes;
  for (uint32_t i = 0; i < t->n_unbounded; i++)
    if (t->unbounded[i] != self && child_inside(node, t->unbounded[i], p))
      return true;
  for (uint32_t i = 0; i < t->n_outside; i++)
    if (t->outside[i] != self && child_inside(node, t->outside[i], p))
      return true;
  uint32_t stack[64];
  int sp = 0;
  stack[sp++] = 0;
  while (sp > 0) {
    const csg_tree_node *nd = &t->nodes[stack[--sp]];
    if (!box_holds(nd->lo, nd->hi, p))
      continue;
    if (nd->count > 0) {
      for (uint32_t i = 0; i < nd->count; i++) {
        uint32_t j = t->order[nd->first + i];
        if (j != self && !b[j].holds_outside && child_inside(node, j, p))
          return true;
      }
      continue;
    }
    if (sp + 2 > 64) { /* deeper than any tree of 2^32 children */
      for (size_t j = 0; j < node->u.csg.n_children; j++)
        if (j != self && child_inside(node, j, p))
          return true;
      return false;
    }
    stack[sp++] = nd->right;
    stack[sp++] = (uint32_t)(nd - t->nodes) + 1;
  }
  return false;
}

bool zr__csg_inside(const zr_object *object, zr_vec3 p) {
  bool in;
  if (object->kind != ZR_OBJ_INTERSECTION && object->u.csg.tree) {
    in = some_other_holds(object, SIZE_MAX, p);
  } else if (object->kind == ZR_OBJ_INTERSECTION) {
    in = object->u.csg.n_children > 0;
    for (size_t i = 0; in && i < object->u.csg.n_children; i++)
      in = child_inside(object, i, p);
  } else {
    in = false;
    for (size_t i = 0; !in && i < object->u.csg.n_children; i++)
      in = child_inside(object, i, p);
  }
  if (in && object->clip)
    in = zr__inside(object->clip, p);
  return in != object->inverse;
}

/* CSG objects are traced whole by the functions above, before any
   transform (their children carry theirs); the table gives their names
   and their inside test (lib/trace/shape.h). */
const zr_shape_ops zr__shape_union = {
    .name = "a union",
    .inside = zr__csg_inside,
};
const zr_shape_ops zr__shape_intersection = {
    .name = "an intersection or difference",
    .inside = zr__csg_inside,
};
const zr_shape_ops zr__shape_merge = {
    .name = "a merge",
    .inside = zr__csg_inside,
};
