/*
 * refine.c - links between quadtree nodes: where they go (refinement),
 * which sides they join, how much of the source each receiver sees
 * (visibility) and the form factor they carry.
 *
 * This follows Hanrahan, Salzman and Aupperle, "A Rapid Hierarchical
 * Radiosity Algorithm" (SIGGRAPH 1991).  Every pair of input surfaces
 * that can see each other starts with one link between their roots.  A
 * link from source q to receiver p is refined while the energy it may
 * carry, B_q F_pq A_p with F_pq the cheap oracle estimate (formfactor.h)
 * and B_q the current radiosity of the source, exceeds BF_eps times the
 * scene's emitted power ("BF refinement", their section 5); the node that
 * looks larger from the other (the larger oracle factor) is split, unless
 * it is already smaller than A_eps (criterion 1 replaces the oracle by
 * an error estimate, see error_choice).  Refinement alternates with solving
 * (solve.c), so links that turn out to carry light get refined on the
 * next round.  The oracle's cosines are taken at the cell centres, loosened
 * by the spread of a curved cell's normals so a large curved cell is never
 * judged invisible because its centre faces away.
 *
 * Sides.  A link joins one side of the receiver to one side of the
 * source.  Both are found from 3 x 3 sample points of each cell: the
 * direction between two samples says which side of each surface faces
 * the other.  Coplanar cells see nothing (their factor is 0).  When the
 * receiver has points on both sides of the source (a floor under a box's
 * side face), the receiver is split until each part lies on one side; at
 * A_eps the side of the majority wins.  Receiver points on both sides of
 * their own plane are exact without splitting: each side gets its own
 * link, and the contour formula clips the source to that side.
 *
 * The transfer.  A final link carries F * V: F is the exact
 * point-to-polygon factor (Lambert's contour formula, Baum et al. 1989)
 * integrated over the receiver with Gauss points (zr__ff_patch_patch;
 * curved source cells by their boundary with 16 chords per curved edge),
 * with 3 x 3 cells of Gauss points when the two cells are close, where the
 * integrand varies fast.  A curved cell that sees itself (inside a sphere)
 * has a link to itself, integrated with the bounded kernel
 * cos cos / (pi r^2) on two different Gauss rules so no point meets
 * itself; it is split while B A F_self, with F_self estimated from the
 * spread of the cell's normals, exceeds the threshold.  V is the
 * fraction of k x k rays between stratified points of the two cells
 * that the tracer's BVH finds unobstructed (Hanrahan's paper used a
 * similar fixed set of rays; a fraction, not a yes/no).
 *
 * Threads (params.threads, workers.h).  Transfer factors and visibility,
 * most of the time of a solve, are computed for many links at once,
 * each into its own link.  Refinement is worked out in parallel as plans
 * (one per link or pair of input surfaces) that one thread then replays
 * in order (see "refinement as a plan" below), so the cells and links,
 * and with them the solution, are the same bytes for any thread count.
 */
#include "radiosity/radiosity.h"

#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/arena.h"
#include "core/team.h"
#include "radiosity/formfactor.h"
#include "radiosity/workers.h"
#include "trace/bvh.h"

/* Sample points of a cell for side classification. */
typedef struct cell_samples {
  zr_vec3 p[9], n[9];
} cell_samples;

static void node_samples(const zr_radiosity *rad, const zr__rad_node *node,
                         cell_samples *out) {
  double cell[4];
  zr__rad_node_cell(node, cell);
  static const double f[3] = {0.1, 0.5, 0.9};
  for (int j = 0; j < 3; j++)
    for (int i = 0; i < 3; i++) {
      zr__surface_point pt;
      zr__surface_eval(&rad->surfs[node->surf].geom,
                       cell[0] + f[i] * (cell[1] - cell[0]),
                       cell[2] + f[j] * (cell[3] - cell[2]), &pt);
      out->p[3 * j + i] = pt.p;
      out->n[3 * j + i] = pt.n;
    }
}

/* The side of the closed surface of node n (zr__surface_encloses) that
   the points pts[0..8] see: 1 inside, 0 outside, -1 each when it is not
   closed or a CSG trims it (a hole shows its inside from outside). */
static void enclosed_sides(const zr_radiosity *rad, const zr__rad_node *n,
                           const zr_vec3 pts[9], int out[9]) {
  const zr__rad_surface *s = &rad->surfs[n->surf];
  for (int i = 0; i < 9; i++)
    out[i] = s->trim == NULL ? zr__surface_encloses(&s->geom, pts[i]) : -1;
}

/*
 * Counts of sample pairs per side combination, index 2 * rside + sside,
 * and in counts[4] the pairs whose source point the source's own
 * surface hides (its rim runs through the source cell as seen).
 * On a closed surface (a sphere, a torus) the side a pair would join
 * is checked against the other point's place: a point outside the
 * solid sees only the outward side, and a pair of points of the same
 * closed surface is joined inside or outside at both ends.  A pair that
 * fails is hidden by the surface itself and counts for no side: a wall
 * sees the far half of a ball through the ball, behind those points'
 * tangent planes, and counting it made the wall's cells straddle the
 * ball's "back" side, so they split down to A_eps (a torus or sphere in
 * a room took minutes to link).
 */
static void classify(const zr_radiosity *rad, const zr__rad_node *p,
                     const zr__rad_node *q, int counts[5]) {
  cell_samples a, b;
  node_samples(rad, p, &a);
  node_samples(rad, q, &b);
  bool same = p->surf == q->surf;
  int in_p[9], in_q[9]; /* b's points against p's solid, a's against q's */
  enclosed_sides(rad, p, b.p, in_p);
  enclosed_sides(rad, q, a.p, in_q);
  memset(counts, 0, 5 * sizeof *counts);
  for (int i = 0; i < 9; i++)
    for (int j = 0; j < 9; j++) {
      zr_vec3 d = zr_v3_sub(b.p[j], a.p[i]);
      double len = zr_v3_len(d);
      if (!(len > 0.0))
        continue;
      double ca = zr_v3_dot(d, a.n[i]) / len;
      double cb = -zr_v3_dot(d, b.n[j]) / len;
      /* Coplanar up to rounding: no light passes edge-on. */
      if (fabs(ca) < 1e-7 || fabs(cb) < 1e-7)
        continue;
      int rs = ca < 0.0, ss = cb < 0.0;
      /* Hidden at the source end: the receiver's side of the pair is
         right but the source point turns its other side to it. */
      bool hidden_q = same ? in_p[j] >= 0 && rs != ss
                           : in_q[i] >= 0 && ss != in_q[i];
      if (hidden_q) {
        counts[4] += same || in_p[j] < 0 || rs == in_p[j];
        continue;
      }
      if (!same && in_p[j] >= 0 && rs != in_p[j])
        continue; /* the receiver's surface clips it (formfactor.c) */
      counts[2 * rs + ss]++;
    }
}

/* A cone of normals of half-angle spread, for loose_cos: cos(spread),
   sin(spread), and the cosine at or below which the loosened cosine is
   0 (cos(pi/2 + spread), none when spread is pi/2 or more). */
typedef struct loosen {
  double c, s, zero;
} loosen;

static loosen loosen_by(double spread) {
  loosen l = {cos(spread), sin(spread), -2.0};
  if (spread < M_PI / 2)
    l.zero = -l.s;
  return l;
}

/* fmax and fmin, bit for bit (the sign libm gives a max of two zeros
   included), without the call where the answer is plain: the oracle
   takes 18 of each a call, and -O2 calls libm for them. */
static inline double max_of(double a, double b) {
  if (a > b || (a == b && a != 0.0))
    return a;
  return b > a ? b : fmax(a, b);
}

static inline double min_of(double a, double b) {
  if (a < b || (a == b && a != 0.0))
    return a;
  return b < a ? b : fmin(a, b);
}

/* The cosine between the sided normal n (loosened by the cone lo) and
   the direction from c to t, clamped to [0, 1]: cos(max(0, acos(x) -
   spread)) for the plain cosine x, without the acos and cos (x cos
   spread + sqrt(1 - x^2) sin spread between the clamps). */
static double loose_cos(zr_vec3 n, const loosen *lo, zr_vec3 c, zr_vec3 t) {
  zr_vec3 d = zr_v3_sub(t, c);
  double len = zr_v3_len(d);
  if (!(len > 0.0))
    return 0.0;
  double x = max_of(-1.0, min_of(1.0, zr_v3_dot(n, d) / len));
  if (x >= lo->c)
    return 1.0;
  if (x <= lo->zero)
    return 0.0;
  /* A flat cell (no spread): x * 1 + sqrt(1 - x^2) * 0 is x, in (0, 1)
     here, which both clamps keep. */
  if (lo->s == 0.0 && lo->c == 1.0)
    return x;
  return min_of(1.0, max_of(0.0, x * lo->c + sqrt(1.0 - x * x) * lo->s));
}

/*
 * The oracle factor from node a's side sx to node b's side sy: Hanrahan's
 * A cos cos / (pi r^2 + A) between the centres, where each cosine is the
 * largest towards the other cell's 3 x 3 sample points, so a large cell
 * whose centre lies behind the other (a floor under a box's face) is
 * not judged invisible.  Its parts (the two cosines and r^2) serve both
 * directions: from b to a the cosines swap ends and r^2 is the same
 * bits (a difference negated exactly), so larger_end finds the factor
 * back from the parts its caller found, not from 18 more samples.
 */
typedef struct oracle_parts {
  double r2, ca, cb; /* ca at a towards b's samples, cb at b */
} oracle_parts;

static void oracle_parts_of(const zr_radiosity *rad, const zr__rad_node *a,
                            int sx, const zr__rad_node *b, int sy,
                            oracle_parts *o) {
  zr_vec3 d = zr_v3_sub(b->centre, a->centre);
  o->r2 = zr_v3_dot(d, d);
  o->ca = o->cb = 0.0;
  if (!(o->r2 > 0.0))
    return;
  zr_vec3 na = zr_v3_scale(a->normal, sx ? -1.0 : 1.0);
  zr_vec3 nb = zr_v3_scale(b->normal, sy ? -1.0 : 1.0);
  cell_samples sa, sb;
  node_samples(rad, a, &sa);
  node_samples(rad, b, &sb);
  double ca = 0.0, cb = 0.0;
  loosen la = loosen_by(a->spread), lb = loosen_by(b->spread);
  for (int i = 0; i < 9; i++) {
    ca = max_of(ca, loose_cos(na, &la, a->centre, sb.p[i]));
    cb = max_of(cb, loose_cos(nb, &lb, b->centre, sa.p[i]));
  }
  o->ca = ca;
  o->cb = cb;
}

/* The factor from a to b (the parts' order), and from b back to a. */
static double oracle_ab(const oracle_parts *o, const zr__rad_node *b) {
  if (!(o->r2 > 0.0))
    return b->area > 0.0 ? 1.0 : 0.0;
  return b->area * o->ca * o->cb / (M_PI * o->r2 + b->area);
}

static double oracle_ba(const oracle_parts *o, const zr__rad_node *a) {
  if (!(o->r2 > 0.0))
    return a->area > 0.0 ? 1.0 : 0.0;
  return a->area * o->cb * o->ca / (M_PI * o->r2 + a->area);
}

static bool can_split(const zr_radiosity *rad, const zr__rad_node *node) {
  if (rad->params.uniform > 0)
    return node->child >= 0;
  return node->child >= 0 ||
         (node->area > rad->area_eps_abs && node->depth < ZR__RAD_DEPTH);
}

/* A link as refinement judges it: its two ends, sides, whether it joins
   a cell to itself and whether its computed visibility is partial. */
typedef struct link_view {
  const zr__rad_node *p, *q; /* receiver, source */
  int rside, sside;
  bool self, partial;
} link_view;

/*
 * How much the exact unoccluded factor to the source varies over the
 * receiver: the spread (largest minus smallest) of the point-to-polygon
 * factor near the receiver's corners, edge midpoints and centre.  A link
 * hands every point of its receiver the receiver's mean factor, so
 * B_q A_p times this spread bounds the light it misplaces inside the
 * receiver.
 */
static double factor_spread(const zr_radiosity *rad, const link_view *l) {
  const zr__rad_node *p = l->p, *q = l->q;
  double rc[4], sc[4];
  zr__rad_node_cell(p, rc);
  zr__rad_node_cell(q, sc);
  if (zr__rad_cluster(rad, p, NULL, NULL))
    return 1.0; /* a cluster's factor varies as its faces: split it */
  bool to_cluster = zr__rad_cluster(rad, q, NULL, NULL);
  zr_vec3 poly[4 * ZR__FF_MAX_SEGS];
  size_t nv = zr__surface_patch_polygon(&rad->surfs[q->surf].geom, sc[0],
                                        sc[1], sc[2], sc[3], 16, poly,
                                        4 * ZR__FF_MAX_SEGS);
  /* Just inside the corners: on a boundary shared with the source the
     contour formula sees the source edge-on, which is not the limit.
     A curved source is its chord polygon here, so its samples keep
     further in, away from the chords' error. */
  bool curved = !rad->surfs[p->surf].geom.planar ||
                !rad->surfs[q->surf].geom.planar;
  const double f[3] = {curved ? 0.1 : 0.01, 0.5, curved ? 0.9 : 0.99};
  double lo = INFINITY, hi = 0.0;
  for (int j = 0; j < 3; j++)
    for (int i = 0; i < 3; i++) {
      zr__surface_point pt;
      zr__surface_eval(&rad->surfs[p->surf].geom,
                       rc[0] + f[i] * (rc[1] - rc[0]),
                       rc[2] + f[j] * (rc[3] - rc[2]), &pt);
      zr_vec3 n = l->rside ? zr_v3_neg(pt.n) : pt.n;
      double f = to_cluster ? zr__rad_cluster_point_factor(rad, q, l->sside,
                                                           pt.p, n)
                            : zr__ff_point_polygon(pt.p, n, poly, nv);
      lo = fmin(lo, f);
      hi = fmax(hi, f);
    }
  return hi - lo;
}

/* The spread of the largest channel of B over node's children (0 for a
   leaf): how unevenly a source shines.  A cell split during the current
   pass has children that all start from its own value, so this is 0 for
   it as for a leaf: the answer does not depend on the order in which a
   pass splits cells. */
static double radiosity_spread(const zr_radiosity *rad,
                               const zr__rad_node *node, int side) {
  if (node->child < 0)
    return 0.0;
  double lo = INFINITY, hi = 0.0;
  for (int k = 0; k < 4; k++) {
    double b = zr__rad_max3(rad->nodes[node->child + k].b[side]);
    lo = fmin(lo, b);
    hi = fmax(hi, b);
  }
  return hi - lo;
}

/* Hanrahan's choice: split the node that looks larger from the other. */
static int larger_end(const link_view *l, bool sp, bool sq,
                      const oracle_parts *o) {
  double f_pq = oracle_ab(o, l->q);
  double f_qp = oracle_ba(o, l->p);
  /* Equal up to rounding (equal cells, common in symmetric scenes) is a
     tie, settled for the receiver: rounding must not pick, or a scaled
     scene would refine differently. */
  if (f_qp >= f_pq * (1.0 - 1e-9))
    return sp ? 1 : 2;
  return sq ? 2 : 1;
}

/*
 * The error criterion (criterion 1): a link is split when the light it
 * may misplace exceeds the threshold, from three causes: the factor
 * varying over the receiver (split the receiver), partial visibility
 * (known once the link was computed; split the larger end), and an
 * uneven source (split the source).
 */
static int error_choice(const zr_radiosity *rad, const link_view *l, bool sp,
                        bool sq, double thr) {
  const zr__rad_node *p = l->p, *q = l->q;
  double bq = zr__rad_max3(q->b[l->sside]);
  if (!(bq * p->area > thr))
    return 0; /* no factor can make this link matter */
  if (sp && bq * p->area * factor_spread(rad, l) > thr)
    return 1;
  oracle_parts o;
  oracle_parts_of(rad, p, l->rside, q, l->sside, &o);
  double f_pq = oracle_ab(&o, q);
  if (l->partial && bq * p->area * f_pq > thr)
    return larger_end(l, sp, sq, &o);
  /* An uneven source errs by the same sign at every small receiver near
     it, so this test is per unit area of the receiver: the irradiance
     error against the threshold spread over the scene's area. */
  double thr_area = thr / rad->total_area;
  if (sq && radiosity_spread(rad, q, l->sside) * f_pq > thr_area)
    return 2;
  return 0;
}

/*
 * A self link is split (3) while the light it keeps inside the cell may
 * exceed the threshold: B A F_self, with F_self estimated as that of a
 * spherical cap whose normals spread as much, (1 - cos spread) / 2.
 */
static int self_choice(const zr_radiosity *rad, const zr__rad_node *p,
                       int sside) {
  if (!can_split(rad, p))
    return 0;
  if (rad->params.uniform > 0 || zr__rad_cluster(rad, p, NULL, NULL))
    return 3; /* a cluster receives as its faces (refine_choice) */
  double f_self = 0.5 * (1.0 - cos(fmin(p->spread, M_PI)));
  double e = zr__rad_max3(p->b[sside]) * p->area * f_self;
  return e > rad->params.bf_eps * rad->power_ref ? 3 : 0;
}

/* Whether link l should be split, and which end: 1 receiver, 2 source,
   3 both (a self link). */
static int refine_choice(const zr_radiosity *rad, const link_view *l) {
  /* A cell that a CSG trim crosses holds removed area that would send
     and receive as if it were there: links go below it, to the cells
     zr__rad_trim_split made down to A_eps (trim.c). */
  /* A cluster of a mesh's faces receives as its faces: a cluster
     handing its mean factor to every face would light faces that turn
     away as much as those that face the source (cluster.c). */
  if (zr__rad_cluster(rad, l->p, NULL, NULL) && can_split(rad, l->p))
    return l->self ? 3 : 1;
  bool tp = l->p->kept < 1.0 && can_split(rad, l->p);
  bool tq = l->q->kept < 1.0 && can_split(rad, l->q);
  if (l->self)
    return tp ? 3 : self_choice(rad, l->p, l->sside);
  if (tp || tq)
    return tp && (!tq || l->p->area >= l->q->area) ? 1 : 2;
  bool sp = can_split(rad, l->p), sq = can_split(rad, l->q);
  if (!sp && !sq)
    return 0;
  if (rad->params.uniform > 0)
    return sp ? 1 : 2;
  double thr = rad->params.bf_eps * rad->power_ref;
  if (rad->params.criterion == 1)
    return error_choice(rad, l, sp, sq, thr);
  /* Hanrahan's BF criterion: B_q F_pq A_p against the threshold, ten
     times tighter for a partially visible link (a shadow boundary runs
     through it), which is what keeps light from leaking under objects
     standing on a floor. */
  oracle_parts o;
  oracle_parts_of(rad, l->p, l->rside, l->q, l->sside, &o);
  double f_pq = oracle_ab(&o, l->q);
  if (l->partial)
    thr *= 0.1;
  if (!(zr__rad_max3(l->q->b[l->sside]) * f_pq * l->p->area > thr))
    return 0;
  return larger_end(l, sp, sq, &o);
}

/* ---- refinement as a plan, then its replay ----
 *
 * Every decision above reads only the geometry of cells, the radiosity
 * they start the pass with (a new cell takes its parent's) and the
 * link's own sides and visibility; none depends on what the pass split
 * before.  So the recursion of one link (or one pair of input surfaces)
 * is worked out by a thread on its own, on copies of the cells (a cell
 * not yet made is filled in as splitting would make it), into a plan:
 * the splits and links it makes, in the order it makes them.  The
 * plans are then replayed one after the other in link order by the
 * calling thread, which makes the cells and links: the nodes and links
 * come out in the same order, with the same values, for any number of
 * threads, as if one thread had refined depth first. */

/* A cell by its place in a surface's quadtree. */
typedef struct cell_key {
  int32_t surf, depth;
  uint32_t iu, iv;
} cell_key;

enum { OP_SPLIT, OP_LINK, OP_KILL_SELF };

/* One step of a plan: split cell a, link receiver a (side rside) to
   source b (side sside), or kill the self links of cell a. */
typedef struct plan_op {
  uint8_t kind, rside, sside, dead;
  cell_key a, b;
} plan_op;

typedef struct plan {
  plan_op *ops;
  size_t n, cap;
  bool nomem;
  /* ops points into another member's part of an exchange (team plans,
     plans_unpack), which the plan does not own: cap is 0. */
  bool borrowed;
  int choice; /* of the link a refinement plan starts from */
} plan;

/* A cell as a plan sees it: a copy of node index, or of the node a
   split would make (index -1). */
typedef struct vnode {
  zr__rad_node n;
  int32_t index;
} vnode;

static cell_key key_of(const vnode *v) {
  cell_key k = {v->n.surf, v->n.depth, v->n.iu, v->n.iv};
  return k;
}

static bool same_cell(const vnode *a, const vnode *b) {
  return a->n.surf == b->n.surf && a->n.depth == b->n.depth &&
         a->n.iu == b->n.iu && a->n.iv == b->n.iv;
}

static void vnode_of(const zr_radiosity *rad, int32_t n, vnode *out) {
  out->n = rad->nodes[n];
  out->index = n;
}

/* The four children of v, in zr__rad_subdivide's order, starting from
   v's radiosity as it gives them. */
static void vnode_children(const zr_radiosity *rad, const vnode *v,
                           vnode out[4]) {
  if (v->index >= 0 && v->n.child >= 0) {
    for (int k = 0; k < 4; k++)
      vnode_of(rad, v->n.child + k, &out[k]);
    return;
  }
  uint32_t half = (ZR__RAD_GRID >> v->n.depth) / 2;
  const uint32_t du[4] = {0, half, half, 0}, dv[4] = {0, 0, half, half};
  for (int k = 0; k < 4; k++) {
    zr__rad_node *c = &out[k].n;
    memset(c, 0, sizeof *c);
    c->child = -1;
    c->parent = v->index;
    c->surf = v->n.surf;
    c->depth = v->n.depth + 1;
    c->iu = v->n.iu + du[k];
    c->iv = v->n.iv + dv[k];
    zr__rad_node_geometry(rad, c);
    memcpy(c->b, v->n.b, sizeof c->b);
    out[k].index = -1;
  }
}

/* Appends a step; its index, or SIZE_MAX when out of memory. */
static size_t plan_push(plan *pl, int kind, const vnode *a, int rside,
                        const vnode *b, int sside) {
  if (pl->n == pl->cap) {
    size_t cap = pl->cap ? 2 * pl->cap : 16;
    plan_op *ops = realloc(pl->ops, cap * sizeof *ops);
    if (ops == NULL) {
      pl->nomem = true;
      return SIZE_MAX;
    }
    pl->ops = ops;
    pl->cap = cap;
  }
  plan_op *op = &pl->ops[pl->n];
  memset(op, 0, sizeof *op);
  op->kind = (uint8_t)kind;
  op->rside = (uint8_t)rside;
  op->sside = (uint8_t)sside;
  op->a = key_of(a);
  if (b != NULL)
    op->b = key_of(b);
  return pl->n++;
}

static void plan_links(const zr_radiosity *rad, plan *pl, const vnode *p,
                       const vnode *q, int rs_only, int ss_only);
static void plan_add_link(const zr_radiosity *rad, plan *pl, const vnode *p,
                          int rs, const vnode *q, int ss);

/* Links every child of p to q (or p to every child of q); rs_only
   (0, 1, or -1 for both) keeps the receiver side of the link split, so
   a receiver linked on both sides does not get its children linked
   twice; ss_only likewise keeps the source side of a cluster link
   (cluster.c), which may join one receiver side to both. */
static void plan_split_and_link(const zr_radiosity *rad, plan *pl,
                                const vnode *p, const vnode *q, bool split_p,
                                int rs_only, int ss_only) {
  const vnode *n = split_p ? p : q;
  vnode ch[4];
  plan_push(pl, OP_SPLIT, n, 0, NULL, 0);
  vnode_children(rad, n, ch);
  for (int k = 0; k < 4 && !pl->nomem; k++)
    plan_links(rad, pl, split_p ? &ch[k] : p, split_p ? q : &ch[k],
               rs_only, ss_only);
}

/* Links all pairs of the children of p (after a self link is split). */
static void plan_link_children(const zr_radiosity *rad, plan *pl,
                               const vnode *p) {
  vnode ch[4];
  plan_push(pl, OP_SPLIT, p, 0, NULL, 0);
  vnode_children(rad, p, ch);
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4 && !pl->nomem; j++)
      plan_links(rad, pl, &ch[i], &ch[j], -1, -1);
}

/* A curved cell that sees itself gets a link to itself on each pair of
   sides that face, unless the self transfer is large enough that its
   children should be linked instead. */
static void plan_self_links(const zr_radiosity *rad, plan *pl,
                            const vnode *p, const int counts[4],
                            int rs_only) {
  int sside = 0;
  for (int k = 0; k < 4; k++)
    if (counts[k] > 0 && sside < (k & 1))
      sside = k & 1;
  if (self_choice(rad, &p->n, sside) == 3) {
    plan_link_children(rad, pl, p);
    return;
  }
  for (int k = 0; k < 4 && !pl->nomem; k++)
    if (counts[k] > 0 && (rs_only < 0 || rs_only == k >> 1))
      plan_add_link(rad, pl, p, k >> 1, p, k & 1);
}

/* Links receiver p to source q on the sides that face each other (only
   receiver side rs_only unless it is -1). */
static void plan_links(const zr_radiosity *rad, plan *pl, const vnode *p,
                       const vnode *q, int rs_only, int ss_only) {
  /* A cell that CSG removes whole takes no part (trim.c). */
  if (!(p->n.kept > 0.0) || !(q->n.kept > 0.0))
    return;
  int counts[5];
  classify(rad, &p->n, &q->n, counts);
  /* A cluster of a mesh's faces facing many ways may show any side to
     any side (its factor picks the faces per side, cluster.c); the nine
     samples of classify could miss some. */
  bool mixed = zr__rad_mixed_cluster(rad, &p->n) ||
               zr__rad_mixed_cluster(rad, &q->n);
  if (mixed)
    counts[0] = counts[1] = counts[2] = counts[3] = 1;
  if (same_cell(p, q)) {
    if (counts[0] + counts[1] + counts[2] + counts[3] > 0)
      plan_self_links(rad, pl, p, counts, rs_only);
    return;
  }
  int front = counts[0] + counts[2], back = counts[1] + counts[3];
  if (front == 0 && back == 0)
    return;
  /* The source's own rim (the silhouette of a ball) crosses it as the
     receiver sees it: the contour formula needs a source cell seen
     one-to-one, so the source is split, not the receiver. */
  if (counts[4] > 0 && !rad->surfs[q->n.surf].geom.planar &&
      can_split(rad, &q->n)) {
    plan_split_and_link(rad, pl, p, q, false, rs_only, ss_only);
    return;
  }
  /* A source cluster or a planar source is sided per receiver point in
     a cluster link (cluster.c): no split is needed. */
  bool sided = zr__rad_cluster(rad, &q->n, NULL, NULL) ||
               (zr__rad_cluster(rad, &p->n, NULL, NULL) &&
                (rad->surfs[q->n.surf].geom.planar ||
                 rad->surfs[q->n.surf].geom.kind == ZR__SURFACE_MESH));
  if (front > 0 && back > 0 && !sided) {
    /* The receiver straddles the source's plane: split it if it can. */
    if (can_split(rad, &p->n)) {
      plan_split_and_link(rad, pl, p, q, true, rs_only, ss_only);
      return;
    }
    if (!rad->surfs[q->n.surf].geom.planar &&
        rad->surfs[q->n.surf].geom.kind != ZR__SURFACE_MESH &&
        can_split(rad, &q->n)) {
      plan_split_and_link(rad, pl, p, q, false, rs_only, ss_only);
      return;
    }
  }
  int ss = back > front;
  bool both = sided && front > 0 && back > 0;
  for (int rs = 0; rs < 2 && !pl->nomem; rs++)
    for (int s2 = 0; s2 < 2 && !pl->nomem; s2++)
      if ((s2 == ss || both) && (ss_only < 0 || s2 == ss_only) &&
          counts[2 * rs + s2] > 0 && (rs_only < 0 || rs == rs_only))
        plan_add_link(rad, pl, p, rs, q, s2);
}

/* Refines the link p <- q at once (depth first) if it asks to be;
   li is its step in the plan (SIZE_MAX for a link the plan starts
   from).  Returns the choice. */
static int plan_refine(const zr_radiosity *rad, plan *pl, size_t li,
                       const vnode *p, int rs, const vnode *q, int ss,
                       bool partial) {
  link_view l = {&p->n, &q->n, rs, ss, same_cell(p, q), partial};
  int choice = refine_choice(rad, &l);
  if (choice == 0)
    return 0;
  if (li != SIZE_MAX)
    pl->ops[li].dead = 1;
  if (choice == 3) {
    /* Every side pair of the cell is relinked through its children, so
       its other self links go too. */
    plan_push(pl, OP_KILL_SELF, p, 0, NULL, 0);
    plan_link_children(rad, pl, p);
  } else {
    /* A link with a cluster end may have a twin on the source's other
       side (plan_links): the children keep this one's. */
    bool clustered = zr__rad_cluster(rad, &p->n, NULL, NULL) ||
                     zr__rad_cluster(rad, &q->n, NULL, NULL);
    plan_split_and_link(rad, pl, p, q, choice == 1, rs, clustered ? ss : -1);
  }
  return choice;
}

/* Appends the link and refines it at once (depth first). */
static void plan_add_link(const zr_radiosity *rad, plan *pl, const vnode *p,
                          int rs, const vnode *q, int ss) {
  size_t li = plan_push(pl, OP_LINK, p, rs, q, ss);
  if (li != SIZE_MAX)
    plan_refine(rad, pl, li, p, rs, q, ss, false);
}

/* The node of a cell the replay has made (its ancestors are split). */
static int32_t node_of_key(const zr_radiosity *rad, const cell_key *k) {
  int32_t n = rad->surfs[k->surf].root;
  while (rad->nodes[n].depth < k->depth) {
    const zr__rad_node *node = &rad->nodes[n];
    uint32_t half = (ZR__RAD_GRID >> node->depth) / 2;
    bool hu = k->iu - node->iu >= half, hv = k->iv - node->iv >= half;
    n = node->child + (hv ? (hu ? 2 : 3) : (hu ? 1 : 0));
  }
  return n;
}

static zr_status append_link(zr_radiosity *rad, int32_t p, int rs,
                             int32_t q, int ss, bool dead) {
  if (rad->n_links == rad->cap_links) {
    size_t cap = rad->cap_links ? 2 * rad->cap_links : 256;
    if (!zr__rad_charge(rad, (cap - rad->cap_links) * sizeof *rad->links))
      return ZR_ENOMEM;
    zr__rad_link *a = zr__huge_grow(rad->links, rad->cap_links * sizeof *a,
                                    cap * sizeof *a);
    if (a == NULL)
      return ZR_ENOMEM;
    rad->links = a;
    rad->cap_links = cap;
  }
  zr__rad_link *l = &rad->links[rad->n_links++];
  memset(l, 0, sizeof *l);
  l->recv = p;
  l->src = q;
  l->rside = (uint8_t)rs;
  l->sside = (uint8_t)ss;
  l->dead = dead;
  return ZR_OK;
}

static zr_status replay(zr_radiosity *rad, const plan *pl) {
  if (pl->nomem)
    return ZR_ENOMEM;
  for (size_t i = 0; i < pl->n; i++) {
    const plan_op *op = &pl->ops[i];
    int32_t a = node_of_key(rad, &op->a);
    if (op->kind == OP_SPLIT) {
      if (!zr__rad_subdivide(rad, a))
        return ZR_ENOMEM;
    } else if (op->kind == OP_LINK) {
      zr_status st = append_link(rad, a, op->rside,
                                 node_of_key(rad, &op->b), op->sside,
                                 op->dead);
      if (st != ZR_OK)
        return st;
    } else {
      for (size_t k = 0; k < rad->n_links; k++)
        if (rad->links[k].recv == a && rad->links[k].src == a)
          rad->links[k].dead = 1;
    }
  }
  return ZR_OK;
}

/* Plans are made this many at a time, then replayed: enough to keep
   the threads busy, few enough that the plans stay small.  A team
   makes this many per member at a time (fewer exchanges); the batch
   does not change the result, as no plan reads what another made. */
#define PLAN_BATCH 2048
/* A team deals tasks out in chunks of this many. */
#define PLAN_CHUNK 8

typedef struct planner {
  const zr_radiosity *rad;
  plan *plans;
  size_t first; /* the task of plans[0] */
  zr__rad_work_fn make; /* plans tasks [begin, end) of the batch */
  const uint32_t *chunks; /* a team member's chunks of the batch */
  size_t count;           /* tasks in the batch */
  /* A team's deal: chunks of `chunk` tasks, chunk c to member
     (c + c / stagger) % n (stagger 0: c % n). */
  size_t chunk, stagger;
  /* link_all's pairs from a list (2 surfaces each) instead of all. */
  const uint32_t *pairs;
  /* A team's exchange of the batch's plans, which the plans made by
     other members borrow their steps from until the batch is replayed
     (planner_done); it arrives in room, packed from pack (the solve's
     kept buffers, radiosity.h). */
  zr__team_parts parts;
  zr__team_room *room;
  zr__pack *pack;
} planner;

/* The member that plans chunk c of a batch. */
static int chunk_owner(const planner *w, size_t c, int n) {
  size_t k = c;
  if (w->stagger) {
    size_t whole = w->first / w->chunk + c; /* over every batch */
    k = whole + whole / w->stagger;
  }
  return (int)(k % (size_t)n);
}

static int threads_of(const zr_radiosity *rad) {
  return rad->params.threads > 1 ? rad->params.threads : 1;
}

/* The tasks in a batch: alone PLAN_BATCH; a team 64 PLAN_BATCH, so
   that a pass over the links of a scene like the Cornell box (1e5) is
   one exchange: each exchange makes the members wait for the slowest. */
static size_t batch_of(const zr_radiosity *rad) {
  return zr__team_size(rad->params.team) == 1 ? PLAN_BATCH
                                               : 64 * PLAN_BATCH;
}

/* link_all's task t joins surface t / n (receiver) to t % n. */
static void plan_pairs(void *user, size_t begin, size_t end, int worker) {
  (void)worker;
  planner *w = user;
  const zr_radiosity *rad = w->rad;
  for (size_t t = begin; t < end; t++) {
    plan *pl = &w->plans[t];
    pl->n = 0;
    size_t i = (w->first + t) / rad->n_surfs, j = (w->first + t) % rad->n_surfs;
    if (w->pairs != NULL) {
      i = w->pairs[2 * (w->first + t)];
      j = w->pairs[2 * (w->first + t) + 1];
    }
    if (i == j && rad->surfs[i].geom.planar)
      continue; /* a planar surface cannot see itself */
    vnode p, q;
    vnode_of(rad, rad->surfs[i].root, &p);
    vnode_of(rad, rad->surfs[j].root, &q);
    plan_links(rad, pl, &p, &q, -1, -1);
  }
}

/* Room for n plans, all empty; NULL when out of memory.  A team's
   batch holds up to 64 PLAN_BATCH plans (5 MiB), in huge pages from
   zr__huge_alloc: a 2-rank solve of cornell.pov took 1,100 page faults
   of 4 KiB (about 14 us each here) in calloc's fresh plans. */
static plan *new_plans(size_t n) {
  plan *plans = zr__huge_alloc((n ? n : 1) * sizeof *plans);
  if (plans != NULL)
    memset(plans, 0, (n ? n : 1) * sizeof *plans);
  return plans;
}

/* Lets go of the steps plans borrowed from the batch's exchange. */
static void planner_done(planner *w, size_t n) {
  for (size_t i = 0; i < n; i++)
    if (w->plans[i].borrowed) {
      w->plans[i].ops = NULL;
      w->plans[i].n = w->plans[i].cap = 0;
      w->plans[i].borrowed = false;
    }
  zr__team_parts_free(&w->parts);
}

static void free_plans(plan *plans, size_t n) {
  for (size_t i = 0; plans != NULL && i < n; i++)
    if (!plans[i].borrowed)
      free(plans[i].ops);
  free(plans);
}

/* ---- plans across a team ----
 *
 * Member r of n makes the plans of the chunks r, r + n, ... of a batch
 * (PLAN_CHUNK tasks each; link_all's pairs one at a time, staggered,
 * chunk_owner), sends those that do something (each one's task, its
 * choice, its length and its steps, which are plain values with their
 * padding zeroed by plan_push; a plan not sent is empty, as most are
 * once refinement settles: cornell.pov's later passes sent 12 bytes for
 * each of 1e5 links, 0.6 MB a rank, nearly all for empty plans), and
 * every member reads every member's plans into the same slots; then
 * each replays the whole batch in order as alone.  A plan
 * depends on the cells and links as the pass found them and on nothing
 * else, so it is the same bytes whoever makes it, and so are the cells
 * and links every member makes from it. */
static void plan_chunks(void *user, size_t begin, size_t end, int worker) {
  planner *w = user;
  for (size_t c = begin; c < end; c++) {
    size_t t0 = (size_t)w->chunks[c] * w->chunk;
    size_t t1 = t0 + w->chunk < w->count ? t0 + w->chunk : w->count;
    w->make(user, t0, t1, worker);
  }
}

/* What precedes a plan's steps in an exchange: 12 bytes. */
typedef struct plan_head {
  uint32_t task; /* in the batch */
  int32_t choice;
  uint32_t n;
} plan_head;

/* Reads a plan another member made: its steps stay in the exchange's
   part (borrowed, not copied: a 2-rank solve of cornell.pov copied
   megabytes into a fresh buffer a plan).  A part starts at a multiple
   of 4 bytes from the exchange's malloc'd room and every plan in it
   takes 12 + 36 n bytes, so the steps (4-byte fields) lie aligned. */
static zr_status plans_unpack(plan *pl, const plan_head *h, const char **at,
                              const char *end) {
  if ((size_t)(end - *at) / sizeof(plan_op) < h->n)
    return ZR_EMPI;
  if (h->n > 0 && ((uintptr_t)*at % _Alignof(plan_op)) != 0)
    return ZR_EMPI; /* cannot happen: see above */
  if (!pl->borrowed)
    free(pl->ops);
  pl->choice = h->choice;
  pl->ops = h->n > 0 ? (plan_op *)(void *)*at : NULL;
  pl->n = h->n;
  pl->cap = 0;
  pl->borrowed = true;
  *at += (size_t)h->n * sizeof *pl->ops;
  return ZR_OK;
}

/* Makes the plans of tasks [0, w->count) of the batch on every member
   of the team, each member making its chunks. */
static zr_status make_plans_team(planner *w) {
  const zr_team *team = w->rad->params.team;
  size_t n_chunks = (w->count + w->chunk - 1) / w->chunk;
  uint32_t *chunks = malloc((n_chunks + 1) * sizeof *chunks);
  zr__pack *pack = w->pack;
  zr__pack_reset(pack);
  zr_status st = chunks ? ZR_OK : ZR_ENOMEM;
  if (st == ZR_OK) {
    size_t n_mine = 0;
    for (size_t c = 0; c < n_chunks; c++)
      if (chunk_owner(w, c, team->size) == team->rank)
        chunks[n_mine++] = (uint32_t)c;
    w->chunks = chunks;
    zr__rad_parallel(threads_of(w->rad), n_mine, 1, plan_chunks, w);
    for (size_t k = 0; k < n_mine && !pack->nomem; k++) {
      size_t t0 = (size_t)chunks[k] * w->chunk;
      for (size_t t = t0; t < t0 + w->chunk && t < w->count; t++) {
        const plan *pl = &w->plans[t];
        if (pl->nomem) {
          st = ZR_ENOMEM;
          break;
        }
        if (pl->n == 0 && pl->choice == 0)
          continue; /* empty: the others know it by its absence */
        if (pl->n > UINT32_MAX) {
          st = ZR_ENOMEM; /* 150 GB of steps: never */
          break;
        }
        plan_head h = {(uint32_t)t, pl->choice, (uint32_t)pl->n};
        zr__pack_put(pack, &h, sizeof h);
        if (pl->n > 0)
          zr__pack_put(pack, pl->ops, pl->n * sizeof *pl->ops);
      }
    }
    if (pack->nomem)
      st = ZR_ENOMEM;
  }
  zr__team_parts parts;
  st = zr__team_exchange_in(team, st, pack->bytes, pack->n, w->room,
                            &parts);
  for (int r = 0; st == ZR_OK && r < team->size; r++) {
    if (r == team->rank) /* its plans are in place */
      continue;
    const char *at = parts.bytes + parts.offset[r];
    const char *end = parts.bytes + parts.offset[r + 1];
    /* Member r's plans are empty but those it sent, in task order. */
    for (size_t c = 0; c < n_chunks; c++) {
      if (chunk_owner(w, c, team->size) != r)
        continue;
      for (size_t t = c * w->chunk; t < (c + 1) * w->chunk && t < w->count;
           t++) {
        w->plans[t].n = 0;
        w->plans[t].choice = 0;
      }
    }
    size_t next = 0; /* the lowest task the next plan may have */
    while (st == ZR_OK && at != end) {
      plan_head h;
      if (!zr__unpack(&at, end, &h, sizeof h) || h.task < next ||
          h.task >= w->count ||
          chunk_owner(w, h.task / w->chunk, team->size) != r)
        st = ZR_EMPI; /* a member sent what the others did not expect */
      else {
        st = plans_unpack(&w->plans[h.task], &h, &at, end);
        next = (size_t)h.task + 1;
      }
    }
  }
  w->parts = parts; /* the plans borrow from it (planner_done) */
  free(chunks);
  /* A member that failed to unpack (out of memory) replays nothing;
     the others learn it after their replay (replayed()). */
  return st;
}

/* After a batch's replay, which fails only for memory: a team's
   members all go on to the next batch, or all stop. */
static zr_status replayed(const zr_radiosity *rad, zr_status st) {
  const zr_team *team = rad->params.team;
  return zr__team_size(team) > 1 ? zr__team_agree(team, st) : st;
}

/* The plans of the batch's tasks [0, count): this process's threads
   alone, or shared among the team. */
static zr_status make_plans(planner *w) {
  if (zr__team_size(w->rad->params.team) > 1)
    return make_plans_team(w);
  zr__rad_parallel(threads_of(w->rad), w->count, PLAN_CHUNK, w->make, w);
  return ZR_OK;
}

/* Plans and replays n_pairs pair tasks (all pairs, or a list). */
static zr_status link_tasks(zr_radiosity *rad, size_t n_pairs,
                            const uint32_t *pairs) {
  size_t batch = batch_of(rad);
  size_t room = n_pairs < batch ? n_pairs : batch;
  plan *plans = new_plans(room);
  if (plans == NULL)
    return ZR_ENOMEM;
  /* A team deals the pairs one at a time, staggered by a receiver's
     row of pairs (member (i + j) % n plans pair i, j): a pair's cost
     follows its surfaces' sizes, and chunks of 8 pairs in a row gave
     one of 2 ranks 3 times the other's planning (cornell.pov). */
  planner w = {.rad = rad,
               .plans = plans,
               .make = plan_pairs,
               .chunk = 1,
               .stagger = rad->n_surfs,
               .pairs = pairs,
               .room = &rad->team_room,
               .pack = &rad->team_pack};
  zr_status st = ZR_OK;
  for (size_t at = 0; st == ZR_OK && at < n_pairs; at += batch) {
    w.count = n_pairs - at < batch ? n_pairs - at : batch;
    w.first = at;
    st = make_plans(&w);
    for (size_t t = 0; st == ZR_OK && t < w.count; t++)
      st = replay(rad, &plans[t]);
    planner_done(&w, w.count);
    /* Ctrl-C, SIGTERM or a progress callback stop the linking between
       batches (a team agrees on it below). */
    if (st == ZR_OK)
      st = zr__rad_progress(rad);
    st = replayed(rad, st);
  }
  free_plans(plans, room);
  return st;
}

zr_status zr__rad_link_pairs(zr_radiosity *rad, const zr__rad_pairs *pairs) {
  if (pairs->nomem)
    return ZR_ENOMEM;
  return link_tasks(rad, pairs->n, pairs->ij);
}

zr_status zr__rad_link_all(zr_radiosity *rad) {
  if (!rad->clustered)
    return link_tasks(rad, rad->n_surfs * rad->n_surfs, NULL);
  /* Volume clusters (volume.c): the pairs of surfaces close enough to
     matter, cluster links for the rest. */
  zr__rad_pairs pairs = {0};
  zr_status st = zr__rad_vol_link(rad, &pairs);
  if (st == ZR_OK)
    st = zr__rad_link_pairs(rad, &pairs);
  free(pairs.ij);
  return st;
}

static void plan_refinements(void *user, size_t begin, size_t end,
                             int worker) {
  (void)worker;
  planner *w = user;
  const zr_radiosity *rad = w->rad;
  for (size_t t = begin; t < end; t++) {
    plan *pl = &w->plans[t];
    pl->n = 0;
    pl->choice = 0;
    const zr__rad_link *l = &rad->links[w->first + t];
    if (l->dead)
      continue;
    vnode p, q;
    vnode_of(rad, l->recv, &p);
    vnode_of(rad, l->src, &q);
    bool partial = l->final && l->vis > 0.0 && l->vis < 1.0;
    pl->choice =
        plan_refine(rad, pl, SIZE_MAX, &p, l->rside, &q, l->sside, partial);
  }
}

zr_status zr__rad_refine_links(zr_radiosity *rad, size_t *changed) {
  size_t n = rad->n_links;
  *changed = 0;
  size_t batch = batch_of(rad);
  size_t room = n < batch ? n : batch;
  plan *plans = new_plans(room);
  if (plans == NULL)
    return ZR_ENOMEM;
  planner w = {.rad = rad,
               .plans = plans,
               .make = plan_refinements,
               .chunk = PLAN_CHUNK,
               .room = &rad->team_room,
               .pack = &rad->team_pack};
  zr_status st = ZR_OK;
  for (size_t at = 0; st == ZR_OK && at < n; at += batch) {
    w.count = n - at < batch ? n - at : batch;
    w.first = at;
    st = make_plans(&w);
    for (size_t t = 0; st == ZR_OK && t < w.count; t++) {
      /* A self link killed by an earlier plan of this pass (its cell's
         other self link split) is left alone, as one thread would. */
      if (rad->links[at + t].dead || plans[t].choice == 0)
        continue;
      rad->links[at + t].dead = 1;
      (*changed)++;
      st = replay(rad, &plans[t]);
    }
    planner_done(&w, w.count);
    if (st == ZR_OK)
      st = zr__rad_progress(rad); /* a stop asked for, as in link_tasks */
    st = replayed(rad, st);
  }
  free_plans(plans, room);
  if (st == ZR_OK && rad->clustered) {
    zr__rad_pairs pairs = {0};
    size_t split = 0;
    st = zr__rad_vol_refine(rad, &pairs, &split);
    if (st == ZR_OK)
      st = zr__rad_link_pairs(rad, &pairs);
    free(pairs.ij);
    *changed += split;
  }
  return st;
}

void zr__rad_compact_links(zr_radiosity *rad) {
  size_t k = 0;
  for (size_t i = 0; i < rad->n_links; i++) {
    const zr__rad_link *l = &rad->links[i];
    /* A link that carries nothing (every ray blocked, or a factor of
       exactly 0) is dropped, as Hanrahan et al. do with occluded pairs:
       it would only cost time in every sweep. */
    if (!l->dead && !(l->final && l->ff == 0.0))
      rad->links[k++] = *l;
  }
  rad->n_links = k;
}

zr_status zr__rad_uniform(zr_radiosity *rad, int n_levels) {
  for (size_t n = 0; n < rad->n_nodes; n++) {
    /* On a mesh the levels count from its faces' (surface.c). */
    const zr__surface *g = &rad->surfs[rad->nodes[n].surf].geom;
    int levels = n_levels + (g->kind == ZR__SURFACE_MESH ? g->slot_depth : 0);
    if (rad->nodes[n].depth < levels && rad->nodes[n].child < 0 &&
        (g->kind != ZR__SURFACE_MESH || rad->nodes[n].kept > 0.0) &&
        !zr__rad_subdivide(rad, (int32_t)n))
      return ZR_ENOMEM;
  }
  return ZR_OK;
}

/* ---- transfer factors ---- */

typedef struct self_sum {
  const zr__surface *src;
  double cell[4];
  double side, sside; /* the receiver's side and the source's, +-1 */
  const zr__gauss_rule *rule;
  double flux, area;
} self_sum;

/* The kernel cos_p cos_q / (pi r^2) from a point p (normal n, turned
   to the link's side) over the source points that turn that same side
   to p.  Inside a sphere that is every point; on a torus, which sees
   itself round its bend, a point showing p its other side is hidden by
   the surface, and counting it (as a two-sided source would) gave a
   self factor too large: a cell handed back more light than it had. */
typedef struct sided_kernel {
  zr_vec3 p, n;
  double side;
  double sum;
} sided_kernel;

static void add_sided_kernel(const zr__surface_point *q, double weight,
                             void *user) {
  sided_kernel *k = user;
  zr_vec3 d = zr_v3_sub(q->p, k->p);
  double r2 = zr_v3_dot(d, d);
  double cos_p = zr_v3_dot(k->n, d);
  double cos_q = -k->side * zr_v3_dot(q->n, d);
  /* A Gauss point on p itself is the kernel's pole; behind, nothing. */
  if (!(r2 > 0.0) || cos_p <= 0.0 || cos_q <= 0.0)
    return;
  k->sum += weight * cos_p * cos_q / (M_PI * r2 * r2);
}

static void add_self(const zr__surface_point *pt, double weight,
                     void *user) {
  self_sum *s = user;
  sided_kernel k = {pt->p, zr_v3_scale(pt->n, s->side), s->sside, 0.0};
  zr__surface_quadrature(s->src, s->cell[0], s->cell[1], s->cell[2],
                         s->cell[3], 1, s->rule, add_sided_kernel, &k);
  s->flux += weight * k.sum;
  s->area += weight;
}

/* The mean factor over the part of a trimmed receiver cell that its CSG
   keeps (trim.c): removed points see what the solid's surface does not
   (the inside of a hole), so they take no part in the mean. */
typedef struct trimmed_sum {
  const zr__rad_surface *recv;
  const zr_vec3 *poly;
  size_t nv;
  double side;
  double flux, area;
} trimmed_sum;

static void add_trimmed(const zr__surface_point *pt, double weight,
                        void *user) {
  trimmed_sum *s = user;
  if (!zr__rad_trim_keeps(s->recv, pt->p))
    return;
  zr_vec3 n = zr_v3_scale(pt->n, s->side);
  s->flux += weight * zr__ff_point_polygon(pt->p, n, s->poly, s->nv);
  s->area += weight;
}

static double trimmed_factor(const zr_radiosity *rad, const zr__rad_node *p,
                             const double rc[4], double side,
                             const zr__rad_node *q, const double sc[4]) {
  zr_vec3 poly[4 * ZR__FF_MAX_SEGS];
  size_t nv = zr__surface_patch_polygon(&rad->surfs[q->surf].geom, sc[0],
                                        sc[1], sc[2], sc[3], 16, poly,
                                        4 * ZR__FF_MAX_SEGS);
  trimmed_sum s = {&rad->surfs[p->surf], poly, nv, side, 0.0, 0.0};
  zr__surface_quadrature(&rad->surfs[p->surf].geom, rc[0], rc[1], rc[2],
                         rc[3], 3, &rad->rule_recv, add_trimmed, &s);
  return s.area > 0.0 ? s.flux / s.area : -1.0;
}

static double link_factor(const zr_radiosity *rad, const zr__rad_link *l) {
  const zr__rad_node *p = &rad->nodes[l->recv], *q = &rad->nodes[l->src];
  const zr__surface *gp = &rad->surfs[p->surf].geom;
  const zr__surface *gq = &rad->surfs[q->surf].geom;
  double rc[4], sc[4], side = l->rside ? -1.0 : 1.0;
  zr__rad_node_cell(p, rc);
  zr__rad_node_cell(q, sc);
  if (zr__rad_cluster(rad, p, NULL, NULL) ||
      zr__rad_cluster(rad, q, NULL, NULL))
    return zr__rad_cluster_link_factor(rad, p, l->rside, q, l->sside);
  if (l->recv == l->src) {
    self_sum s = {gq,  {sc[0], sc[1], sc[2], sc[3]}, side,
                  l->sside ? -1.0 : 1.0, &rad->rule_src, 0.0, 0.0};
    zr__surface_quadrature(gp, rc[0], rc[1], rc[2], rc[3], 2,
                           &rad->rule_recv, add_self, &s);
    return s.area > 0.0 ? q->kept * fmin(1.0, s.flux / s.area) : 0.0;
  }
  zr_vec3 d = zr_v3_sub(q->centre, p->centre);
  bool near = zr_v3_dot(d, d) < 4.0 * (p->area + q->area);
  if (p->kept < 1.0) {
    double f = trimmed_factor(rad, p, rc, side, q, sc);
    if (f >= 0.0)
      return q->kept * f;
  }
  /* Only the source's part that CSG keeps sends light (trim.c).  A
     curved source sends from the link's side only: where a receiver
     point sees its other side (through a ball, or round a torus's
     bend) that side's own link, if any, carries the light. */
  if (!gq->planar && gq->kind != ZR__SURFACE_MESH)
    return q->kept * zr__ff_patch_patch_sided(
                         gp, rc, side, gq, sc, l->sside ? -1.0 : 1.0, 16,
                         near ? 3 : 1, &rad->rule_recv);
  return q->kept * zr__ff_patch_patch(gp, rc, side, gq, sc, 16,
                                      near ? 3 : 1, &rad->rule_recv);
}

/* The points of node n at the centres of a k x k grid of its cell,
   moved off the surface towards side by eps, with that side's normal. */
static void grid_points(const zr_radiosity *rad, const zr__rad_node *node,
                        int k, int side, double eps, zr_vec3 *p,
                        zr_vec3 *n) {
  double cell[4];
  zr__rad_node_cell(node, cell);
  for (int i = 0; i < k * k; i++) {
    zr__surface_point pt;
    zr__surface_eval(&rad->surfs[node->surf].geom,
                     cell[0] + (i % k + 0.5) / k * (cell[1] - cell[0]),
                     cell[2] + (i / k + 0.5) / k * (cell[3] - cell[2]), &pt);
    n[i] = side ? zr_v3_neg(pt.n) : pt.n;
    p[i] = zr_v3_madd(pt.p, n[i], eps);
  }
}

bool zr__rad_occluded(const zr_radiosity *rad, zr_vec3 from, zr_vec3 to) {
  return zr__rad_occluded_hint(rad, from, to, NULL);
}

bool zr__rad_occluded_hint(const zr_radiosity *rad, zr_vec3 from,
                           zr_vec3 to, zr_bvh_hint *hint) {
  /* Any crossing will do: the walk asks each primitive only whether it
     crosses the segment, a shadow ray's question (zr__bvh_occluded). */
  zr_ray ray = {from, zr_v3_sub(to, from)};
  return zr__bvh_occluded(rad->scene->bvh, &ray, 1e-9, 1.0 - 1e-9, hint);
}

/* Whether x (normal nx) and y (normal ny) face each other. */
static bool facing(zr_vec3 x, zr_vec3 nx, zr_vec3 y, zr_vec3 ny) {
  zr_vec3 d = zr_v3_sub(y, x);
  return zr_v3_dot(d, nx) > 0.0 && zr_v3_dot(d, ny) < 0.0;
}

/*
 * The visible fraction of a link.  Only pairs of points that face each
 * other count: the form factor already leaves out what lies behind
 * either side (the contour formula clips it), so a ray to such a point
 * would count the same loss twice.  Receiver point i is paired with a
 * permuted source point (stride k + 1, coprime to k^2, so the rays do
 * not run in parallel bundles), or the next one that faces it.
 */
static double link_visibility(const zr_radiosity *rad,
                              const zr__rad_link *l, uint64_t *rays) {
  int k = rad->params.visibility_rays, kk = k * k, open = 0, cast = 0;
  double eps = 1e-7 * sqrt(rad->total_area);
  zr_vec3 xp[256], xn[256], yp[256], yn[256];
  grid_points(rad, &rad->nodes[l->recv], k, l->rside, eps, xp, xn);
  grid_points(rad, &rad->nodes[l->src], k, l->sside, eps, yp, yn);
  /* Points that a CSG removes (trim.c) cast no ray. */
  bool xk[256], yk[256];
  zr_bvh_hint hint = {0}; /* the link's rays share their blockers */
  const zr__rad_surface *xs = &rad->surfs[rad->nodes[l->recv].surf];
  const zr__rad_surface *ys = &rad->surfs[rad->nodes[l->src].surf];
  for (int i = 0; i < kk; i++) {
    xk[i] = xs->trim == NULL || zr__rad_trim_keeps(xs, xp[i]);
    yk[i] = ys->trim == NULL || zr__rad_trim_keeps(ys, yp[i]);
  }
  for (int i = 0; i < kk; i++) {
    if (!xk[i])
      continue;
    int j = (i * (k + 1)) % kk, tries = 0;
    while (tries < kk &&
           (!yk[j] || !facing(xp[i], xn[i], yp[j], yn[j]))) {
      j = (j + 1) % kk;
      tries++;
    }
    if (tries == kk)
      continue;
    cast++;
    if (!zr__rad_occluded_hint(rad, xp[i], yp[j], &hint))
      open++;
  }
  *rays += (uint64_t)cast;
  return cast > 0 ? (double)open / cast : 1.0;
}

/* Whether node n's surface can stand between two of its own points: a
   torus can (its tube hides the far side of the hole); the inside of a
   sphere, cylinder or cone cannot. */
static bool self_hiding(const zr_radiosity *rad, int32_t n) {
  return rad->surfs[rad->nodes[n].surf].geom.kind == ZR__SURFACE_TORUS;
}

/* The links of [begin, end) not yet final get their transfer factors;
   each link's own slot is all a worker writes, so the factors are the
   same whichever thread computes them. */
typedef struct finisher {
  zr_radiosity *rad;
  atomic_uint_fast64_t rays;
} finisher;

/* Link l's transfer factor and visibility, into l. */
static void finish_one(const zr_radiosity *rad, zr__rad_link *l,
                       uint64_t *rays) {
  double f = link_factor(rad, l);
  double vis = 1.0;
  /* A cell sees all of itself unless its surface can hide part of
     itself from itself, as a torus's tube does across the hole. */
  bool self = l->recv == l->src;
  if (f > 0.0 && (!self || self_hiding(rad, l->recv)))
    vis = link_visibility(rad, l, rays);
  f *= vis;
  l->vis = vis;
  l->ff = isfinite(f) ? f : 0.0;
  l->final = 1;
}

static void finish_range(void *user, size_t begin, size_t end, int worker) {
  (void)worker;
  finisher *w = user;
  uint64_t rays = 0;
  for (size_t i = begin; i < end; i++) {
    zr__rad_link *l = &w->rad->links[i];
    if (!l->dead && !l->final)
      finish_one(w->rad, l, &rays);
  }
  /* A count has no summation order: any thread may add its share. */
  atomic_fetch_add(&w->rays, rays);
}

/* ---- transfer factors across a team (zr_team, core/team.h) ----
 *
 * The links still to finish are listed in link order and cut into
 * chunks of FINISH_CHUNK; member r of n finishes chunks r, r + n, ...
 * (interleaved, because the cost of a link varies a hundredfold and
 * neighbouring links cost alike), with its threads.  Each member then
 * sends the factor and visibility of its links, and every member writes
 * every member's values into the same links: a link's values are
 * computed by one member from the scene and the link alone, so they are
 * the same bits whoever computes them. */
#define FINISH_CHUNK 64

typedef struct team_finisher {
  zr_radiosity *rad;
  const uint32_t *mine; /* the links this member finishes */
  atomic_uint_fast64_t rays;
} team_finisher;

static void finish_list(void *user, size_t begin, size_t end, int worker) {
  (void)worker;
  team_finisher *w = user;
  uint64_t rays = 0;
  for (size_t i = begin; i < end; i++)
    finish_one(w->rad, &w->rad->links[w->mine[i]], &rays);
  atomic_fetch_add(&w->rays, rays);
}

static zr_status finish_team(zr_radiosity *rad, const zr_team *team) {
  size_t n_todo = 0;
  for (size_t i = 0; i < rad->n_links; i++)
    n_todo += !rad->links[i].dead && !rad->links[i].final;
  uint32_t *todo = malloc((n_todo + 1) * sizeof *todo);
  uint32_t *mine = malloc((n_todo + 1) * sizeof *mine);
  zr__pack *pack = &rad->team_pack;
  zr__pack_reset(pack);
  zr_status st = todo && mine ? ZR_OK : ZR_ENOMEM;
  size_t n_mine = 0;
  if (st == ZR_OK) {
    size_t k = 0;
    for (size_t i = 0; i < rad->n_links; i++)
      if (!rad->links[i].dead && !rad->links[i].final)
        todo[k++] = (uint32_t)i;
    for (size_t k = 0; k < n_todo; k++)
      if (zr__team_mine(team, k / FINISH_CHUNK))
        mine[n_mine++] = todo[k];
    team_finisher w;
    w.rad = rad;
    w.mine = mine;
    atomic_init(&w.rays, 0);
    zr__rad_parallel(threads_of(rad), n_mine, 16, finish_list, &w);
    uint64_t rays = (uint64_t)atomic_load(&w.rays);
    zr__pack_put(pack, &rays, sizeof rays);
    for (size_t k = 0; k < n_mine; k++) {
      const zr__rad_link *l = &rad->links[mine[k]];
      double v[2] = {l->ff, l->vis};
      zr__pack_put(pack, v, sizeof v);
    }
    if (pack->nomem)
      st = ZR_ENOMEM;
  }
  zr__team_parts parts;
  st = zr__team_exchange_in(team, st, pack->bytes, pack->n, &rad->team_room,
                            &parts);
  for (int r = 0; st == ZR_OK && r < team->size; r++) {
    const char *at = parts.bytes + parts.offset[r];
    const char *end = parts.bytes + parts.offset[r + 1];
    uint64_t rays = 0;
    if (!zr__unpack(&at, end, &rays, sizeof rays))
      st = ZR_EMPI;
    rad->stats.visibility_rays += rays;
    for (size_t k = (size_t)r * FINISH_CHUNK; st == ZR_OK && k < n_todo;
         k += (size_t)team->size * FINISH_CHUNK) {
      for (size_t j = k; j < n_todo && j < k + FINISH_CHUNK; j++) {
        zr__rad_link *l = &rad->links[todo[j]];
        double v[2];
        if (!zr__unpack(&at, end, v, sizeof v)) {
          st = ZR_EMPI;
          break;
        }
        l->ff = v[0];
        l->vis = v[1];
        l->final = 1;
      }
    }
    if (st == ZR_OK && at != end)
      st = ZR_EMPI; /* a member sent what the others did not expect */
  }
  zr__team_parts_free(&parts);
  free(todo);
  free(mine);
  return st;
}

zr_status zr__rad_finish_links(zr_radiosity *rad) {
  const zr_team *team = rad->params.team;
  if (rad->clustered) {
    zr_status st = zr__rad_vol_finish(rad);
    if (st != ZR_OK)
      return st;
  }
  if (zr__team_size(team) > 1)
    return finish_team(rad, team);
  finisher w;
  w.rad = rad;
  atomic_init(&w.rays, 0);
  zr__rad_parallel(threads_of(rad), rad->n_links, 64, finish_range, &w);
  rad->stats.visibility_rays += (uint64_t)atomic_load(&w.rays);
  return ZR_OK;
}
