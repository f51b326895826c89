/*
 * obj_mesh.c - triangle meshes: POV-Ray 3.7's mesh, mesh2 and
 * smooth_triangle (reference manual, "Mesh", "Mesh2", "Smooth
 * Triangle").
 *
 * A mesh is one primitive to the scene's BVH, with a hierarchy of its
 * own over its triangles, so a mesh declared once and placed many times
 * with object { M transform } costs its triangles once: every placed
 * copy is a zr_object that points to the same struct zr_mesh and carries
 * its own transform, and a ray is mapped into the mesh's coordinates
 * before it meets the inner hierarchy.
 *
 * The inner hierarchy is built top down with the binned surface area
 * heuristic (Wald, "On fast Construction of SAH-based Bounding Volume
 * Hierarchies", 2007) with lib/trace/bvh.c's sweep (zr__sah_sweep), but
 * over the faces' own boxes (single precision, rounded outward),
 * partitioned in place.  The binary tree is then collapsed four wide
 * into the nodes the scene's hierarchy uses (lib/trace/bvh_wide.h: one
 * SSE slab test for four children), which took the terrain of
 * bench/peers.sh from 6.80 to 5.42 CPU seconds of render at 2048^2
 * (bench/results/peers-cpu-2026-12-02-s5.txt).  The faces are put in
 * leaf order, so a leaf is a run of consecutive rows and needs no index
 * table.  Triangles are tested in double precision (Moller and
 * Trumbore, "Fast, minimum storage ray/triangle intersection", 1997).
 * A shadow ray through a mesh that stops light wherever it is crossed
 * takes the first crossing met (zr__mesh_any_t), not the nearest.
 *
 * A smooth triangle's shading normal is its corner normals weighted by
 * the barycentric coordinates of the hit (Phong interpolation, as the
 * manual describes smooth_triangle).  A mesh has no inside unless it has
 * an inside_vector; then a point is inside when a ray from it along that
 * vector crosses the mesh an odd number of times ("Mesh": the mesh must
 * be closed for this to mean anything).
 */
#include "trace/obj_mesh.h"

#include "core/arena.h"
#include "core/parallel.h"
#include "core/team.h"
#include "trace/bvh.h"
#include "trace/bvh_wide.h"
#include "trace/embree.h"
#include "trace/intersect.h"
#include "trace/prepare.h"
#include "trace/shape.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum {
  BINS = ZR_SAH_BINS,
  LEAF_MAX = 4,    /* a node this small is always a leaf */
  LEAF_SAH_MAX = 8, /* SAH may prefer a leaf up to this size */
  DEPTH_MAX = 64,
  STACK_MAX = 96
};

/* The mesh's hierarchy as the tracer walks it: four-wide nodes
   (lib/trace/bvh_wide.h), collapsed from the binary tree built here. */
struct zr_mesh_node {
  zr_wide_node wide;
};

/* A face's box and centre while building.  The boxes themselves are
   partitioned (not an index table into them), so every pass over a
   node's faces reads memory in order. */
typedef struct face_box {
  float lo[3], hi[3], centre[3];
  uint32_t face;
} face_box;

typedef struct builder {
  face_box *boxes;
  zr_bvh_bin_node *nodes;
  size_t n_nodes, cap_nodes;
  /* The nodes have room for the most a tree of their faces can have
     (2 n - 1 for n faces: every leaf holds a face) in memory the
     builder does not own (a worker's run, or zr__map_alloc's block):
     new_node never moves them. */
  bool fixed;
} builder;

typedef struct fbox {
  float lo[3], hi[3];
} fbox;

static void fbox_empty(fbox *b) {
  for (int i = 0; i < 3; i++) {
    b->lo[i] = INFINITY;
    b->hi[i] = -INFINITY;
  }
}

/* Plain comparisons: fminf and fmaxf are calls at -O2, and this is the
   builder's innermost loop. */
static void fbox_grow(fbox *b, const float lo[3], const float hi[3]) {
  for (int i = 0; i < 3; i++) {
    b->lo[i] = lo[i] < b->lo[i] ? lo[i] : b->lo[i];
    b->hi[i] = hi[i] > b->hi[i] ? hi[i] : b->hi[i];
  }
}

static double fbox_area(const fbox *b) {
  double d[3];
  for (int i = 0; i < 3; i++)
    d[i] = b->hi[i] > b->lo[i] ? (double)b->hi[i] - b->lo[i] : 0.0;
  return 2.0 * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
}

static int bin_of(float c, float lo, float scale) {
  int k = (int)((c - lo) * scale);
  return k < 0 ? 0 : k >= BINS ? BINS - 1 : k;
}

/* The box of faces [0, n) and the box of their centres. */
static void bounds_of(const face_box *boxes, size_t n, fbox *bounds,
                      fbox *centres) {
  fbox_empty(bounds);
  fbox_empty(centres);
  for (size_t i = 0; i < n; i++) {
    fbox_grow(bounds, boxes[i].lo, boxes[i].hi);
    fbox_grow(centres, boxes[i].centre, boxes[i].centre);
  }
}

/*
 * The binning pass of split: each face of [0, n) counted in the bin of
 * its centre along axis, and the bin's box and centres' box grown by it.
 * This loop is most of the mesh's hierarchy build (23% of the terrain's
 * parse, perf), and as scalar code each face's twelve comparisons wait
 * on the stores of the face before it, which mostly falls in the same
 * bin.  With SSE each box is two 4-wide min/max: _mm_min_ps(a, b) is
 * a < b ? a : b and _mm_max_ps(a, b) is a > b ? a : b, lane by lane,
 * the very comparisons of fbox_grow in the same order, so the boxes are
 * the same floats (signed zeros and all) and so is the tree.  The
 * fourth lane of each load is the next field of face_box (hi[0],
 * centre[0], face) and is never stored.
 */
static void bin_faces(const face_box *boxes, size_t n, int axis, float lo,
                      float scale, size_t counts[BINS], fbox bins[BINS],
                      fbox bin_centres[BINS]) {
#ifdef __SSE2__
  __m128 vlo[BINS], vhi[BINS], vclo[BINS], vchi[BINS];
  for (int k = 0; k < BINS; k++) {
    vlo[k] = vclo[k] = _mm_set1_ps(INFINITY);
    vhi[k] = vchi[k] = _mm_set1_ps(-INFINITY);
  }
  for (size_t i = 0; i < n; i++) {
    const face_box *fb = &boxes[i];
    int k = bin_of(fb->centre[axis], lo, scale);
    counts[k]++;
    __m128 c = _mm_loadu_ps(fb->centre);
    vlo[k] = _mm_min_ps(_mm_loadu_ps(fb->lo), vlo[k]);
    vhi[k] = _mm_max_ps(_mm_loadu_ps(fb->hi), vhi[k]);
    vclo[k] = _mm_min_ps(c, vclo[k]);
    vchi[k] = _mm_max_ps(c, vchi[k]);
  }
  for (int k = 0; k < BINS; k++) {
    float t[4];
    _mm_storeu_ps(t, vlo[k]);
    memcpy(bins[k].lo, t, sizeof bins[k].lo);
    _mm_storeu_ps(t, vhi[k]);
    memcpy(bins[k].hi, t, sizeof bins[k].hi);
    _mm_storeu_ps(t, vclo[k]);
    memcpy(bin_centres[k].lo, t, sizeof bin_centres[k].lo);
    _mm_storeu_ps(t, vchi[k]);
    memcpy(bin_centres[k].hi, t, sizeof bin_centres[k].hi);
  }
#else
  for (int k = 0; k < BINS; k++) {
    fbox_empty(&bins[k]);
    fbox_empty(&bin_centres[k]);
  }
  for (size_t i = 0; i < n; i++) {
    const face_box *fb = &boxes[i];
    int k = bin_of(fb->centre[axis], lo, scale);
    counts[k]++;
    fbox_grow(&bins[k], fb->lo, fb->hi);
    fbox_grow(&bin_centres[k], fb->centre, fb->centre);
  }
#endif
}

/* The sides of a split: each side's box and the box of its centres,
   the unions of its bins' (the same floats a pass over its faces would
   give, so the children need no pass of their own). */
typedef struct sides {
  fbox bounds[2], centres[2];
} sides;

/* A split in halves, for nodes the heuristic cannot split; a node of
   at most leaf_max faces stays a leaf (0). */
static size_t halve(face_box *boxes, size_t n, size_t leaf_max,
                    sides *out) {
  if (n <= leaf_max)
    return 0;
  size_t left = n / 2;
  bounds_of(boxes, left, &out->bounds[0], &out->centres[0]);
  bounds_of(boxes + left, n - left, &out->bounds[1], &out->centres[1]);
  return left;
}

/*
 * The number of faces of order[0..n) that go left, reordered so they
 * come first; 0 when a leaf is the better choice.  out gets the boxes
 * of both sides.
 */
static size_t split(face_box *boxes, size_t n, const fbox *bounds,
                    const fbox *centres, sides *out) {
  const fbox cb = *centres;
  int axis = 0;
  for (int a = 1; a < 3; a++)
    if (cb.hi[a] - cb.lo[a] > cb.hi[axis] - cb.lo[axis])
      axis = a;
  double ext = (double)cb.hi[axis] - cb.lo[axis];
  if (!(ext > 0.0)) {
    /* Every centre coincides: any halving is as good as another. */
    return halve(boxes, n, LEAF_SAH_MAX, out);
  }
  float scale = (float)(BINS / ext);
  size_t counts[BINS] = {0};
  fbox bins[BINS], bin_centres[BINS];
  bin_faces(boxes, n, axis, cb.lo[axis], scale, counts, bins, bin_centres);
  /* The shared sweep, in double precision: the floats convert exactly
     and give the areas fbox_area would. */
  zr_sah_bin sweep[BINS];
  for (int k = 0; k < BINS; k++) {
    for (int a = 0; a < 3; a++) {
      sweep[k].lo[a] = bins[k].lo[a];
      sweep[k].hi[a] = bins[k].hi[a];
    }
    sweep[k].count = counts[k];
  }
  double best;
  int best_k = zr__sah_sweep(sweep, n, &best);
  if (best_k < 0)
    return halve(boxes, n, LEAF_SAH_MAX, out);
  /* A traversal step costs about as much as one triangle test. */
  double area = fbox_area(bounds);
  if (n <= LEAF_SAH_MAX && area + best >= area * (double)n)
    return 0;
  for (int side = 0; side < 2; side++) {
    fbox_empty(&out->bounds[side]);
    fbox_empty(&out->centres[side]);
  }
  for (int k = 0; k < BINS; k++) {
    int side = k >= best_k;
    if (counts[k]) {
      fbox_grow(&out->bounds[side], bins[k].lo, bins[k].hi);
      fbox_grow(&out->centres[side], bin_centres[k].lo, bin_centres[k].hi);
    }
  }
  size_t left = 0;
  for (size_t i = 0; i < n; i++) {
    if (bin_of(boxes[i].centre[axis], cb.lo[axis], scale) < best_k) {
      face_box t = boxes[i];
      boxes[i] = boxes[left];
      boxes[left] = t;
      left++;
    }
  }
  return left;
}

static zr_status new_node(builder *b, size_t *index) {
  if (b->n_nodes == b->cap_nodes) {
    if (b->fixed)
      return ZR_ENOMEM; /* never: the room is the most there can be */
    size_t cap = b->cap_nodes ? b->cap_nodes * 2 : 64;
    zr_bvh_bin_node *p = realloc(b->nodes, cap * sizeof *p);
    if (!p)
      return ZR_ENOMEM;
    b->nodes = p;
    b->cap_nodes = cap;
  }
  *index = b->n_nodes++;
  return ZR_OK;
}

/*
 * The step build_node and build_top share: node index gets the box of
 * faces [first, first + n), whose box and centres' box the caller knows
 * (the parent's split found them), and the faces are split; a node that
 * stays a leaf (left 0 or n) gets its faces here.  The number going
 * left is returned, with both sides' boxes in out.
 */
static size_t split_node(builder *b, size_t index, size_t first, size_t n,
                         int depth, const fbox *bounds, const fbox *centres,
                         sides *out) {
  for (int a = 0; a < 3; a++) {
    b->nodes[index].lo[a] = bounds->lo[a];
    b->nodes[index].hi[a] = bounds->hi[a];
  }
  size_t left = 0;
  if (n > LEAF_MAX)
    left = depth < DEPTH_MAX
               ? split(b->boxes + first, n, bounds, centres, out)
               : halve(b->boxes + first, n, LEAF_MAX, out);
  if (left == 0 || left == n) {
    b->nodes[index].first = (uint32_t)first;
    b->nodes[index].count = (uint32_t)n;
    return left;
  }
  b->nodes[index].count = 0;
  return left;
}

/* The node of faces [first, first + n) and its subtree, depth first. */
static zr_status build_node(builder *b, size_t first, size_t n, int depth,
                            const fbox *bounds, const fbox *centres) {
  size_t index;
  zr_status s = new_node(b, &index);
  if (s != ZR_OK)
    return s;
  sides out;
  size_t left = split_node(b, index, first, n, depth, bounds, centres, &out);
  if (left == 0 || left == n)
    return ZR_OK;
  s = build_node(b, first, left, depth + 1, &out.bounds[0],
                 &out.centres[0]);
  if (s != ZR_OK)
    return s;
  b->nodes[index].first = (uint32_t)b->n_nodes;
  return build_node(b, first + left, n - left, depth + 1, &out.bounds[1],
                    &out.centres[1]);
}

/*
 * The same tree built by several threads.  The top of the tree is built
 * as above, except that a node of at most cutoff faces becomes a task
 * (its placeholder node stays in the top array); the tasks, whose faces
 * are disjoint runs of the boxes, are then built by zr__parallel_for,
 * each into an array of its own by build_node, and spliced into the top
 * array's depth-first order.  A node's split depends only on its faces,
 * depth and boxes, never on who builds it or where its nodes go, so the
 * spliced array is the one build_node gives alone, node for node,
 * whatever the number of threads (tests/test_mesh checks it).
 */
typedef struct subtree {
  size_t first, n, top; /* faces, and the placeholder in the top array */
  int depth;
  fbox bounds, centres;
  builder b;
  zr_status status;
  /* Where its nodes are: at run's node at (run_of_nodes), or, run -1, in
     an array of their own (another member's, take_part). */
  int run;
  size_t at;
} subtree;

/*
 * A worker's nodes: the tasks it builds, one after another, each built
 * in the room the most nodes of its faces need (2 n - 1) at the end of
 * the run, which then keeps only the nodes it used.  Every task's nodes
 * in an array of its own that doubled by realloc took 950 of the
 * terrain's 1,850 page faults (bench/results/arena-2026-12-03-s15.md):
 * the copies, and 4 KiB pages; a run is one mapping in huge pages
 * (zr__map_alloc), grown by mremap, never copied, its pages touched in
 * order.  Its address changes as it grows, so a task keeps its place
 * (at) and build_some points its nodes there once all are built.
 */
typedef struct node_run {
  zr_bvh_bin_node *nodes;
  size_t used, cap;
} node_run;

typedef struct top_build {
  builder top;
  subtree *tasks;
  size_t n_tasks, cap_tasks;
  size_t cutoff;
  node_run *runs; /* one a worker */
  int n_runs;
  size_t run_start; /* a run's first room, in nodes */
} top_build;

static zr_status add_task(top_build *t, size_t first, size_t n, int depth,
                          const fbox *bounds, const fbox *centres,
                          size_t top) {
  if (t->n_tasks == t->cap_tasks) {
    size_t cap = t->cap_tasks ? 2 * t->cap_tasks : 64;
    subtree *q = realloc(t->tasks, cap * sizeof *q);
    if (!q)
      return ZR_ENOMEM;
    t->tasks = q;
    t->cap_tasks = cap;
  }
  subtree *k = &t->tasks[t->n_tasks++];
  memset(k, 0, sizeof *k);
  k->run = -1;
  k->first = first;
  k->n = n;
  k->top = top;
  k->depth = depth;
  k->bounds = *bounds;
  k->centres = *centres;
  k->b.boxes = t->top.boxes;
  return ZR_OK;
}

/* build_node's top: nodes of at most cutoff faces are left as tasks (a
   placeholder node each, whose count says nothing). */
static zr_status build_top(top_build *t, size_t first, size_t n, int depth,
                           const fbox *bounds, const fbox *centres) {
  builder *b = &t->top;
  size_t index;
  zr_status s = new_node(b, &index);
  if (s != ZR_OK)
    return s;
  if (n <= t->cutoff)
    return add_task(t, first, n, depth, bounds, centres, index);
  sides out;
  size_t left = split_node(b, index, first, n, depth, bounds, centres, &out);
  if (left == 0 || left == n)
    return ZR_OK;
  s = build_top(t, first, left, depth + 1, &out.bounds[0], &out.centres[0]);
  if (s != ZR_OK)
    return s;
  b->nodes[index].first = (uint32_t)b->n_nodes;
  return build_top(t, first + left, n - left, depth + 1, &out.bounds[1],
                   &out.centres[1]);
}

/* The top array's node i and what it stands for, appended to out in
   depth-first order: a placeholder's subtree with its inner nodes'
   right-child indices moved by where it lands (a leaf's first is a
   face, which stays). */
static void splice(const top_build *t, const size_t *task_of, size_t i,
                   zr_bvh_bin_node *out, size_t *n_out) {
  if (task_of[i] != SIZE_MAX) {
    const builder *sub = &t->tasks[task_of[i]].b;
    size_t at = *n_out;
    for (size_t j = 0; j < sub->n_nodes; j++) {
      out[at + j] = sub->nodes[j];
      if (out[at + j].count == 0)
        out[at + j].first += (uint32_t)at;
    }
    *n_out += sub->n_nodes;
    return;
  }
  size_t at = (*n_out)++;
  out[at] = t->top.nodes[i];
  if (out[at].count != 0)
    return;
  splice(t, task_of, i + 1, out, n_out);
  out[at].first = (uint32_t)*n_out;
  splice(t, task_of, t->top.nodes[i].first, out, n_out);
}

/* Fewer faces than this a thread: the tasks' start-up is not worth it. */
#define PARALLEL_FACES_MIN 16384

/* The tasks of this member, built by its threads. */
typedef struct task_list {
  top_build *t;
  const size_t *which;
} task_list;

/* Room for need more nodes at the end of run r (first start nodes). */
static bool run_room(node_run *r, size_t need, size_t start) {
  if (r->cap - r->used >= need)
    return true;
  size_t cap = r->cap ? 2 * r->cap : start;
  if (cap < r->used + need)
    cap = r->used + need;
  const size_t node = sizeof *r->nodes;
  if (cap > SIZE_MAX / node)
    return false;
  zr_bvh_bin_node *p = zr__map_grow(r->nodes, r->cap * node, cap * node);
  if (!p)
    return false;
  r->nodes = p;
  r->cap = cap;
  return true;
}

static void build_listed(void *user, size_t begin, size_t end, int worker) {
  task_list *l = user;
  node_run *r = &l->t->runs[worker];
  for (size_t i = begin; i < end; i++) {
    subtree *k = &l->t->tasks[l->which[i]];
    size_t need = 2 * k->n - 1;
    if (!run_room(r, need, l->t->run_start)) {
      k->status = ZR_ENOMEM;
      continue;
    }
    k->b.nodes = r->nodes + r->used;
    k->b.n_nodes = 0;
    k->b.cap_nodes = need;
    k->b.fixed = true;
    k->status = build_node(&k->b, k->first, k->n, k->depth, &k->bounds,
                           &k->centres);
    k->run = worker;
    k->at = r->used;
    r->used += k->b.n_nodes;
  }
}

/* Builds the tasks which[0 .. count) with threads threads. */
static void build_some(top_build *t, const size_t *which, size_t count,
                       int threads) {
  task_list l = {t, which};
  if (count == 0)
    return;
  int workers = threads < 1                  ? 1
                : threads > ZR__MAX_THREADS ? ZR__MAX_THREADS
                                            : threads;
  if (!t->runs) {
    t->runs = calloc((size_t)workers, sizeof *t->runs);
    if (!t->runs) {
      for (size_t i = 0; i < count; i++)
        t->tasks[which[i]].status = ZR_ENOMEM;
      return;
    }
    t->n_runs = workers;
  }
  if (workers > t->n_runs)
    workers = t->n_runs;
  /* A run starts with room for its share of the faces' most nodes (the
     terrain's tasks used 0.54 nodes a face): one mapping, rarely grown. */
  size_t faces = 0;
  for (size_t i = 0; i < count; i++)
    faces += t->tasks[which[i]].n;
  t->run_start = 2 * faces / (size_t)workers;
  zr__parallel_for(workers, count, 1, build_listed, &l, NULL);
  for (size_t i = 0; i < count; i++) {
    subtree *k = &t->tasks[which[i]];
    if (k->run >= 0)
      k->b.nodes = t->runs[k->run].nodes + k->at;
  }
}

/* A task's size and index while they are dealt. */
typedef struct task_size {
  size_t n, index;
} task_size;

/* Largest first; equal sizes by index (a total order: every member
   sorts alike). */
static int larger_task(const void *a, const void *b) {
  const task_size *x = a, *y = b;
  if (x->n != y->n)
    return x->n > y->n ? -1 : 1;
  return x->index < y->index ? -1 : x->index > y->index;
}

/*
 * Deals the tasks to the members, owner[i] the member of task i: the
 * largest first, each to the member with the fewest faces so far (the
 * lowest rank among equals), so that the members' shares even out
 * although the tasks' sizes differ (the top splits where the heuristic
 * says, not in halves).  Every member deals alike from the same tasks.
 * false when there is no memory for it.
 */
static bool deal_tasks(const top_build *t, int members, int *owner) {
  task_size *order = malloc((t->n_tasks ? t->n_tasks : 1) * sizeof *order);
  size_t *load = calloc((size_t)members, sizeof *load);
  bool ok = order && load;
  if (ok) {
    for (size_t i = 0; i < t->n_tasks; i++)
      order[i] = (task_size){t->tasks[i].n, i};
    qsort(order, t->n_tasks, sizeof *order, larger_task);
    for (size_t i = 0; i < t->n_tasks; i++) {
      int m = 0;
      for (int r = 1; r < members; r++)
        if (load[r] < load[m])
          m = r;
      owner[order[i].index] = m;
      load[m] += order[i].n;
    }
  }
  free(order);
  free(load);
  return ok;
}

/*
 * Whether nodes[0 .. n_nodes) is the tree build_node makes of the task
 * k's faces: depth first, an inner node's left child right after it and
 * its right child (first) after the left subtree, every leaf's faces
 * the next run of the task's faces, the runs covering them all, and no
 * node deeper than the tracer's stacks allow (STACK_MAX).  A part
 * another member sent is taken only so, so that whatever arrives the
 * tree cannot send the tracer or the collapse outside its arrays.
 */
static bool check_node(const zr_bvh_bin_node *nodes, size_t n_nodes,
                       size_t j, int depth, size_t *next_node,
                       size_t *next_face, size_t end_face) {
  if (j != *next_node || j >= n_nodes || depth > STACK_MAX)
    return false;
  (*next_node)++;
  const zr_bvh_bin_node *node = &nodes[j];
  if (node->count > 0) {
    if (node->first != *next_face || node->count > end_face - *next_face)
      return false;
    *next_face += node->count;
    return true;
  }
  if (!check_node(nodes, n_nodes, j + 1, depth + 1, next_node, next_face,
                  end_face) ||
      node->first != *next_node)
    return false;
  return check_node(nodes, n_nodes, node->first, depth + 1, next_node,
                    next_face, end_face);
}

static bool subtree_ok(const subtree *k, const zr_bvh_bin_node *nodes,
                       size_t n_nodes) {
  size_t next_node = 0, next_face = k->first;
  return n_nodes > 0 &&
         check_node(nodes, n_nodes, 0, k->depth, &next_node, &next_face,
                    k->first + k->n) &&
         next_node == n_nodes && next_face == k->first + k->n;
}

/*
 * A node as it travels: its box in single precision, which holds it
 * exactly (split_node sets a node's box from the faces' float boxes
 * alone), and its first and count; 32 bytes against the 56 of a
 * zr_bvh_bin_node.
 */
typedef struct wire_node {
  float lo[3], hi[3];
  uint32_t first, count;
} wire_node;

/*
 * Another member's built tasks (part, as pack_tasks wrote it) taken
 * into t: a task is taken when it is one dealt to that member, its tree
 * passes subtree_ok and its faces are those of the task's rows here
 * (mark: a byte per face, all 0 on entry and on return).  Tasks not
 * taken stay unbuilt (built[i] 0): the caller builds them itself.
 */
static void take_part(top_build *t, const char *at, const char *end,
                      int member, const int *owner, unsigned char *built,
                      unsigned char *mark, size_t n_faces) {
  face_box *boxes = t->top.boxes;
  for (;;) {
    uint32_t index, n_nodes;
    if (!zr__unpack(&at, end, &index, sizeof index) ||
        !zr__unpack(&at, end, &n_nodes, sizeof n_nodes) ||
        index >= t->n_tasks || owner[index] != member || built[index])
      return;
    subtree *k = &t->tasks[index];
    size_t node_bytes = (size_t)n_nodes * sizeof(wire_node);
    if ((size_t)(end - at) < node_bytes ||
        (size_t)(end - at) - node_bytes < k->n * sizeof(uint32_t))
      return;
    zr_bvh_bin_node *nodes =
        malloc(n_nodes ? n_nodes * sizeof *nodes : 1);
    if (!nodes)
      return;
    for (size_t j = 0; j < n_nodes; j++) {
      wire_node w;
      memcpy(&w, at + j * sizeof w, sizeof w);
      for (int a = 0; a < 3; a++) {
        nodes[j].lo[a] = w.lo[a];
        nodes[j].hi[a] = w.hi[a];
      }
      nodes[j].first = w.first;
      nodes[j].count = w.count;
    }
    at += node_bytes;
    const char *faces = at;
    at += k->n * sizeof(uint32_t);
    bool ok = subtree_ok(k, nodes, n_nodes);
    for (size_t i = 0; i < k->n; i++)
      mark[boxes[k->first + i].face] = 1;
    for (size_t i = 0; ok && i < k->n; i++) {
      uint32_t f;
      memcpy(&f, faces + i * sizeof f, sizeof f);
      ok = f < n_faces && mark[f];
      if (ok)
        mark[f] = 0;
    }
    /* The marks left (of a part refused half way) are cleared. */
    for (size_t i = 0; i < k->n; i++)
      mark[boxes[k->first + i].face] = 0;
    if (!ok) {
      free(nodes);
      continue;
    }
    for (size_t i = 0; i < k->n; i++)
      memcpy(&boxes[k->first + i].face, faces + i * sizeof(uint32_t),
             sizeof(uint32_t));
    k->b.nodes = nodes;
    k->b.n_nodes = k->b.cap_nodes = n_nodes;
    k->status = ZR_OK;
    built[index] = 1;
  }
}

/* This member's built tasks, for take_part: for each its index, its
   node count, the nodes (wire_node) and the face of each of its rows
   in leaf order.  The size is known first, so the pack is made once
   (a pack grown by doubling touched fresh pages for every step). */
static void pack_tasks(const top_build *t, const size_t *which, size_t count,
                       zr__pack *pack) {
  size_t bytes = 0;
  for (size_t i = 0; i < count; i++) {
    const subtree *k = &t->tasks[which[i]];
    bytes += 2 * sizeof(uint32_t) + k->b.n_nodes * sizeof(wire_node) +
             k->n * sizeof(uint32_t);
  }
  zr__pack_reserve(pack, bytes);
  for (size_t i = 0; i < count; i++) {
    const subtree *k = &t->tasks[which[i]];
    uint32_t index = (uint32_t)which[i], n_nodes = (uint32_t)k->b.n_nodes;
    zr__pack_put(pack, &index, sizeof index);
    zr__pack_put(pack, &n_nodes, sizeof n_nodes);
    for (size_t j = 0; j < k->b.n_nodes; j++) {
      const zr_bvh_bin_node *node = &k->b.nodes[j];
      wire_node w;
      for (int a = 0; a < 3; a++) {
        w.lo[a] = (float)node->lo[a];
        w.hi[a] = (float)node->hi[a];
      }
      w.first = node->first;
      w.count = node->count;
      zr__pack_put(pack, &w, sizeof w);
    }
    for (size_t f = 0; f < k->n; f++)
      zr__pack_put(pack, &t->top.boxes[k->first + f].face,
                   sizeof(uint32_t));
  }
}

/*
 * build_top's tasks, built by this process's threads or shared with a
 * team's members.  With a team (several members, in step) the tasks are
 * dealt by deal_tasks, each member builds its own with its threads, and
 * one zr__team_exchange gives every member the others' (their nodes and
 * the order of their faces), which take_part checks before it takes
 * them; any task not received that way (an exchange that failed, a part
 * refused) is built here, so the tree is build_node's in every case.
 * *team_on becomes false when the exchange failed: the members all see
 * it fail alike.
 */
static zr_status build_tasks_shared(top_build *t, zr_status top,
                                    size_t n_faces, int threads,
                                    const zr_team *team, bool *team_on) {
  int members = zr__team_size(team), me = zr__team_rank(team);
  int *owner = calloc(t->n_tasks ? t->n_tasks : 1, sizeof *owner);
  unsigned char *built = calloc(t->n_tasks ? t->n_tasks : 1, 1);
  size_t *which = malloc((t->n_tasks ? t->n_tasks : 1) * sizeof *which);
  zr_status s = top != ZR_OK              ? top
                : owner && built && which ? ZR_OK
                                          : ZR_ENOMEM;
  if (s == ZR_OK && members > 1 && !deal_tasks(t, members, owner))
    s = ZR_ENOMEM;
  size_t count = 0;
  for (size_t i = 0; s == ZR_OK && i < t->n_tasks; i++)
    if (owner[i] == me)
      which[count++] = i;
  if (s == ZR_OK)
    build_some(t, which, count, threads);
  for (size_t i = 0; s == ZR_OK && i < count; i++) {
    s = t->tasks[which[i]].status;
    built[which[i]] = 1;
  }
  if (members > 1) {
    /* Every member in step comes here once a mesh, failed or not. */
    zr__pack pack = {0};
    if (s == ZR_OK)
      pack_tasks(t, which, count, &pack);
    zr_status local = s == ZR_OK && pack.nomem ? ZR_ENOMEM : s;
    zr__team_parts parts;
    zr_status e = zr__team_exchange(team, local, pack.bytes, pack.n, &parts);
    zr__pack_free(&pack);
    unsigned char *mark = e == ZR_OK ? calloc(n_faces ? n_faces : 1, 1)
                                     : NULL;
    for (int r = 0; mark && r < members; r++)
      if (r != me)
        take_part(t, parts.bytes + parts.offset[r],
                  parts.bytes + parts.offset[r + 1], r, owner, built, mark,
                  n_faces);
    free(mark);
    zr__team_parts_free(&parts);
    if (e != ZR_OK)
      *team_on = false;
  }
  /* What no member delivered is built here. */
  count = 0;
  for (size_t i = 0; s == ZR_OK && i < t->n_tasks; i++)
    if (!built[i])
      which[count++] = i;
  if (s == ZR_OK)
    build_some(t, which, count, threads);
  for (size_t i = 0; s == ZR_OK && i < count; i++)
    s = t->tasks[which[i]].status;
  free(owner);
  free(built);
  free(which);
  return s;
}

/*
 * The faces' order, the boxes' last use: order gets each box's face and
 * the boxes (b's, n of them) are unmapped, before the final node array
 * is made, so the two are never held at once (6 MiB of boxes in huge
 * pages, the terrain's nodes 4 MiB).
 */
static void take_order(builder *b, size_t n, uint32_t *order) {
  for (size_t i = 0; i < n; i++)
    order[i] = b->boxes[i].face;
  zr__map_free(b->boxes, n * sizeof *b->boxes);
  b->boxes = NULL;
}

static zr_status build_parallel(builder *b, size_t n, int threads,
                                const zr_team *team, bool *team_on,
                                const fbox *bounds, const fbox *centres,
                                uint32_t *order) {
  top_build t;
  memset(&t, 0, sizeof t);
  t.top.boxes = b->boxes;
  /* Some 8 tasks a thread, so that unequal halves even out; with a
     team some 8 a member, whatever its threads, so that every member
     makes the same tasks (a rank's default threads depend on its
     host). */
  int members = zr__team_size(team);
  t.cutoff = n / (8 * (size_t)(members > 1 ? members : threads));
  if (t.cutoff < LEAF_SAH_MAX)
    t.cutoff = LEAF_SAH_MAX;
  zr_status s = build_top(&t, 0, n, 0, bounds, centres);
  size_t *task_of = NULL;
  /* With a team the exchange is reached whatever build_top did. */
  if (s == ZR_OK || members > 1)
    s = build_tasks_shared(&t, s, n, threads, team, team_on);
  if (s == ZR_OK) {
    size_t total = t.top.n_nodes;
    for (size_t i = 0; i < t.n_tasks && s == ZR_OK; i++) {
      s = t.tasks[i].status;
      total += t.tasks[i].b.n_nodes;
    }
    if (s == ZR_OK)
      take_order(b, n, order);
    task_of = malloc(t.top.n_nodes * sizeof *task_of);
    b->nodes = zr__map_alloc(total * sizeof *b->nodes);
    if (b->nodes)
      b->cap_nodes = total;
    if (s == ZR_OK && (!task_of || !b->nodes))
      s = ZR_ENOMEM;
    if (s == ZR_OK) {
      for (size_t i = 0; i < t.top.n_nodes; i++)
        task_of[i] = SIZE_MAX;
      for (size_t i = 0; i < t.n_tasks; i++)
        task_of[t.tasks[i].top] = i;
      b->n_nodes = 0;
      splice(&t, task_of, 0, b->nodes, &b->n_nodes);
    }
  }
  for (size_t i = 0; i < t.n_tasks; i++)
    if (t.tasks[i].run < 0)
      free(t.tasks[i].b.nodes);
  for (int i = 0; i < t.n_runs; i++)
    zr__map_free(t.runs[i].nodes, t.runs[i].cap * sizeof *t.runs[i].nodes);
  free(t.runs);
  free(t.tasks);
  free(t.top.nodes);
  free(task_of);
  return s;
}

/*
 * The key of a mesh's build in a team's step (zr__team_same_key): a
 * hash of the faces' boxes in their order and their number, which is
 * all the tree depends on, so members whose keys agree build parts of
 * one tree.  Four independent lanes of multiply and xor over the boxes'
 * 64-bit words, so the products do not wait on each other.  Never
 * ZR__TEAM_KEY_DONE (the lowest bit is set).
 */
static uint64_t boxes_key(const face_box *boxes, size_t n) {
  const uint64_t k = 0x9e3779b97f4a7c15u;
  uint64_t lane[4] = {n, k, ~(uint64_t)n, 0x5bd1e9955bd1e995u};
  const unsigned char *bytes = (const unsigned char *)boxes;
  size_t words = n * sizeof *boxes / 8, i = 0;
  for (; i + 4 <= words; i += 4)
    for (int j = 0; j < 4; j++) {
      uint64_t w;
      memcpy(&w, bytes + (i + (size_t)j) * 8, 8);
      lane[j] = (lane[j] ^ w) * k;
      lane[j] ^= lane[j] >> 29;
    }
  for (; i < words; i++) {
    uint64_t w;
    memcpy(&w, bytes + i * 8, 8);
    lane[0] = (lane[0] ^ w) * k;
    lane[0] ^= lane[0] >> 29;
  }
  uint64_t tail = 0;
  memcpy(&tail, bytes + words * 8, n * sizeof *boxes - words * 8);
  uint64_t h = (lane[0] ^ tail) * k;
  for (int j = 1; j < 4; j++)
    h = ((h ^ (h >> 31)) + lane[j]) * k;
  return (h ^ (h >> 32)) | 1;
}

/* The faces' boxes, computed in BOX_PARTS parts of the faces (a part
   a call of zr__parallel_for's), each part's union kept apart. */
enum { BOX_PARTS = 16 };

typedef struct face_boxes {
  struct zr_mesh *mesh;
  face_box *boxes;
  zr_vec3 lo[BOX_PARTS], hi[BOX_PARTS];
} face_boxes;

static void box_faces(void *user, size_t begin, size_t end, int worker) {
  (void)worker;
  face_boxes *fbs = user;
  const struct zr_mesh *mesh = fbs->mesh;
  size_t n = mesh->n_faces;
  for (size_t part = begin; part < end; part++) {
    zr_vec3 part_lo = zr_v3(INFINITY, INFINITY, INFINITY);
    zr_vec3 part_hi = zr_v3_neg(part_lo);
    size_t f0 = n / BOX_PARTS * part + (part < n % BOX_PARTS ? part
                                                            : n % BOX_PARTS);
    size_t f1 = f0 + n / BOX_PARTS + (part < n % BOX_PARTS);
    for (size_t f = f0; f < f1; f++) {
      zr_vec3 lo = zr_v3(INFINITY, INFINITY, INFINITY), hi = zr_v3_neg(lo);
      for (int k = 0; k < 3; k++) {
        zr_vec3 p = mesh->vertices[mesh->faces[f][k]];
        lo = zr_v3_min(lo, p);
        hi = zr_v3_max(hi, p);
      }
      part_lo = zr_v3_min(part_lo, lo);
      part_hi = zr_v3_max(part_hi, hi);
      face_box *fb = &fbs->boxes[f];
      double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
      for (int a = 0; a < 3; a++) {
        /* Single precision bounds that still contain the double value
           (bvh_wide.h's roundings: nextafterf's floats, without its
           call, which took 1.4% of the terrain's parse). */
        fb->lo[a] = zr__float_down(l[a]);
        fb->hi[a] = zr__float_up(h[a]);
        fb->centre[a] = (float)(0.5 * (l[a] + h[a]));
      }
      fb->face = (uint32_t)f;
    }
    fbs->lo[part] = part_lo;
    fbs->hi[part] = part_hi;
  }
}

/* Puts the rows of an n-row table of row-size bytes in the given order,
   through one scratch copy: in spare (spare_size bytes) when it has
   room, else in a block of its own. */
static zr_status permute(void *rows, size_t row, const uint32_t *order,
                         size_t n, void *spare, size_t spare_size) {
  if (!rows)
    return ZR_OK;
  bool own = spare_size < n * row;
  unsigned char *tmp = own ? zr__map_alloc(n * row) : spare;
  if (!tmp)
    return ZR_ENOMEM;
  const unsigned char *src = rows;
  for (size_t i = 0; i < n; i++)
    memcpy(tmp + i * row, src + (size_t)order[i] * row, row);
  memcpy(rows, tmp, n * row);
  if (own)
    zr__map_free(tmp, n * row);
  return ZR_OK;
}

static bool check_indices(const uint32_t (*rows)[3], size_t n, size_t limit,
                          size_t *bad) {
  if (!rows)
    return true;
  for (size_t f = 0; f < n; f++)
    for (int k = 0; k < 3; k++)
      if (rows[f][k] >= limit) {
        *bad = f;
        return false;
      }
  return true;
}

zr_status zr__mesh_build(struct zr_mesh *mesh, zr_arena *arena,
                         int threads, size_t *bad_face) {
  bool team_on = false;
  return zr__mesh_build_team(mesh, arena, threads, NULL, &team_on,
                             bad_face);
}

zr_status zr__mesh_build_team(struct zr_mesh *mesh, zr_arena *arena,
                              int threads, const zr_team *team,
                              bool *team_on, size_t *bad_face) {
  size_t n = mesh->n_faces;
  *bad_face = 0;
  if (!check_indices((const uint32_t(*)[3])mesh->faces, n,
                     mesh->n_vertices, bad_face) ||
      !check_indices((const uint32_t(*)[3])mesh->face_normals, n,
                     mesh->n_normals, bad_face) ||
      !check_indices((const uint32_t(*)[3])mesh->face_uvs, n, mesh->n_uvs,
                     bad_face))
    return ZR_ESCENE;
  if (mesh->face_textures)
    for (size_t f = 0; f < n; f++)
      for (int k = 0; k < 3; k++)
        if (mesh->face_textures[f][k] >= (int32_t)mesh->n_textures) {
          *bad_face = f;
          return ZR_ESCENE;
        }
  if (n > UINT32_MAX / 2)
    return ZR_ENOMEM;
  mesh->lo = zr_v3(INFINITY, INFINITY, INFINITY);
  mesh->hi = zr_v3_neg(mesh->lo);
  if (n == 0)
    return ZR_OK;
  /* The build's scratch arrays (5.2 MB of boxes for a 130,050-face
     terrain, the order, the permutations' copies, the wide nodes) are
     filled once: in 4 KiB pages they took 2,100 of its parse's 6,900
     page faults (perf record -e page-faults, --parse-only), about 14 us
     each on this project's VM, so they come in huge pages, in mappings
     of their own that are unmapped when freed (zr__map_alloc,
     core/arena.h), and the nodes are never grown by copying (a lone
     build's room is the most nodes there can be, a parallel build's
     tasks share a run per worker).  bench/results/
     arena-2026-12-03-s15.md has the faults and peaks. */
  /* The order is written all through: faulted in at once. */
  face_box *boxes = zr__map_alloc(n * sizeof *boxes);
  uint32_t *order = zr__map_alloc(n * sizeof *order);
  zr__mem_populate(order, n * sizeof *order);
  builder b = {boxes, NULL, 0, 0, false};
  zr_wide_node *wide = NULL;
  zr_status s = ZR_ENOMEM;
  if (!boxes || !order)
    goto done;
  face_boxes fbs;
  memset(&fbs, 0, sizeof fbs);
  fbs.mesh = mesh;
  fbs.boxes = boxes;
  if (threads > 1 && n >= PARALLEL_FACES_MIN) {
    /* Each part's bounds in a slot of its own, combined in order below
       (a minimum is exact, so any order gives the same box). */
    zr__parallel_for(threads, BOX_PARTS, 1, box_faces, &fbs, NULL);
  } else {
    box_faces(&fbs, 0, BOX_PARTS, 0);
  }
  for (int i = 0; i < BOX_PARTS; i++) {
    mesh->lo = zr_v3_min(mesh->lo, fbs.lo[i]);
    mesh->hi = zr_v3_max(mesh->hi, fbs.hi[i]);
  }
  fbox bounds, centres;
  bounds_of(boxes, n, &bounds, &centres);
  /* A team shares the build of a mesh as large as threads would, once
     its members agree that they hold the same faces; else each builds
     alone from here on (zr__team_same_key). */
  const zr_team *shared = NULL;
  if (*team_on && zr__team_size(team) > 1 && n >= PARALLEL_FACES_MIN) {
    if (zr__team_same_key(team, ZR_OK, boxes_key(boxes, n)) == ZR_OK)
      shared = team;
    else
      *team_on = false;
  }
  if (shared || (threads > 1 && n >= PARALLEL_FACES_MIN)) {
    if ((size_t)threads > n / PARALLEL_FACES_MIN)
      threads = (int)(n / PARALLEL_FACES_MIN);
    s = build_parallel(&b, n, threads, shared, team_on, &bounds, &centres,
                       order);
  } else {
    /* Room for the most nodes n faces can have, of which a prefix is
       used (0.54 a face on the terrain): no doubling and copying, and
       the pages past the nodes made are never touched. */
    b.nodes = zr__map_alloc((2 * n - 1) * sizeof *b.nodes);
    b.cap_nodes = b.nodes ? 2 * n - 1 : 0;
    b.fixed = true;
    s = b.nodes ? build_node(&b, 0, n, 0, &bounds, &centres) : ZR_ENOMEM;
    if (s == ZR_OK)
      take_order(&b, n, order);
  }
  if (s != ZR_OK)
    goto done;
  /* The binary tree collapsed four wide: each wide node stands for one
     to three of its inner nodes, so b.n_nodes of them are room enough. */
  wide = zr__map_alloc(b.n_nodes * sizeof *wide);
  if (!wide) {
    s = ZR_ENOMEM;
    goto done;
  }
  size_t n_wide = zr__bvh_collapse(b.nodes, wide);
  mesh->nodes = zr__arena_memdup(arena, wide, n_wide * sizeof *wide);
  zr__map_free(wide, b.n_nodes * sizeof *wide);
  wide = NULL;
  mesh->face_row = zr__arena_alloc(arena, n * sizeof *mesh->face_row);
  if (!mesh->nodes || !mesh->face_row) {
    s = ZR_ENOMEM;
    goto done;
  }
  /* The binary nodes, collapsed, are done with: their pages (the
     terrain's 3.9 MB, 56 bytes a node and 0.54 nodes a face) hold each
     permutation's copy (12 bytes a face), where a block of its own cost
     a mapping and its faults each. */
  void *spare = b.nodes;
  size_t spare_size = b.n_nodes * sizeof *b.nodes;
  if ((s = permute(mesh->faces, sizeof *mesh->faces, order, n, spare,
                   spare_size)) != ZR_OK ||
      (s = permute(mesh->face_normals, sizeof *mesh->face_normals, order, n,
                   spare, spare_size)) != ZR_OK ||
      (s = permute(mesh->face_uvs, sizeof *mesh->face_uvs, order, n, spare,
                   spare_size)) != ZR_OK ||
      (s = permute(mesh->face_textures, sizeof *mesh->face_textures, order,
                   n, spare, spare_size)) != ZR_OK)
    goto done;
  for (size_t i = 0; i < n; i++)
    mesh->face_row[order[i]] = (uint32_t)i;
  mesh->n_nodes = n_wide;
done:
  zr__map_free(wide, b.n_nodes * sizeof *wide);
  zr__map_free(b.nodes, b.cap_nodes * sizeof *b.nodes);
  zr__map_free(order, n * sizeof *order);
  zr__map_free(b.boxes, n * sizeof *b.boxes);
  return s;
}

/* ---- tracing ---- */

/* Moller-Trumbore's start for face f: its edges from p0, dir x e2 and
   the reciprocal determinant; false when the ray runs parallel to the
   face (or the face is degenerate). */
static inline bool face_start(const struct zr_mesh *m, size_t f,
                              zr_vec3 dir, zr_vec3 *p0, zr_vec3 *e1,
                              zr_vec3 *e2, zr_vec3 *pv, double *inv) {
  const uint32_t *idx = m->faces[f];
  *p0 = m->vertices[idx[0]];
  *e1 = zr_v3_sub(m->vertices[idx[1]], *p0);
  *e2 = zr_v3_sub(m->vertices[idx[2]], *p0);
  *pv = zr_v3_cross(dir, *e2);
  double det = zr_v3_dot(*e1, *pv);
  if (det == 0.0 || !isfinite(det))
    return false;
  *inv = 1.0 / det;
  return true;
}

/* Moller-Trumbore; true with t, u, v when the ray crosses face f. */
static bool face_hit(const struct zr_mesh *m, size_t f, zr_vec3 org,
                     zr_vec3 dir, double *t, double *u, double *v) {
  zr_vec3 p0, e1, e2, pv;
  double inv;
  if (!face_start(m, f, dir, &p0, &e1, &e2, &pv, &inv))
    return false;
  zr_vec3 tv = zr_v3_sub(org, p0);
  double uu = zr_v3_dot(tv, pv) * inv;
  if (uu < 0.0 || uu > 1.0)
    return false;
  zr_vec3 qv = zr_v3_cross(tv, e1);
  double vv = zr_v3_dot(dir, qv) * inv;
  if (vv < 0.0 || uu + vv > 1.0)
    return false;
  *t = zr_v3_dot(e2, qv) * inv;
  *u = uu;
  *v = vv;
  return true;
}

bool zr__mesh_face_hit(const struct zr_mesh *m, size_t f, zr_vec3 org,
                       zr_vec3 dir, double *t, double *u, double *v) {
  return face_hit(m, f, org, dir, t, u, v);
}

bool zr__mesh_face_plane(const struct zr_mesh *m, size_t f, zr_vec3 org,
                         zr_vec3 dir, double *t, double *u, double *v) {
  zr_vec3 p0, e1, e2, pv;
  double inv;
  if (!face_start(m, f, dir, &p0, &e1, &e2, &pv, &inv))
    return false;
  zr_vec3 tv = zr_v3_sub(org, p0);
  zr_vec3 qv = zr_v3_cross(tv, e1);
  *u = zr_v3_dot(tv, pv) * inv;
  *v = zr_v3_dot(dir, qv) * inv;
  *t = zr_v3_dot(e2, qv) * inv;
  return true;
}

/* The slab test's form of the line org + t dir (lib/trace/bvh_wide.h). */
static void make_slab(zr_vec3 org, zr_vec3 dir, zr_slab_ray *r) {
  zr_ray ray = {org, dir};
  zr__make_slab_ray(&ray, r);
}

/* The four-wide tree's depth is at most the binary tree's (build_node:
   DEPTH_MAX levels of splits, then halvings of at most 2^32 faces), and
   each node pushes at most three more entries than it pops. */
enum { WIDE_STACK_MAX = 3 * STACK_MAX + 1 };

/* A crossing found during traversal, before its normal is made. */
typedef zr_mesh_raw_hit raw_hit;

static zr_mesh_crossing finish_hit(const struct zr_mesh *m,
                                   const raw_hit *h) {
  zr_mesh_crossing c;
  c.t = h->t;
  c.face = h->face;
  const uint32_t *idx = m->faces[h->face];
  zr_vec3 p0 = m->vertices[idx[0]];
  c.normal = zr_v3_cross(zr_v3_sub(m->vertices[idx[1]], p0),
                         zr_v3_sub(m->vertices[idx[2]], p0));
  double w[3] = {1.0 - h->u - h->v, h->u, h->v};
  if (m->face_normals) {
    const uint32_t *ni = m->face_normals[h->face];
    zr_vec3 s = zr_v3(0, 0, 0);
    for (int k = 0; k < 3; k++)
      s = zr_v3_madd(s, m->normals[ni[k]], w[k]);
    if (zr_v3_dot(s, s) > 0.0 && isfinite(zr_v3_dot(s, s)))
      c.normal = s;
  }
  /* uv_mapping: the corners' uv_vectors blended like the normals;
     without them POV-Ray gives each triangle (0,0), (1,0), (1,1). */
  if (m->uvs && m->face_uvs) {
    const uint32_t *ui = m->face_uvs[h->face];
    c.u = w[0] * m->uvs[ui[0]][0] + w[1] * m->uvs[ui[1]][0] +
          w[2] * m->uvs[ui[2]][0];
    c.v = w[0] * m->uvs[ui[0]][1] + w[1] * m->uvs[ui[1]][1] +
          w[2] * m->uvs[ui[2]][1];
  } else {
    c.u = w[1] + w[2];
    c.v = w[2];
  }
  c.texture = -1;
  if (m->face_textures) {
    /* Three texture indices per face: POV-Ray blends the corners'
       textures; zRcube takes the corner nearest the hit (the parser
       warns about this). */
    int k = w[1] > w[0] ? (w[2] > w[1] ? 2 : 1) : (w[2] > w[0] ? 2 : 0);
    const int32_t *ti = m->face_textures[h->face];
    c.texture = ti[1] == ti[0] && ti[2] == ti[0] ? ti[0] : ti[k];
  }
  return c;
}

int zr__mesh_crossings(const struct zr_mesh *m, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, zr_mesh_crossing out[2]) {
  if (m->n_nodes == 0)
    return 0;
  if (m->accel) {
    /* Embree names the triangles (lib/trace/embree.c); -1: a ray it
       cannot take, which the hierarchy below searches. */
    raw_hit h[2];
    int n = zr__embree_crossings(m, org, dir, tmin, tmax, h);
    for (int i = 0; i < n; i++)
      out[i] = finish_hit(m, &h[i]);
    if (n >= 0)
      return n;
  }
  zr_slab_ray sr;
  make_slab(org, dir, &sr);
  raw_hit best[2];
  int n = 0;
  /* With two crossings kept, nodes beyond the second are skipped. */
  double limit = tmax;
  const float tmin_f = zr__float_down(tmin);
  float limit_f = zr__float_up(limit);
  /* Leaves are searched in the tree's left-to-right order. */
  zr_wide_entry stack[WIDE_STACK_MAX];
  int sp = 0;
  stack[sp++] = (zr_wide_entry){0, 0, tmin_f};
  while (sp > 0) {
    zr_wide_entry e = stack[--sp];
    if (e.t > limit)
      continue;
    if (e.count > 0) {
      for (uint32_t f = e.child; f < e.child + e.count; f++) {
        raw_hit h;
        if (!face_hit(m, f, org, dir, &h.t, &h.u, &h.v) ||
            !(h.t > tmin && h.t < limit))
          continue;
        h.face = f;
        if (n < 2) {
          best[n++] = h;
        } else {
          best[1] = h;
        }
        if (n == 2 && best[1].t < best[0].t) {
          raw_hit t = best[0];
          best[0] = best[1];
          best[1] = t;
        }
        if (n == 2) {
          limit = best[1].t;
          limit_f = zr__float_up(limit);
        }
      }
      continue;
    }
    const zr_wide_node *w = &m->nodes[e.child].wide;
    float t[ZR_WIDE_WIDTH];
    unsigned mask = zr__slab_entries(w, &sr, tmin_f, limit_f, t);
    sp = zr__wide_push_in_order(w, mask, t, stack, sp, WIDE_STACK_MAX);
  }
  for (int i = 0; i < n; i++)
    out[i] = finish_hit(m, &best[i]);
  return n;
}

/*
 * The nearest crossing alone, for the tracer's search of the nearest
 * surface: the first of zr__mesh_crossings' two, the least (t, face),
 * found with nodes visited nearest first and pruned at the best t so far
 * (the search for two prunes only at its second crossing, which a
 * terrain seldom has: every box behind the hit was opened).  Faces are
 * stored in leaf order, so the least face index among equal t is the
 * one the search for two keeps first.
 */
int zr__mesh_nearest(const struct zr_mesh *m, zr_vec3 org, zr_vec3 dir,
                     double tmin, double tmax, zr_mesh_crossing *out) {
  if (m->n_nodes == 0)
    return 0;
  if (m->accel) {
    raw_hit h;
    int n = zr__embree_nearest(m, org, dir, tmin, tmax, &h);
    if (n > 0)
      *out = finish_hit(m, &h);
    if (n >= 0)
      return n;
  }
  zr_slab_ray sr;
  make_slab(org, dir, &sr);
  raw_hit best;
  bool found = false;
  double limit = tmax;
  const float tmin_f = zr__float_down(tmin);
  float limit_f = zr__float_up(limit);
  zr_wide_entry stack[WIDE_STACK_MAX];
  int sp = 0;
  stack[sp++] = (zr_wide_entry){0, 0, tmin_f};
  while (sp > 0) {
    zr_wide_entry e = stack[--sp];
    if (e.t > limit)
      continue;
    if (e.count > 0) {
      for (uint32_t f = e.child; f < e.child + e.count; f++) {
        raw_hit h;
        if (!face_hit(m, f, org, dir, &h.t, &h.u, &h.v) ||
            !(h.t > tmin && h.t < tmax))
          continue;
        h.face = f;
        if (!found || h.t < best.t || (h.t == best.t && h.face < best.face)) {
          best = h;
          found = true;
          limit = h.t;
          limit_f = zr__float_up(limit);
        }
      }
      continue;
    }
    const zr_wide_node *w = &m->nodes[e.child].wide;
    float t[ZR_WIDE_WIDTH];
    unsigned mask = zr__slab_entries(w, &sr, tmin_f, limit_f, t);
    /* The nearest child met is searched first and lowers the limit for
       the others. */
    sp = zr__wide_push_nearest_first(w, mask, t, stack, sp, WIDE_STACK_MAX);
  }
  if (found)
    *out = finish_hit(m, &best);
  return found;
}

/* A world ray in the mesh object's own space. */
static void mesh_ray(const zr_object *o, const zr_ray *ray, zr_vec3 *org,
                     zr_vec3 *dir) {
  *org = ray->origin;
  *dir = ray->dir;
  if (o->transform) {
    *org = zr__xform_point(o->transform->inv, *org);
    *dir = zr__xform_dir(o->transform->inv, *dir);
  }
}

/* The zr_hit of a crossing, as zr__intersect_t gives it: no normal. */
static int mesh_crossing_hit(const zr_object *o, const zr_mesh_crossing *c,
                             zr_hit *hit) {
  hit->t = c->t;
  hit->normal = zr_v3(0, 0, 0);
  hit->object = zr__mesh_hit_object(o, c->texture);
  hit->u = c->u;
  hit->v = c->v;
  return 1;
}

int zr__mesh_nearest_t(const zr_object *o, const zr_ray *ray, double tmin,
                       double tmax, zr_hit *hit, zr_vec3 *normal) {
  /* As zr__intersect_t takes a mesh (intersect.c): in the mesh's own
     space, the first crossing, no normal in the hit. */
  zr_vec3 org, dir;
  mesh_ray(o, ray, &org, &dir);
  zr_mesh_crossing c;
  if (!zr__mesh_nearest(o->u.mesh.data, org, dir, tmin, tmax, &c))
    return 0;
  *normal = c.normal;
  return mesh_crossing_hit(o, &c, hit);
}

zr_vec3 zr__mesh_world_normal(const zr_object *o, zr_vec3 n) {
  /* intersect.c's crossings() with normals, step for step. */
  if (o->transform)
    n = zr__xform_normal(o->transform->inv, n);
  n = zr_v3_norm(n);
  return o->inverse ? zr_v3_neg(n) : n;
}

/* The first crossing the hierarchy meets, in its left-to-right order. */
static bool mesh_any(const struct zr_mesh *m, zr_vec3 org, zr_vec3 dir,
                     double tmin, double tmax, raw_hit *out) {
  if (m->n_nodes == 0)
    return false;
  if (m->accel) {
    int n = zr__embree_nearest(m, org, dir, tmin, tmax, out);
    if (n >= 0)
      return n > 0;
  }
  zr_slab_ray sr;
  make_slab(org, dir, &sr);
  const float tmin_f = zr__float_down(tmin), tmax_f = zr__float_up(tmax);
  zr_wide_entry stack[WIDE_STACK_MAX];
  int sp = 0;
  stack[sp++] = (zr_wide_entry){0, 0, tmin_f};
  while (sp > 0) {
    zr_wide_entry e = stack[--sp];
    if (e.count > 0) {
      for (uint32_t f = e.child; f < e.child + e.count; f++)
        if (face_hit(m, f, org, dir, &out->t, &out->u, &out->v) &&
            out->t > tmin && out->t < tmax) {
          out->face = f;
          return true;
        }
      continue;
    }
    const zr_wide_node *w = &m->nodes[e.child].wide;
    float t[ZR_WIDE_WIDTH];
    unsigned mask = zr__slab_entries(w, &sr, tmin_f, tmax_f, t);
    sp = zr__wide_push_in_order(w, mask, t, stack, sp, WIDE_STACK_MAX);
  }
  return false;
}

int zr__mesh_any_t(const zr_object *o, const zr_ray *ray, double tmin,
                   double tmax, zr_hit *hit) {
  zr_vec3 org, dir;
  mesh_ray(o, ray, &org, &dir);
  const struct zr_mesh *m = o->u.mesh.data;
  raw_hit h;
  if (!mesh_any(m, org, dir, tmin, tmax, &h))
    return 0;
  zr_mesh_crossing c = finish_hit(m, &h);
  return mesh_crossing_hit(o, &c, hit);
}

bool zr__mesh_inside(const struct zr_mesh *m, zr_vec3 p) {
  if (!m->has_inside || m->n_nodes == 0)
    return false;
  zr_vec3 dir = m->inside_vector;
  zr_slab_ray sr;
  make_slab(p, dir, &sr);
  size_t crossings = 0;
  zr_wide_entry stack[WIDE_STACK_MAX];
  int sp = 0;
  stack[sp++] = (zr_wide_entry){0, 0, 0.0f};
  while (sp > 0) {
    zr_wide_entry e = stack[--sp];
    if (e.count > 0) {
      for (uint32_t f = e.child; f < e.child + e.count; f++) {
        double t, u, v;
        if (face_hit(m, f, p, dir, &t, &u, &v) && t > 0.0)
          crossings++;
      }
      continue;
    }
    const zr_wide_node *w = &m->nodes[e.child].wide;
    float t[ZR_WIDE_WIDTH];
    unsigned mask = zr__slab_entries(w, &sr, 0.0f, INFINITY, t);
    sp = zr__wide_push_in_order(w, mask, t, stack, sp, WIDE_STACK_MAX);
  }
  return crossings % 2 == 1;
}

zr_status zr__mesh_instance(zr_arena *arena, const zr_object **prim) {
  const zr_object *o = *prim;
  if (o->kind != ZR_OBJ_MESH || o->u.mesh.data->n_textures == 0)
    return ZR_OK;
  const struct zr_mesh *m = o->u.mesh.data;
  zr_object *copy = zr__arena_memdup(arena, o, sizeof *copy);
  zr_object *textured = zr__arena_alloc(arena, m->n_textures * sizeof *o);
  if (!copy || !textured)
    return ZR_ENOMEM;
  copy->u.mesh.textured = textured;
  for (size_t k = 0; k < m->n_textures; k++) {
    textured[k] = *copy;
    textured[k].texture =
        o->u.mesh.textures ? o->u.mesh.textures[k] : m->textures[k];
  }
  *prim = copy;
  return ZR_OK;
}

bool zr__mesh_has_inside(const zr_object *object) {
  return object->u.mesh.data->has_inside;
}

/* ---- the operations the tracer calls through (lib/trace/shape.h) ---- */

/* A mesh holds many surfaces, so it searches the interval itself and
   gives the nearest two crossings in it, with their texture list index
   and surface coordinates. */
static void mesh_crossings(const zr_object *o, zr_vec3 org, zr_vec3 dir,
                           double tmin, double tmax, zr_crossings *l) {
  zr_mesh_crossing c[2];
  int n = zr__mesh_crossings(o->u.mesh.data, org, dir, tmin, tmax, c);
  for (int i = 0; i < n; i++) {
    zr__crossings_add(l, c[i].t, c[i].normal);
    l->texture[l->n - 1] = c[i].texture;
    l->u[l->n - 1] = c[i].u;
    l->v[l->n - 1] = c[i].v;
  }
}

static bool mesh_inside(const zr_object *o, zr_vec3 p) {
  return zr__mesh_inside(o->u.mesh.data, p);
}

/* The box of the mesh's vertices; an empty mesh has none. */
static bool mesh_box(const zr_object *o, zr_vec3 *lo, zr_vec3 *hi) {
  *lo = o->u.mesh.data->lo;
  *hi = o->u.mesh.data->hi;
  return o->u.mesh.data->n_faces > 0;
}

const zr_shape_ops zr__shape_mesh = {
    .name = "a mesh",
    .crossings = mesh_crossings,
    .inside = mesh_inside,
    .has_inside = zr__mesh_has_inside,
    .bounds = mesh_box,
    .uv_from_hit = true,
    .hit_object = zr__mesh_hit_object,
    .prepare = zr__mesh_instance,
};
