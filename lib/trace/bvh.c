/*
 * bvh.c - a bounding volume hierarchy of axis-aligned boxes, built top
 * down with the binned surface area heuristic (Wald, "On fast
 * Construction of SAH-based Bounding Volume Hierarchies", 2007).
 *
 * Each node's primitives are sorted into 16 bins by the centre of
 * their boxes along the widest axis of those centres; the split between
 * buckets that minimises  A_left * N_left + A_right * N_right  (areas of
 * the child boxes, the expected number of intersection tests for a ray
 * that hits the node) wins, unless a leaf is cheaper; that sweep,
 * zr__sah_sweep, serves each mesh's hierarchy too.  Nodes live in one
 * array in depth-first order: an inner node's left child follows it and
 * its right child's index is stored.
 *
 * Primitives with no finite box (planes, inverse objects) cannot be
 * bounded, so they sit in a separate list that every ray tests.  The
 * binary tree is then collapsed into one of four children a node
 * (zr_wide_node below), which the tracer walks: nearest child first,
 * skipping boxes beyond the nearest crossing found so far, or for
 * shadow rays every leaf met in the tree's left-to-right order.
 */
#include "trace/bvh.h"
#include "trace/bvh_wide.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/arena.h"
#include "core/context.h"
#include "trace/obj_mesh.h"
#include "trace/obj_shapes.h"
#include "trace/shape.h"

enum {
  LEAF_MAX = 4,     /* a node this small is always a leaf */
  DEPTH_MAX = 60,   /* beyond this splits fall back to the median */
  STACK_MAX = 128,
  WIDTH = ZR_WIDE_WIDTH,
  /* A wide node pushes at most WIDTH - 1 more entries than it pops, and
     the wide tree is at most as deep as the binary one. */
  WIDE_STACK_MAX = (WIDTH - 1) * STACK_MAX + 1
};

/*
 * A bounded primitive's sphere, if it is a plain one (no transform, no
 * clip), beside prims[] in leaf order; radius is a NaN for any other
 * primitive.  A leaf's spheres are then tested from 32 contiguous bytes
 * each rather than from their objects, where kind, transform, clip and
 * the shape's data lie on three cache lines: bench/peers.sh's
 * sphereflake is 7,381 spheres, and its rays test mostly spheres.
 */
typedef struct leaf_sphere {
  zr_vec3 centre;
  double radius;
} leaf_sphere;

struct zr_bvh {
  size_t n_nodes, n_leaves; /* of the binary tree, for statistics */
  zr_wide_node *wide; /* the tree the tracer walks; wide[0] is the root */
  size_t n_wide;
  const zr_object **prims; /* bounded primitives in leaf order */
  leaf_sphere *spheres;    /* beside prims (see leaf_sphere) */
  size_t n_prims;
  const zr_object **unbounded;
  size_t n_unbounded;
  /* Where each of prims and of unbounded is in scene->primitives. */
  uint32_t *prim_index, *unbounded_index;
  int depth;
};

/* A primitive's box while building; its centre is computed where it
   is needed (centre_of), and its object is found from its index at the
   end.  The split moves items about at every level of the tree: 56
   bytes where the centre and the object pointer made 88. */
typedef struct build_item {
  double lo[3], hi[3];
  uint32_t index; /* in scene->primitives */
} build_item;

/* The centre of an item's box along axis a: the same expression, so the
   same double, as when it was stored beside the box. */
static inline double centre_of(const build_item *it, int a) {
  return 0.5 * (it->lo[a] + it->hi[a]);
}

typedef struct box3 {
  double lo[3], hi[3];
} box3;

/* A sphere the tracer may test without its table of operations (see
   sphere_t below). */
static inline bool plain_sphere(const zr_object *o) {
  return o->kind == ZR_OBJ_SPHERE && !o->transform && !o->clip &&
         !o->bound_cuts;
}

static void box_empty(box3 *b) {
  for (int i = 0; i < 3; i++) {
    b->lo[i] = INFINITY;
    b->hi[i] = -INFINITY;
  }
}

/* fmin and fmax as glibc computes them (the second operand when the
   two are equal, the other one when one is a NaN), in comparisons that
   -O2 keeps inline where fmin and fmax stay calls: the builder's boxes
   are the same floats, bit for bit, a few times faster. */
static inline double min_of(double a, double b) {
  return a < b || b != b ? a : b;
}

static inline double max_of(double a, double b) {
  return a > b || b != b ? a : b;
}

static inline void box_grow(box3 *b, const double lo[3],
                            const double hi[3]) {
  for (int i = 0; i < 3; i++) {
    b->lo[i] = min_of(b->lo[i], lo[i]);
    b->hi[i] = max_of(b->hi[i], hi[i]);
  }
}

/*
 * min_of and max_of where no operand is a NaN (nan_free: the build's
 * items, their centres and so every box made of them hold none, which
 * zr__bvh_build checks once): then they are a < b ? a : b and
 * a > b ? a : b, the same double, which x86-64 computes in one
 * instruction (minsd, maxsd) where the NaN test took a compare and a
 * branch more.  The loops over the three axes are written out: -O2 did
 * not unroll them.  These tests and the loop counters were 11 M of the
 * 16 M instructions the splits of bench/peers.sh's sphereflake (7,381
 * spheres) took (callgrind).
 */
static inline __attribute__((always_inline)) double
pick_min(double a, double b, bool nan_free) {
  return nan_free ? (a < b ? a : b) : min_of(a, b);
}

static inline __attribute__((always_inline)) double
pick_max(double a, double b, bool nan_free) {
  return nan_free ? (a > b ? a : b) : max_of(a, b);
}

static inline __attribute__((always_inline)) void
grow3(double lo[3], double hi[3], const double add_lo[3],
      const double add_hi[3], bool nan_free) {
  lo[0] = pick_min(lo[0], add_lo[0], nan_free);
  lo[1] = pick_min(lo[1], add_lo[1], nan_free);
  lo[2] = pick_min(lo[2], add_lo[2], nan_free);
  hi[0] = pick_max(hi[0], add_hi[0], nan_free);
  hi[1] = pick_max(hi[1], add_hi[1], nan_free);
  hi[2] = pick_max(hi[2], add_hi[2], nan_free);
}

/* The axes written out, as in grow3 below: -O2 kept the loop (the
   SAH sweep takes 30 areas a node). */
static inline double box_area(const box3 *b) {
  double d0 = b->hi[0] > b->lo[0] ? b->hi[0] - b->lo[0] : 0.0;
  double d1 = b->hi[1] > b->lo[1] ? b->hi[1] - b->lo[1] : 0.0;
  double d2 = b->hi[2] > b->lo[2] ? b->hi[2] - b->lo[2] : 0.0;
  return 2.0 * (d0 * d1 + d1 * d2 + d2 * d0);
}

typedef struct builder {
  build_item *items;
  bool nan_free; /* no item's box or centre holds a NaN (pick_min) */
  uint8_t *bins; /* each item's bin in the split being made */
  void *scratch; /* items, bins and nodes in one block */
  zr_bvh_bin_node *nodes;
  size_t n_nodes, cap_nodes;
  int depth;
} builder;

/* qsort comparators by centre, one per axis, so no state is shared. */
#define CMP_CENTRE(axis)                                                   \
  static int cmp_centre_##axis(const void *pa, const void *pb) {           \
    double a = centre_of(pa, axis);                                        \
    double b = centre_of(pb, axis);                                        \
    return (a > b) - (a < b);                                              \
  }
CMP_CENTRE(0)
CMP_CENTRE(1)
CMP_CENTRE(2)
#undef CMP_CENTRE

static void sort_by_axis(build_item *items, size_t n, int axis) {
  static int (*const cmp[3])(const void *, const void *) = {
      cmp_centre_0, cmp_centre_1, cmp_centre_2};
  qsort(items, n, sizeof *items, cmp[axis]);
}

static zr_status new_node(builder *b, size_t *index) {
  /* The room holds the most nodes a tree of n leaves has, 2 n - 1. */
  if (b->n_nodes == b->cap_nodes)
    return ZR_ELIMIT;
  *index = b->n_nodes++;
  return ZR_OK;
}

/* box_grow with plain comparisons, which -O2 makes instructions where
   fmin and fmax stay calls: the sweep runs once per node of a
   million-triangle mesh.  (The sweep's boxes hold no NaN.) */
static inline void sweep_grow(box3 *b, const double lo[3],
                              const double hi[3]) {
  b->lo[0] = lo[0] < b->lo[0] ? lo[0] : b->lo[0];
  b->lo[1] = lo[1] < b->lo[1] ? lo[1] : b->lo[1];
  b->lo[2] = lo[2] < b->lo[2] ? lo[2] : b->lo[2];
  b->hi[0] = hi[0] > b->hi[0] ? hi[0] : b->hi[0];
  b->hi[1] = hi[1] > b->hi[1] ? hi[1] : b->hi[1];
  b->hi[2] = hi[2] > b->hi[2] ? hi[2] : b->hi[2];
}

int zr__sah_sweep(const zr_sah_bin bins[ZR_SAH_BINS], size_t n,
                  double *cost) {
  /* Sweep from the right to know the right side's cost of every split,
     then from the left to find the cheapest. */
  double right_cost[ZR_SAH_BINS] = {0};
  box3 acc;
  box_empty(&acc);
  size_t acc_n = 0;
  /* A split k after an empty bin k - 1 has the sides, so the cost, of
     split k - 1, which the strict < below keeps: only the splits after
     a bin that holds something are costed (the same best k and cost;
     a node of a few primitives has most of its bins empty). */
  for (int k = ZR_SAH_BINS - 1; k > 0; k--) {
    if (bins[k].count)
      sweep_grow(&acc, bins[k].lo, bins[k].hi);
    acc_n += bins[k].count;
    if (bins[k - 1].count)
      right_cost[k] = acc_n ? box_area(&acc) * (double)acc_n : 0.0;
  }
  double best = INFINITY;
  int best_k = -1;
  box_empty(&acc);
  acc_n = 0;
  for (int k = 1; k < ZR_SAH_BINS; k++) {
    if (!bins[k - 1].count)
      continue;
    sweep_grow(&acc, bins[k - 1].lo, bins[k - 1].hi);
    acc_n += bins[k - 1].count;
    if (acc_n == 0 || acc_n == n)
      continue;
    double c = box_area(&acc) * (double)acc_n + right_cost[k];
    if (c < best) {
      best = c;
      best_k = k;
    }
  }
  *cost = best;
  return best_k;
}

static int bin_of(double c, double lo, double scale) {
  int k = (int)((c - lo) * scale);
  return k < 0 ? 0 : k >= ZR_SAH_BINS ? ZR_SAH_BINS - 1 : k;
}

/* A node's box and the box of its primitives' centres. */
typedef struct node_boxes {
  box3 bounds, centres;
} node_boxes;

static inline __attribute__((always_inline)) void
boxes_with(const build_item *items, size_t n, node_boxes *out,
           bool nan_free) {
  box_empty(&out->bounds);
  box_empty(&out->centres);
  for (size_t i = 0; i < n; i++) {
    double c[3] = {centre_of(&items[i], 0), centre_of(&items[i], 1),
                   centre_of(&items[i], 2)};
    grow3(out->bounds.lo, out->bounds.hi, items[i].lo, items[i].hi,
          nan_free);
    grow3(out->centres.lo, out->centres.hi, c, c, nan_free);
  }
}

static void boxes_of(const build_item *items, size_t n, node_boxes *out,
                     bool nan_free) {
  if (nan_free)
    boxes_with(items, n, out, true);
  else
    boxes_with(items, n, out, false);
}

/* The binning of sah_split below: each item's bin in bin_ids, each
   bin's count and box, and the box of its items' centres. */
static inline __attribute__((always_inline)) void
bin_items(const build_item *items, uint8_t *bin_ids, size_t n, int axis,
          double lo, double scale, zr_sah_bin bins[ZR_SAH_BINS],
          box3 bin_centres[ZR_SAH_BINS], bool nan_free) {
  for (size_t i = 0; i < n; i++) {
    double c[3] = {centre_of(&items[i], 0), centre_of(&items[i], 1),
                   centre_of(&items[i], 2)};
    int k = bin_of(c[axis], lo, scale);
    bin_ids[i] = (uint8_t)k; /* for the partition */
    zr_sah_bin *bin = &bins[k];
    bin->count++;
    grow3(bin->lo, bin->hi, items[i].lo, items[i].hi, nan_free);
    grow3(bin_centres[k].lo, bin_centres[k].hi, c, c, nan_free);
  }
}

/*
 * Chooses where to split items[0..n) by the binned SAH.  Returns the
 * number that go left (0 when a leaf is cheaper or no split separates
 * anything), reordering items so those come first; sides gets the boxes
 * of both sides, the unions of their bins' (the values a pass over each
 * side would find, so the children make none).
 */
static size_t sah_split(build_item *items, uint8_t *bin_ids, size_t n,
                        const node_boxes *node, node_boxes sides[2],
                        bool nan_free) {
  const box3 *bounds = &node->bounds;
  box3 cb = node->centres;
  int axis = 0;
  double ext = -1.0;
  for (int a = 0; a < 3; a++)
    if (cb.hi[a] - cb.lo[a] > ext) {
      ext = cb.hi[a] - cb.lo[a];
      axis = a;
    }
  if (!(ext > 0.0))
    return 0;
  zr_sah_bin bins[ZR_SAH_BINS];
  box3 bin_centres[ZR_SAH_BINS];
  for (int i = 0; i < ZR_SAH_BINS; i++) {
    for (int a = 0; a < 3; a++) {
      bins[i].lo[a] = INFINITY;
      bins[i].hi[a] = -INFINITY;
    }
    bins[i].count = 0;
    box_empty(&bin_centres[i]);
  }
  double scale = ZR_SAH_BINS / ext;
  if (nan_free)
    bin_items(items, bin_ids, n, axis, cb.lo[axis], scale, bins,
              bin_centres, true);
  else
    bin_items(items, bin_ids, n, axis, cb.lo[axis], scale, bins,
              bin_centres, false);
  double best;
  int best_k = zr__sah_sweep(bins, n, &best);
  if (best_k < 0)
    return 0;
  /* A traversal step costs about as much as one intersection test. */
  double leaf_cost = box_area(bounds) * (double)n;
  double split_cost = box_area(bounds) + best;
  if (n <= 16 && split_cost >= leaf_cost)
    return 0;
  for (int side = 0; side < 2; side++) {
    box_empty(&sides[side].bounds);
    box_empty(&sides[side].centres);
  }
  /* grow3's plain comparisons where no box holds a NaN, as in the
     binning: box_grow's NaN tests here were 2.1 M of the 17.8 M
     instructions bench/peers.sh's sphereflake's build took
     (callgrind). */
  for (int k = 0; k < ZR_SAH_BINS; k++) {
    node_boxes *side = &sides[k >= best_k];
    if (!bins[k].count)
      continue;
    if (nan_free) {
      grow3(side->bounds.lo, side->bounds.hi, bins[k].lo, bins[k].hi, true);
      grow3(side->centres.lo, side->centres.hi, bin_centres[k].lo,
            bin_centres[k].hi, true);
    } else {
      box_grow(&side->bounds, bins[k].lo, bins[k].hi);
      box_grow(&side->centres, bin_centres[k].lo, bin_centres[k].hi);
    }
  }
  /* The items of bins [0, best_k) go first, in the order a swap with the
     first right-hand item gives.  bin_ids[i] is read only for the item
     that the binning found at i: a swap moves to i an item already
     passed. */
  size_t left = 0;
  for (size_t i = 0; i < n; i++) {
    if (bin_ids[i] < best_k) {
      build_item t = items[i];
      items[i] = items[left];
      items[left] = t;
      left++;
    }
  }
  return left;
}

/* Splits at the median centre along the widest axis. */
static size_t median_split(build_item *items, size_t n) {
  box3 cb;
  box_empty(&cb);
  for (size_t i = 0; i < n; i++) {
    double c[3] = {centre_of(&items[i], 0), centre_of(&items[i], 1),
                   centre_of(&items[i], 2)};
    box_grow(&cb, c, c);
  }
  int axis = 0;
  for (int a = 1; a < 3; a++)
    if (cb.hi[a] - cb.lo[a] > cb.hi[axis] - cb.lo[axis])
      axis = a;
  sort_by_axis(items, n, axis);
  return n / 2;
}

/* The node of items [first, first + n); known (NULL: not known) holds
   its boxes when its parent's split found them. */
static zr_status build_node(builder *b, size_t first, size_t n, int depth,
                            const node_boxes *known) {
  size_t index;
  zr_status s = new_node(b, &index);
  if (s != ZR_OK)
    return s;
  if (depth > b->depth)
    b->depth = depth;
  node_boxes node;
  if (known)
    node = *known;
  else
    boxes_of(b->items + first, n, &node, b->nan_free);
  memcpy(b->nodes[index].lo, node.bounds.lo, sizeof node.bounds.lo);
  memcpy(b->nodes[index].hi, node.bounds.hi, sizeof node.bounds.hi);
  size_t left = 0;
  node_boxes sides[2];
  bool sides_known = false;
  if (n > LEAF_MAX) {
    if (depth < DEPTH_MAX) {
      left = sah_split(b->items + first, b->bins + first, n, &node, sides,
                       b->nan_free);
      sides_known = left > 0;
    } else {
      left = median_split(b->items + first, n);
    }
    /* Too many primitives sharing one centre: force a split so leaves
       stay small unless they are all truly coincident. */
    if (left == 0 && n > 16)
      left = median_split(b->items + first, n);
  }
  if (left == 0 || left == n) {
    b->nodes[index].first = (uint32_t)first;
    b->nodes[index].count = (uint32_t)n;
    return ZR_OK;
  }
  b->nodes[index].count = 0;
  s = build_node(b, first, left, depth + 1, sides_known ? &sides[0] : NULL);
  if (s != ZR_OK)
    return s;
  b->nodes[index].first = (uint32_t)b->n_nodes;
  return build_node(b, first + left, n - left, depth + 1,
                    sides_known ? &sides[1] : NULL);
}

static double node_area(const zr_bvh_bin_node *node) {
  box3 b;
  memcpy(b.lo, node->lo, sizeof b.lo);
  memcpy(b.hi, node->hi, sizeof b.hi);
  return box_area(&b);
}

/* The wide node for binary node root and, recursively, those below it;
   returns its index in out, of which *n_out are used so far. */
static uint32_t collapse(zr_wide_node *out, size_t *n_out,
                         const zr_bvh_bin_node *nodes, uint32_t root) {
  uint32_t index = (uint32_t)(*n_out)++;
  uint32_t kids[WIDTH];
  uint32_t n = 0;
  if (nodes[root].count > 0) {
    kids[n++] = root; /* a tree that is one leaf */
  } else {
    kids[n++] = root + 1;
    kids[n++] = nodes[root].first;
    /* Open the inner child of largest area, in place, so the children
       stay in the binary tree's left-to-right order. */
    while (n < WIDTH) {
      int best = -1;
      double best_area = -1.0;
      for (uint32_t k = 0; k < n; k++)
        if (nodes[kids[k]].count == 0 && node_area(&nodes[kids[k]]) >
                                             best_area) {
          best_area = node_area(&nodes[kids[k]]);
          best = (int)k;
        }
      if (best < 0)
        break;
      uint32_t open = kids[best];
      memmove(&kids[best + 2], &kids[best + 1],
              (n - (uint32_t)best - 1) * sizeof *kids);
      kids[best] = open + 1;
      kids[best + 1] = nodes[open].first;
      n++;
    }
  }
  zr_wide_node *w = &out[index];
  memset(w, 0, sizeof *w);
  float extent = 0.0f;
  for (uint32_t k = 0; k < WIDTH; k++)
    for (int a = 0; a < 3; a++) {
      if (k >= n) {
        /* An unused lane: a box no ray meets (zr__slab_entries). */
        w->lo[a][k] = w->hi[a][k] = NAN;
        continue;
      }
      w->lo[a][k] = zr__float_down(nodes[kids[k]].lo[a]);
      w->hi[a][k] = zr__float_up(nodes[kids[k]].hi[a]);
      extent = fmaxf(extent, fmaxf(fabsf(w->lo[a][k]),
                                   fabsf(w->hi[a][k])));
    }
  w->extent = extent;
  for (uint32_t k = n; k < WIDTH; k++)
    w->count[k] = ZR_WIDE_NO_CHILD;
  for (uint32_t k = 0; k < n; k++) {
    const zr_bvh_bin_node *b = &nodes[kids[k]];
    if (b->count > 0) {
      out[index].child[k] = b->first;
      out[index].count[k] = (uint16_t)b->count;
    } else {
      uint32_t c = collapse(out, n_out, nodes, kids[k]);
      out[index].child[k] = c;
      out[index].count[k] = 0;
    }
  }
  return index;
}

size_t zr__bvh_collapse(const zr_bvh_bin_node *nodes, zr_wide_node *out) {
  size_t n = 0;
  collapse(out, &n, nodes, 0);
  return n;
}

static zr_status build(zr_scene *scene, zr_context *ctx, bool fast_minmax);

zr_status zr__bvh_build(zr_scene *scene, zr_context *ctx) {
  return build(scene, ctx, true);
}

zr_status zr__bvh_build_nan_path(zr_scene *scene, zr_context *ctx) {
  return build(scene, ctx, false);
}

static zr_status build(zr_scene *scene, zr_context *ctx, bool fast_minmax) {
  zr__bvh_free(scene->bvh);
  scene->bvh = NULL;
  struct zr_bvh *bvh = calloc(1, sizeof *bvh);
  size_t n = scene->n_primitives;
  /* The build's own arrays (items, their bins, and room for the most
     nodes a tree of n leaves can have, 2 n - 1) in one block: the
     nodes no longer double and copy, and the items' 413 KB for 7,381
     spheres are filled in at once (core/arena.h, zr__mem_populate).
     (Huge pages took ~1 MB more peak memory for that scene.) */
  builder b = {0};
  size_t n_room = n ? n : 1;
  size_t items_size = n_room * sizeof *b.items;
  size_t nodes_at = (items_size + n_room + 63) & ~(size_t)63;
  if (n_room <= (SIZE_MAX / 4 - nodes_at) / sizeof *b.nodes) {
    b.cap_nodes = 2 * n_room - 1;
    /* From a megabyte of items on, huge pages as before (a huge page
       costs about what 15 small first touches do); below, the items and
       bins, all written, are filled in at once. */
    size_t room = nodes_at + b.cap_nodes * sizeof *b.nodes;
    b.scratch = nodes_at >= ZR__HUGE_FROM ? zr__huge_alloc(room)
                                          : malloc(room);
    if (b.scratch && nodes_at < ZR__HUGE_FROM)
      zr__mem_populate(b.scratch, nodes_at);
  }
  if (b.scratch) {
    b.items = b.scratch;
    b.bins = (uint8_t *)b.scratch + items_size;
    b.nodes = (zr_bvh_bin_node *)((char *)b.scratch + nodes_at);
  }
  build_item *items = b.items;
  if (bvh) {
    bvh->prims = malloc((n ? n : 1) * sizeof *bvh->prims);
    bvh->spheres = malloc((n ? n : 1) * sizeof *bvh->spheres);
    bvh->unbounded = malloc((n ? n : 1) * sizeof *bvh->unbounded);
    bvh->prim_index = malloc((n ? n : 1) * sizeof *bvh->prim_index);
    bvh->unbounded_index =
        malloc((n ? n : 1) * sizeof *bvh->unbounded_index);
  }
  zr_status s = ZR_ENOMEM;
  if (!bvh || !b.scratch || !bvh->prims || !bvh->spheres ||
      !bvh->unbounded || !bvh->prim_index || !bvh->unbounded_index)
    goto fail;
  if (n > UINT32_MAX / 2) {
    s = ZR_ELIMIT;
    goto fail;
  }
  size_t nb = 0;
  b.nan_free = fast_minmax;
  for (size_t i = 0; i < n; i++) {
    const zr_object *o = scene->primitives[i];
    zr_vec3 lo, hi;
    if (!zr__primitive_bounds(o, &lo, &hi)) {
      bvh->unbounded_index[bvh->n_unbounded] = (uint32_t)i;
      bvh->unbounded[bvh->n_unbounded++] = o;
      continue;
    }
    build_item *it = &items[nb++];
    it->lo[0] = lo.x, it->lo[1] = lo.y, it->lo[2] = lo.z;
    it->hi[0] = hi.x, it->hi[1] = hi.y, it->hi[2] = hi.z;
    it->index = (uint32_t)i;
    /* A NaN in a bound makes its centre one too. */
    for (int a = 0; a < 3; a++)
      if (centre_of(it, a) != centre_of(it, a))
        b.nan_free = false;
  }
  if (nb > 0) {
    s = build_node(&b, 0, nb, 0, NULL);
    if (s != ZR_OK)
      goto fail;
  }
  /* Written all through below: filled in at once (zr__mem_populate). */
  zr__mem_populate(bvh->prims, nb * sizeof *bvh->prims);
  zr__mem_populate(bvh->prim_index, nb * sizeof *bvh->prim_index);
  zr__mem_populate(bvh->spheres, nb * sizeof *bvh->spheres);
  for (size_t i = 0; i < nb; i++) {
    const zr_object *o = scene->primitives[items[i].index];
    bvh->prims[i] = o;
    bvh->prim_index[i] = items[i].index;
    bvh->spheres[i].centre = plain_sphere(o) ? o->u.sphere.centre
                                             : zr_v3(0, 0, 0);
    bvh->spheres[i].radius = plain_sphere(o) ? o->u.sphere.radius : NAN;
  }
  bvh->n_prims = nb;
  bvh->n_nodes = b.n_nodes;
  for (size_t i = 0; i < b.n_nodes; i++)
    bvh->n_leaves += b.nodes[i].count > 0;
  bvh->depth = b.depth;
  if (b.n_nodes > 0) {
    bvh->wide = zr__huge_alloc(b.n_nodes * sizeof *bvh->wide);
    if (!bvh->wide) {
      s = ZR_ENOMEM;
      goto fail;
    }
    bvh->n_wide = zr__bvh_collapse(b.nodes, bvh->wide);
    /* About a third of the room is used (a wide node takes up to three
       inner binary nodes): give the rest back. */
    zr_wide_node *fit = realloc(bvh->wide, bvh->n_wide * sizeof *fit);
    if (fit)
      bvh->wide = fit;
  }
  free(b.scratch);
  scene->bvh = bvh;
  return ZR_OK;
fail:
  free(b.scratch);
  zr__bvh_free(bvh);
  return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL,
                  "cannot build the bounding hierarchy: %s",
                  zr_status_str(s));
}

void zr__bvh_free(struct zr_bvh *bvh) {
  if (!bvh)
    return;
  free(bvh->wide);
  free(bvh->prims);
  free(bvh->spheres);
  free(bvh->unbounded);
  free(bvh->prim_index);
  free(bvh->unbounded_index);
  free(bvh);
}

static bool box_holds(const zr_wide_node *w, uint32_t c, zr_vec3 p) {
  return p.x >= w->lo[0][c] && p.x <= w->hi[0][c] && p.y >= w->lo[1][c] &&
         p.y <= w->hi[1][c] && p.z >= w->lo[2][c] && p.z <= w->hi[2][c];
}

static int cmp_index(const void *pa, const void *pb) {
  uint32_t a = *(const uint32_t *)pa, b = *(const uint32_t *)pb;
  return (a > b) - (a < b);
}

size_t zr__bvh_point_candidates(const struct zr_bvh *bvh, zr_vec3 p,
                                uint32_t *out, size_t cap) {
  if (!bvh)
    return 0;
  size_t n = 0;
  for (size_t i = 0; i < bvh->n_unbounded; i++, n++)
    if (n < cap)
      out[n] = bvh->unbounded_index[i];
  uint32_t stack[WIDE_STACK_MAX];
  int sp = 0;
  if (bvh->n_wide > 0)
    stack[sp++] = 0;
  while (sp > 0) {
    const zr_wide_node *w = &bvh->wide[stack[--sp]];
    for (uint32_t c = 0; c < WIDTH; c++) {
      if (w->count[c] == ZR_WIDE_NO_CHILD || !box_holds(w, c, p))
        continue;
      if (w->count[c] > 0) {
        for (uint32_t i = w->child[c]; i < w->child[c] + w->count[c];
             i++, n++)
          if (n < cap)
            out[n] = bvh->prim_index[i];
      } else if (sp < WIDE_STACK_MAX) {
        stack[sp++] = w->child[c];
      }
    }
  }
  if (n <= cap)
    qsort(out, n, sizeof *out, cmp_index);
  return n;
}

void zr__bvh_get_info(const struct zr_bvh *bvh, zr_bvh_info *info) {
  memset(info, 0, sizeof *info);
  if (!bvh)
    return;
  info->nodes = bvh->n_nodes;
  info->leaves = bvh->n_leaves;
  info->bounded = bvh->n_prims;
  info->unbounded = bvh->n_unbounded;
  info->depth = bvh->depth;
  /* FNV-1a over the primitives in leaf order and the shape's counts:
     a build that splits anywhere differently orders them differently. */
  uint64_t h = 14695981039346656037u;
  for (size_t i = 0; i < bvh->n_prims; i++)
    h = (h ^ bvh->prim_index[i]) * 1099511628211u;
  h = (h ^ bvh->n_nodes) * 1099511628211u;
  h = (h ^ bvh->n_leaves) * 1099511628211u;
  info->order_digest = (h ^ (uint64_t)bvh->depth) * 1099511628211u;
  /* The same over the wide nodes' bytes (boxes, children, counts). */
  h = 14695981039346656037u;
  const unsigned char *bytes = (const unsigned char *)bvh->wide;
  for (size_t i = 0; i < bvh->n_wide * sizeof *bvh->wide; i++)
    h = (h ^ bytes[i]) * 1099511628211u;
  info->node_digest = h;
}

/*
 * The crossings of a sphere that has no transform and no clip, without
 * normals, as zr__intersect_t finds them through obj_sphere.c: the same
 * arithmetic in the same order (the same roots, bit for bit), the same
 * filter and order, but without the table call and the crossing list.
 * Spheres are most of what a sphereflake's rays test.
 */
/* A ray as the sphere test wants it, made once for a walk: its
   direction's squared length, the quadratic's a, is the same for every
   sphere the walk tests. */
typedef struct sphere_ray {
  zr_vec3 origin, dir;
  double a;
} sphere_ray;

static inline void make_sphere_ray(const zr_ray *ray, sphere_ray *sr) {
  sr->origin = ray->origin;
  sr->dir = ray->dir;
  sr->a = zr_v3_dot(ray->dir, ray->dir);
}

/* Forced inline: with its early return for rays leaving the sphere GCC
   12 made it a call (callgrind, sphereflake 512^2: 80 M instructions in
   an out-of-line sphere_t). */
static inline __attribute__((always_inline)) int
sphere_t(const zr_object *o, zr_vec3 centre, double r, const sphere_ray *ray,
         double tmin, double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  zr_vec3 oc = zr_v3_sub(ray->origin, centre);
  double b = 2.0 * zr_v3_dot(ray->dir, oc);
  double c = zr_v3_dot(oc, oc) - r * r;
  /* The origin outside (c > 0) and the ray going away from the centre
     (b > 0): zr__solve_quadratic's q is then below 0 (or -0, or -inf),
     so q / a and c / q are at most -0 or not finite, and no root passes
     a tmin >= 0.  Such is the sphere a secondary ray leaves, tested by
     every shadow and reflected ray of the sphereflake (the first leaf
     it opens holds it); its line crosses the sphere, and the square
     root and the two divisions are not paid. */
  if (b > 0.0 && c > 0.0 && tmin >= 0.0)
    return 0;
  double t[2];
  if (zr__solve_quadratic(ray->a, b, c, t) != 2)
    return 0;
  int n = 0;
  for (int i = 0; i < 2; i++)
    if (isfinite(t[i]) && t[i] > tmin && t[i] < tmax) {
      hits[n].t = t[i];
      hits[n].normal = zr_v3(0, 0, 0);
      hits[n].object = o;
      hits[n].u = hits[n].v = 0.0;
      n++;
    }
  return n;
}

/* The same for a plane (obj_plane.c), the floor most scenes stand on,
   which every ray tests. */
static inline bool plain_plane(const zr_object *o) {
  return o->kind == ZR_OBJ_PLANE && !o->transform && !o->clip;
}

static inline __attribute__((always_inline)) int
plane_t_inline(const zr_object *o, const zr_ray *ray, double tmin,
               double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  zr_vec3 n = o->u.plane.normal;
  double dn = zr_v3_dot(n, ray->dir);
  double num = o->u.plane.distance - zr_v3_dot(n, ray->origin);
  /* A quotient of two non-zero numbers of opposite signs is negative
     (or -0 when it underflows, -inf when it overflows), never above a
     tmin >= 0: the ray leaves the plane behind, as every shadow ray
     from the sphereflake's floor and spheres to its lights does, and
     the division's latency (the walk waits on its answer; plane_t was
     3.3% of the sphereflake's CPU samples) is not paid.  Both this
     test and the parallel one below return no crossing, so this one,
     which needs no |dir|^2, comes first. */
  if (tmin >= 0.0 && ((num < 0.0 && dn > 0.0) || (num > 0.0 && dn < 0.0)))
    return 0;
  if (zr__plane_parallel(dn, ray->dir))
    return 0;
  double t = num / dn;
  if (!(isfinite(t) && t > tmin && t < tmax))
    return 0;
  hits[0].t = t;
  hits[0].normal = zr_v3(0, 0, 0);
  hits[0].object = o;
  hits[0].u = hits[0].v = 0.0;
  return 1;
}

static int plane_t(const zr_object *o, const zr_ray *ray, double tmin,
                   double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  return plane_t_inline(o, ray, tmin, tmax, hits);
}

static inline int crossings_t(const zr_object *o, const zr_ray *ray,
                              double tmin, double tmax,
                              zr_hit hits[ZR_MAX_CROSSINGS]) {
  if (plain_sphere(o)) {
    sphere_ray sr;
    make_sphere_ray(ray, &sr);
    return sphere_t(o, o->u.sphere.centre, o->u.sphere.radius, &sr, tmin,
                    tmax, hits);
  }
  if (plain_plane(o))
    return plane_t(o, ray, tmin, tmax, hits);
  return zr__intersect_t(o, ray, tmin, tmax, hits);
}

int zr__bvh_crossings_t(const zr_object *o, const zr_ray *ray, double tmin,
                        double tmax, zr_hit hits[ZR_MAX_CROSSINGS]) {
  return crossings_t(o, ray, tmin, tmax, hits);
}

/* Whether the search for the nearest surface takes o's crossing with
   its world normal at once: a julia_fractal's march, from the bounding
   sphere's entry to the crossing, is the cost, and asking for the
   winner's normal afterwards (zr__bvh_nearest) marched the whole way
   again (objects/fractal2.pov: 15% of the profile in that second march,
   against about a millionth of it for one julia_normal per candidate).
   The march's points do not depend on the interval (obj_julia.c), so
   the crossing asked for again from just before it would be this one,
   with the same normal: the image is the same bytes. */
static inline bool normal_at_once(const zr_object *o) {
  return o->kind == ZR_OBJ_JULIA && !o->clip;
}

/* The first of crossings_t's crossings, all the search for the nearest
   surface keeps: a mesh then prunes at its best crossing so far, and a
   julia_fractal's march stops at its first (zr__intersect_first).  A
   mesh's crossing comes with its normal in the mesh's space in
   *mesh_normal, and *from_mesh says so (otherwise false); a
   normal_at_once object's comes with its world normal in hits[]. */
static inline int first_crossing_t(const zr_object *o, const zr_ray *ray,
                                   double tmin, double tmax,
                                   zr_hit hits[ZR_MAX_CROSSINGS],
                                   zr_vec3 *mesh_normal, bool *from_mesh) {
  *from_mesh = o->kind == ZR_OBJ_MESH && !o->clip && !o->bound_cuts;
  if (*from_mesh)
    return zr__mesh_nearest_t(o, ray, tmin, tmax, hits, mesh_normal);
  if (plain_sphere(o) || plain_plane(o))
    return crossings_t(o, ray, tmin, tmax, hits);
  return zr__intersect_first(o, ray, tmin, tmax, normal_at_once(o), hits);
}

/* The nearest crossing without its normal; when a mesh's own search
   found it, *mesh_won is true and *mesh_normal holds the crossing's
   normal in the mesh's space. */
static bool nearest_t(const struct zr_bvh *bvh, const zr_ray *ray,
                      double tmin, double tmax, zr_hit *hit,
                      bool *mesh_won, zr_vec3 *mesh_normal,
                      bool *normal_won) {
  bool found = false;
  zr_hit h[ZR_MAX_CROSSINGS];
  zr_vec3 n_mesh = zr_v3(0, 0, 0);
  bool is_mesh;
  *mesh_won = false;
  *normal_won = false;
  for (size_t i = 0; i < bvh->n_unbounded; i++)
    /* A plain plane's test written in (see zr__bvh_all_blocked). */
    if ((plain_plane(bvh->unbounded[i])
             ? (is_mesh = false,
                plane_t_inline(bvh->unbounded[i], ray, tmin, tmax, h))
             : first_crossing_t(bvh->unbounded[i], ray, tmin, tmax, h,
                                &n_mesh, &is_mesh)) > 0) {
      *hit = h[0];
      tmax = h[0].t;
      found = true;
      *mesh_won = is_mesh;
      *mesh_normal = n_mesh;
      *normal_won = normal_at_once(bvh->unbounded[i]);
    }
  if (bvh->n_wide == 0)
    return found;
  zr_slab_ray sr;
  zr__make_slab_ray(ray, &sr);
  /* The interval in floats that hold it: tmax_f follows tmax. */
  const float tmin_f = zr__float_down(tmin);
  float tmax_f = zr__float_up(tmax);
  sphere_ray sph;
  make_sphere_ray(ray, &sph);
  /* Children beyond a crossing found meanwhile are skipped unopened.
     e is the entry searched now: the nearest child met of the node
     before, or the next on the stack. */
  zr_wide_entry stack[WIDE_STACK_MAX];
  int sp = 0;
  zr_wide_entry e = {0, 0, tmin_f};
  for (;;) {
    if (e.t < tmax) {
      if (e.count > 0) {
        for (uint32_t i = e.child; i < e.child + e.count; i++) {
          const leaf_sphere *s = &bvh->spheres[i];
          is_mesh = false;
          int n = s->radius == s->radius
                      ? sphere_t(bvh->prims[i], s->centre, s->radius, &sph,
                                 tmin, tmax, h)
                      : first_crossing_t(bvh->prims[i], ray, tmin, tmax, h,
                                         &n_mesh, &is_mesh);
          if (n > 0) {
            *hit = h[0];
            tmax = h[0].t;
            tmax_f = zr__float_up(tmax);
            found = true;
            *mesh_won = is_mesh;
            *mesh_normal = n_mesh;
            *normal_won = normal_at_once(bvh->prims[i]);
          }
        }
      } else {
        const zr_wide_node *w = &bvh->wide[e.child];
        float t[WIDTH];
        unsigned mask = zr__slab_entries(w, &sr, tmin_f, tmax_f, t);
        /* The nearest child met is searched first and shrinks tmax for
           the others. */
        if (mask) {
          sp = zr__wide_next_nearest_first(w, mask, t, stack, sp,
                                           WIDE_STACK_MAX, &e);
          continue;
        }
      }
    }
    if (sp == 0)
      break;
    e = stack[--sp];
  }
  return found;
}

bool zr__bvh_nearest(const struct zr_bvh *bvh, const zr_ray *ray,
                     double tmin, double tmax, zr_hit *hit) {
  if (!bvh)
    return false;
  double t0 = tmin;
  bool mesh_won, normal_won;
  zr_vec3 mesh_normal;
  bool found = nearest_t(bvh, ray, tmin, tmax, hit, &mesh_won, &mesh_normal,
                         &normal_won);
  if (!found)
    return false;
  /* A mesh's own search kept the winning face's normal: searching the
     mesh again over a sliver around hit->t (below) would find the same
     face, the nearest (least t, then least face) by the same arithmetic,
     and give the normal made here (zr__mesh_crossings 5.8% of
     bench/peers.sh's terrain at 1024^2 went to that second search). */
  if (mesh_won) {
    hit->normal = zr__mesh_world_normal(hit->object, mesh_normal);
    return true;
  }
  /* The winner's normal came with its crossing (normal_at_once). */
  if (normal_won)
    return true;
  /* A plain sphere or plane gives its normal as intersect.c would from
     the crossing at hit->t (found again there by the same arithmetic):
     the shape's normal at the point, normalized, turned for inverse. */
  const zr_object *o = hit->object;
  if (plain_sphere(o) || plain_plane(o)) {
    zr_vec3 n = plain_plane(o)
                    ? o->u.plane.normal
                    : zr_v3_sub(zr_v3_madd(ray->origin, ray->dir, hit->t),
                                o->u.sphere.centre);
    n = zr_v3_norm(n);
    hit->normal = o->inverse ? zr_v3_neg(n) : n;
    return true;
  }
  /* Only the winner's normal is needed: intersect it once more with
     normals, over an interval that still contains its crossing.  It
     starts just before that crossing: the winner may be a part of a CSG
     object whose first crossings the CSG rules removed (lib/trace/csg.c),
     and a part reports only its nearest two. */
  zr_hit h[ZR_MAX_CROSSINGS];
  double margin = 1e-9 * fmax(1.0, fabs(hit->t));
  double from = hit->t - margin;
  /* A mesh finds the winner's crossing again at exactly its t (its
     crossings do not depend on the interval), so a crossing past t
     could never be nearer to it: the search stops just past t rather
     than opening every box behind it. */
  double upto = hit->object->kind == ZR_OBJ_MESH ? hit->t + margin
                                                 : INFINITY;
  int n = zr__intersect_first(hit->object, ray, from > t0 ? from : t0,
                               upto, true, h);
  /* The crossing nearest the one found: shapes whose roots are refined
     inside the interval searched (lib/trace/roots.c) may place it a
     rounding away from before. */
  int best = -1;
  for (int i = 0; i < n; i++)
    if (best < 0 || fabs(h[i].t - hit->t) < fabs(h[best].t - hit->t))
      best = i;
  if (best >= 0) {
    double t = hit->t;
    *hit = h[best];
    hit->t = t;
  }
  return true;
}

/* A leaf primitive's crossings for zr__bvh_all_blocked: one, any, of a
   mesh that blocks the walk. */
static inline int walk_crossings_t(const zr_object *o, const zr_ray *ray,
                                   double tmin, double tmax,
                                   zr_blocks_fn blocks, void *user,
                                   zr_hit hits[ZR_MAX_CROSSINGS]) {
  if (blocks && o->kind == ZR_OBJ_MESH && !o->clip && !o->bound_cuts &&
      blocks(o, user))
    return zr__mesh_any_t(o, ray, tmin, tmax, hits);
  return crossings_t(o, ray, tmin, tmax, hits);
}

/* Whether o may cross a ray more than ZR_MAX_CROSSINGS times: all but
   the convex and flat shapes (a clip only removes crossings). */
static bool crosses_more(const zr_object *o) {
  return !zr__simple_kind(o->kind) && o->kind != ZR_OBJ_QUADRIC &&
         o->kind != ZR_OBJ_POLYGON;
}

/* Visits every crossing of the leaf o in (tmin, tmax): a shape that
   gives its nearest two is asked again beyond the second until it
   gives fewer (a shadow ray through a glass merge crosses each of its
   surfaces, and povray 3.7 filters the light at every one: two boxes
   of filter 0.5 apart in a merge pass 0.0625, not the 0.25 of the
   first two surfaces; bench/conform/shadow_fade_probe.sh). */
/* visit_leaf's rounds for a julia_fractal (normal_at_once), from one
   march of up to four crossings (zr__intersect_march_t) instead of one
   march a round: each round asked again from the sphere's entry, and a
   shadow ray through a glass fractal takes two rounds or more
   (objects/fractal2.pov: 46% of the profile in shadow rays' marches).
   A round gets what visit_leaf's would: the first two of the march's
   crossings beyond its tmin, marched again only when the four known do
   not hold them. */
static bool visit_march(const zr_object *o, const zr_ray *ray, double tmin,
                        double tmax, zr_crossing_fn visit, void *user,
                        zr_hit h[ZR_MAX_CROSSINGS]) {
  double t[4];
  bool complete;
  int known = zr__intersect_march_t(o, ray, tmin, tmax, t, &complete);
  int next = 0;
  for (int round = 0; round < 256; round++) {
    while (next < known && !(t[next] > tmin))
      next++;
    if (!complete && known - next < ZR_MAX_CROSSINGS) {
      known = zr__intersect_march_t(o, ray, tmin, tmax, t, &complete);
      next = 0;
    }
    int n = known - next < ZR_MAX_CROSSINGS ? known - next : ZR_MAX_CROSSINGS;
    for (int k = 0; k < n; k++) {
      h[k] = (zr_hit){.t = t[next + k], .object = o};
      if (!visit(&h[k], user))
        return false;
    }
    next += n;
    if (n < ZR_MAX_CROSSINGS)
      return true;
    tmin = h[n - 1].t + 1e-7 * (1.0 + fabs(h[n - 1].t));
  }
  return true;
}

static inline bool visit_leaf(const zr_object *o, const zr_ray *ray,
                              double tmin, double tmax, zr_blocks_fn blocks,
                              zr_crossing_fn visit, void *user,
                              zr_hit h[ZR_MAX_CROSSINGS]) {
  if (normal_at_once(o))
    return visit_march(o, ray, tmin, tmax, visit, user, h);
  for (int round = 0; round < 256; round++) {
    int n = walk_crossings_t(o, ray, tmin, tmax, blocks, user, h);
    for (int k = 0; k < n; k++)
      if (!visit(&h[k], user))
        return false;
    if (n < ZR_MAX_CROSSINGS || !crosses_more(o))
      return true;
    /* Past the last crossing by more than a root's rounding, so that it
       is not found again. */
    tmin = h[n - 1].t + 1e-7 * (1.0 + fabs(h[n - 1].t));
  }
  return true;
}

bool zr__bvh_all(const struct zr_bvh *bvh, const zr_ray *ray, double tmin,
                 double tmax, zr_crossing_fn visit, void *user) {
  return zr__bvh_all_blocked(bvh, ray, tmin, tmax, visit, NULL, user);
}

bool zr__bvh_all_blocked(const struct zr_bvh *bvh, const zr_ray *ray,
                         double tmin, double tmax, zr_crossing_fn visit,
                         zr_blocks_fn blocks, void *user) {
  if (!bvh)
    return true;
  zr_hit h[ZR_MAX_CROSSINGS];
  for (size_t i = 0; i < bvh->n_unbounded; i++) {
    const zr_object *o = bvh->unbounded[i];
    /* A plain plane, the floor every shadow ray tests, with the test
       written in: visit_leaf's rounds come to one plane_t (a plane
       crosses a line once), and the calls cost as much as the test
       (~35 instructions a shadow ray; callgrind, sphereflake 512^2). */
    if (plain_plane(o)) {
      if (plane_t_inline(o, ray, tmin, tmax, h) > 0 && !visit(&h[0], user))
        return false;
      continue;
    }
    if (!visit_leaf(o, ray, tmin, tmax, NULL, visit, user, h))
      return false;
  }
  if (bvh->n_wide == 0)
    return true;
  zr_slab_ray sr;
  zr__make_slab_ray(ray, &sr);
  const float tmin_f = zr__float_down(tmin), tmax_f = zr__float_up(tmax);
  sphere_ray sph;
  make_sphere_ray(ray, &sph);
  /* Leaves are visited in the tree's left-to-right order: children are
     pushed last to first, the first searched at once (e). */
  zr_wide_entry stack[WIDE_STACK_MAX];
  int sp = 0;
  zr_wide_entry e = {0, 0, tmin_f};
  for (;;) {
    if (e.count > 0) {
      for (uint32_t i = e.child; i < e.child + e.count; i++) {
        const leaf_sphere *s = &bvh->spheres[i];
        if (s->radius != s->radius) {
          if (!visit_leaf(bvh->prims[i], ray, tmin, tmax, blocks, visit,
                          user, h))
            return false;
          continue;
        }
        int n = sphere_t(bvh->prims[i], s->centre, s->radius, &sph, tmin,
                         tmax, h);
        for (int k = 0; k < n; k++)
          if (!visit(&h[k], user))
            return false;
      }
    } else {
      const zr_wide_node *w = &bvh->wide[e.child];
      float t[WIDTH];
      unsigned mask = zr__slab_entries(w, &sr, tmin_f, tmax_f, t);
      if (mask) {
        sp = zr__wide_next_in_order(w, mask, t, stack, sp, WIDE_STACK_MAX,
                                    &e);
        continue;
      }
    }
    if (sp == 0)
      break;
    e = stack[--sp];
  }
  return true;
}

bool zr__bvh_region_clear(const struct zr_bvh *bvh, zr_region_box_fn meets,
                          zr_region_prim_fn clear, void *user) {
  if (!bvh)
    return true;
  for (size_t i = 0; i < bvh->n_unbounded; i++)
    if (!clear(bvh->unbounded[i], user))
      return false;
  if (bvh->n_wide == 0)
    return true;
  uint32_t stack[WIDE_STACK_MAX];
  int sp = 0;
  stack[sp++] = 0;
  while (sp > 0) {
    const zr_wide_node *w = &bvh->wide[stack[--sp]];
    for (int c = 0; c < WIDTH; c++) {
      if (w->count[c] == ZR_WIDE_NO_CHILD)
        continue;
      double lo[3], hi[3];
      for (int a = 0; a < 3; a++) {
        lo[a] = w->lo[a][c];
        hi[a] = w->hi[a][c];
      }
      if (!meets(lo, hi, user))
        continue;
      if (w->count[c] == 0) {
        /* A full stack cannot answer: the region is not known clear. */
        if (sp == WIDE_STACK_MAX)
          return false;
        stack[sp++] = w->child[c];
        continue;
      }
      for (uint32_t i = w->child[c]; i < w->child[c] + w->count[c]; i++)
        if (!clear(bvh->prims[i], user))
          return false;
    }
  }
  return true;
}

/* ---- occlusion: whether anything crosses a segment ----
 *
 * zr__bvh_occluded answers what a zr__bvh_all walk with a visit that
 * stops at the first crossing answers (zr__rad_occluded's question),
 * by the same walk over the same boxes, but asks each primitive only
 * whether one of its crossings lies in the interval: no crossing list,
 * no sort, no table call, no normal.  For each kind handled here the
 * test is the shape's own arithmetic, operation for operation (the
 * same roots, bit for bit, so the same answer at the interval's ends
 * and for grazing rays), followed by the filter intersect.c applies
 * (a finite t with tmin < t < tmax); a clipped primitive, a CSG and
 * every other kind are asked through crossings_t, as the walk asks
 * them.  tests/test_bvh_occluded.c compares the two on random segments
 * over a scene of mixed kinds. */

/* Moller and Trumbore's test as obj_triangle.c makes it. */
static inline bool triangle_blocks(const zr_object *o, zr_vec3 org,
                                   zr_vec3 dir, double tmin, double tmax) {
  const zr_vec3 *p = o->u.triangle.p;
  zr_vec3 e1 = zr_v3_sub(p[1], p[0]), e2 = zr_v3_sub(p[2], p[0]);
  zr_vec3 pv = zr_v3_cross(dir, e2);
  double det = zr_v3_dot(e1, pv);
  if (det == 0.0 || !isfinite(det))
    return false;
  double inv = 1.0 / det;
  zr_vec3 tv = zr_v3_sub(org, p[0]);
  double u = zr_v3_dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0)
    return false;
  zr_vec3 qv = zr_v3_cross(tv, e1);
  /* The interval first: most triangles a segment's boxes lead to lie
     beyond its ends; the conditions are all needed, in any order. */
  double t = zr_v3_dot(e2, qv) * inv;
  if (!(isfinite(t) && t > tmin && t < tmax))
    return false;
  double v = zr_v3_dot(dir, qv) * inv;
  return !(v < 0.0 || u + v > 1.0);
}

#ifdef __SSE2__
/* Two triangles' vectors, lane 0 the first's, lane 1 the second's. */
typedef struct pair3 {
  __m128d x, y, z;
} pair3;

static inline pair3 pair_of(zr_vec3 a, zr_vec3 b) {
  return (pair3){_mm_set_pd(b.x, a.x), _mm_set_pd(b.y, a.y),
                 _mm_set_pd(b.z, a.z)};
}

static inline pair3 pair_splat(zr_vec3 a) {
  return (pair3){_mm_set1_pd(a.x), _mm_set1_pd(a.y), _mm_set1_pd(a.z)};
}

static inline pair3 pair_sub(pair3 a, pair3 b) {
  return (pair3){_mm_sub_pd(a.x, b.x), _mm_sub_pd(a.y, b.y),
                 _mm_sub_pd(a.z, b.z)};
}

/* zr_v3_dot's operations in its order: (x x + y y) + z z. */
static inline __m128d pair_dot(pair3 a, pair3 b) {
  return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a.x, b.x), _mm_mul_pd(a.y, b.y)),
                    _mm_mul_pd(a.z, b.z));
}

/* zr_v3_cross's. */
static inline pair3 pair_cross(pair3 a, pair3 b) {
  return (pair3){_mm_sub_pd(_mm_mul_pd(a.y, b.z), _mm_mul_pd(a.z, b.y)),
                 _mm_sub_pd(_mm_mul_pd(a.z, b.x), _mm_mul_pd(a.x, b.z)),
                 _mm_sub_pd(_mm_mul_pd(a.x, b.y), _mm_mul_pd(a.y, b.x))};
}

/* Lanes whose |x| is finite (a NaN's comparison is false). */
static inline __m128d pair_finite(__m128d x) {
  __m128d abs = _mm_andnot_pd(_mm_set1_pd(-0.0), x);
  return _mm_cmple_pd(abs, _mm_set1_pd(DBL_MAX));
}

/*
 * triangle_blocks for two triangles a and b at once, SSE2's two double
 * lanes doing each operation of the scalar test for both (the same
 * IEEE operations, so the same values bit for bit); true when either
 * blocks.  The scalar test's conditions become lane masks, with their
 * NaN cases kept: !(u < 0) is "not less than", which a NaN passes as it
 * passes the scalar test.  The second half is skipped when neither
 * lane passed the first, as the scalar test returns early.
 */
static inline bool triangle_pair_blocks(const zr_object *a,
                                        const zr_object *b, zr_vec3 org,
                                        zr_vec3 dir, double tmin,
                                        double tmax) {
  const zr_vec3 *pa = a->u.triangle.p, *pb = b->u.triangle.p;
  pair3 p0 = pair_of(pa[0], pb[0]);
  pair3 e1 = pair_sub(pair_of(pa[1], pb[1]), p0);
  pair3 e2 = pair_sub(pair_of(pa[2], pb[2]), p0);
  pair3 d = pair_splat(dir);
  pair3 pv = pair_cross(d, e2);
  __m128d det = pair_dot(e1, pv);
  __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  __m128d ok = _mm_and_pd(_mm_cmpneq_pd(det, zero), pair_finite(det));
  __m128d inv = _mm_div_pd(one, det);
  pair3 tv = pair_sub(pair_splat(org), p0);
  __m128d u = _mm_mul_pd(pair_dot(tv, pv), inv);
  ok = _mm_and_pd(ok, _mm_and_pd(_mm_cmpnlt_pd(u, zero),
                                 _mm_cmpngt_pd(u, one)));
  if (_mm_movemask_pd(ok) == 0)
    return false;
  pair3 qv = pair_cross(tv, e1);
  __m128d t = _mm_mul_pd(pair_dot(e2, qv), inv);
  __m128d inside = _mm_and_pd(_mm_cmpgt_pd(t, _mm_set1_pd(tmin)),
                              _mm_cmplt_pd(t, _mm_set1_pd(tmax)));
  ok = _mm_and_pd(ok, _mm_and_pd(pair_finite(t), inside));
  if (_mm_movemask_pd(ok) == 0)
    return false;
  __m128d v = _mm_mul_pd(pair_dot(d, qv), inv);
  ok = _mm_and_pd(ok, _mm_and_pd(_mm_cmpnlt_pd(v, zero),
                                 _mm_cmpngt_pd(_mm_add_pd(u, v), one)));
  return _mm_movemask_pd(ok) != 0;
}
#endif

/* The slab test as obj_box.c makes it; either face may be the one. */
static bool box_blocks(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax) {
  zr_vec3 lo = zr_v3_min(o->u.box.corner1, o->u.box.corner2);
  zr_vec3 hi = zr_v3_max(o->u.box.corner1, o->u.box.corner2);
  double tnear = -INFINITY, tfar = INFINITY;
  bool near_set = false, far_set = false;
  for (int axis = 0; axis < 3; axis++) {
    double oa = zr_v3_get(org, axis), da = zr_v3_get(dir, axis);
    double la = zr_v3_get(lo, axis), ha = zr_v3_get(hi, axis);
    if (da == 0.0) {
      if (oa < la || oa > ha)
        return false;
      continue;
    }
    double t0 = (la - oa) / da, t1 = (ha - oa) / da;
    if (t0 > t1) {
      double tt = t0;
      t0 = t1;
      t1 = tt;
    }
    if (t0 > tnear) {
      tnear = t0;
      near_set = true;
    }
    if (t1 < tfar) {
      tfar = t1;
      far_set = true;
    }
  }
  if (!(tnear <= tfar) || !near_set || !far_set)
    return false;
  return (isfinite(tnear) && tnear > tmin && tnear < tmax) ||
         (isfinite(tfar) && tfar > tmin && tfar < tmax);
}

/* Whether primitive o crosses the ray in (tmin, tmax), as crossings_t
   finds. */
static bool prim_blocks(const zr_object *o, const zr_ray *ray, double tmin,
                        double tmax) {
  zr_object_kind kind = o->kind;
  bool own = !o->clip && (kind == ZR_OBJ_TRIANGLE || kind == ZR_OBJ_BOX ||
                          kind == ZR_OBJ_PLANE || kind == ZR_OBJ_SPHERE ||
                          kind == ZR_OBJ_POLYGON);
  if (!own) {
    zr_hit h[ZR_MAX_CROSSINGS];
    return crossings_t(o, ray, tmin, tmax, h) > 0;
  }
  /* In the object's own coordinates, as intersect.c maps the ray. */
  zr_ray r = *ray;
  if (o->transform) {
    r.origin = zr__xform_point(o->transform->inv, ray->origin);
    r.dir = zr__xform_dir(o->transform->inv, ray->dir);
  }
  switch (kind) {
  case ZR_OBJ_TRIANGLE:
    return triangle_blocks(o, r.origin, r.dir, tmin, tmax);
  case ZR_OBJ_BOX:
    return box_blocks(o, r.origin, r.dir, tmin, tmax);
  case ZR_OBJ_POLYGON: {
    double t[4];
    zr_vec3 n[4];
    return zr__polygon_crossings(o, r.origin, r.dir, tmin, tmax, t, n) >
               0 &&
           isfinite(t[0]);
  }
  default: {
    /* A plane or a sphere: the walk's own tests (plane_t, sphere_t)
       are the shapes' arithmetic. */
    zr_hit h[ZR_MAX_CROSSINGS];
    if (kind == ZR_OBJ_PLANE)
      return plane_t(o, &r, tmin, tmax, h) > 0;
    sphere_ray sr;
    make_sphere_ray(&r, &sr);
    return sphere_t(o, o->u.sphere.centre, o->u.sphere.radius, &sr, tmin,
                    tmax, h) > 0;
  }
  }
}

static inline bool plain_triangle(const zr_object *o) {
  return o->kind == ZR_OBJ_TRIANGLE && !o->transform && !o->clip;
}

/* Whether a primitive of the leaf run [first, first + count) blocks. */
static inline bool leaf_blocks(const struct zr_bvh *bvh, uint32_t first,
                               uint32_t count, const zr_ray *ray,
                               const sphere_ray *sph, double tmin,
                               double tmax) {
  zr_hit h[ZR_MAX_CROSSINGS];
  const uint32_t end = first + count;
  for (uint32_t i = first; i < end; i++) {
    const zr_object *o = bvh->prims[i];
    const leaf_sphere *s = &bvh->spheres[i];
    bool blocks;
    /* A triangle without transform or clip, what meshes of separate
       triangles (the Cornell box) are made of, without the call; two
       of them side by side at once. */
    if (plain_triangle(o)) {
#ifdef __SSE2__
      if (i + 1 < end && plain_triangle(bvh->prims[i + 1])) {
        if (triangle_pair_blocks(o, bvh->prims[i + 1], ray->origin,
                                 ray->dir, tmin, tmax))
          return true;
        i++;
        continue;
      }
#endif
      blocks = triangle_blocks(o, ray->origin, ray->dir, tmin, tmax);
    }
    else if (s->radius == s->radius)
      blocks = sphere_t(o, s->centre, s->radius, sph, tmin, tmax, h) > 0;
    else
      blocks = prim_blocks(o, ray, tmin, tmax);
    if (blocks)
      return true;
  }
  return false;
}

/* A leaf's code in a hint: the wide node holding it and its lane. */
static inline uint64_t leaf_code(uint32_t node, int lane) {
  return 1 + (uint64_t)node * WIDTH + (uint64_t)lane;
}

bool zr__bvh_occluded(const struct zr_bvh *bvh, const zr_ray *ray,
                      double tmin, double tmax, zr_bvh_hint *hint) {
  if (!bvh)
    return false;
  for (size_t i = 0; i < bvh->n_unbounded; i++)
    if (prim_blocks(bvh->unbounded[i], ray, tmin, tmax))
      return true;
  if (bvh->n_wide == 0)
    return false;
  zr_slab_ray sr;
  zr__make_slab_ray(ray, &sr);
  const float tmin_f = zr__float_down(tmin), tmax_f = zr__float_up(tmax);
  sphere_ray sph;
  make_sphere_ray(ray, &sph);
  float t[WIDTH];
  uint64_t tested = 0; /* the hinted leaf, once searched in vain */
  /* The hinted leaf first, if the walk would open it: a child's box
     lies in its parent's, and the parent's extent (hence its margin) is
     at least the child's, so the slab test that meets a leaf's box
     meets every box above it. */
  if (hint && hint->where > 0 && hint->where <= (uint64_t)bvh->n_wide * WIDTH) {
    uint32_t node = (uint32_t)((hint->where - 1) / WIDTH);
    int lane = (int)((hint->where - 1) % WIDTH);
    const zr_wide_node *w = &bvh->wide[node];
    if (w->count[lane] > 0 && w->count[lane] != ZR_WIDE_NO_CHILD &&
        (zr__slab_entries(w, &sr, tmin_f, tmax_f, t) >> lane & 1)) {
      if (leaf_blocks(bvh, w->child[lane], w->count[lane], ray, &sph, tmin,
                      tmax))
        return true;
      tested = hint->where;
    }
  }
  /* The leaves in any order (the tree's, which costs no sort); a
     stack entry is (node, lane), the leaf's place for the hint. */
  uint32_t stack[WIDE_STACK_MAX];
  int sp = 0;
  stack[sp++] = 0;
  while (sp > 0) {
    uint32_t node = stack[--sp];
    const zr_wide_node *w = &bvh->wide[node];
    unsigned mask = zr__slab_entries(w, &sr, tmin_f, tmax_f, t);
    for (; mask; mask &= mask - 1) {
      int c = __builtin_ctz(mask);
      if (w->count[c] == 0) {
        if (sp < WIDE_STACK_MAX)
          stack[sp++] = w->child[c];
        continue;
      }
      if (leaf_code(node, c) != tested &&
          leaf_blocks(bvh, w->child[c], w->count[c], ray, &sph, tmin,
                      tmax)) {
        if (hint)
          hint->where = leaf_code(node, c);
        return true;
      }
    }
  }
  return false;
}
