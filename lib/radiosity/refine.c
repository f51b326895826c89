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
 */
#include "radiosity/radiosity.h"

#include <stdlib.h>
#include <string.h>

#include "radiosity/formfactor.h"
#include "trace/bvh.h"

/* Sample points of a cell for side classification. */
typedef struct cell_samples {
  zr_vec3 p[9], n[9];
} cell_samples;

static void node_samples(const zr_radiosity *rad, int32_t n,
                         cell_samples *out) {
  const zr__rad_node *node = &rad->nodes[n];
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

/* Counts of sample pairs per side combination, index 2 * rside + sside. */
static void classify(const zr_radiosity *rad, int32_t p, int32_t q,
                     int counts[4]) {
  cell_samples a, b;
  node_samples(rad, p, &a);
  node_samples(rad, q, &b);
  memset(counts, 0, 4 * sizeof *counts);
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
      counts[2 * (ca < 0.0) + (cb < 0.0)]++;
    }
}

/* The cosine between the sided normal n (loosened by spread) and the
   direction from c to t, clamped to [0, 1]. */
static double loose_cos(zr_vec3 n, double spread, zr_vec3 c, zr_vec3 t) {
  zr_vec3 d = zr_v3_sub(t, c);
  double len = zr_v3_len(d);
  if (!(len > 0.0))
    return 0.0;
  double th = acos(fmax(-1.0, fmin(1.0, zr_v3_dot(n, d) / len))) - spread;
  return th <= 0.0 ? 1.0 : th >= M_PI / 2 ? 0.0 : cos(th);
}

/*
 * The oracle factor from node x's side sx to node y's side sy: Hanrahan's
 * A cos cos / (pi r^2 + A) between the centres, where each cosine is the
 * largest towards the other cell's 3 x 3 sample points, so a large cell
 * whose centre lies behind the other (a floor under a box's face) is
 * not judged invisible.
 */
static double oracle(const zr_radiosity *rad, int32_t x, int sx, int32_t y,
                     int sy) {
  const zr__rad_node *a = &rad->nodes[x], *b = &rad->nodes[y];
  zr_vec3 d = zr_v3_sub(b->centre, a->centre);
  double r2 = zr_v3_dot(d, d);
  if (!(r2 > 0.0))
    return b->area > 0.0 ? 1.0 : 0.0;
  zr_vec3 na = zr_v3_scale(a->normal, sx ? -1.0 : 1.0);
  zr_vec3 nb = zr_v3_scale(b->normal, sy ? -1.0 : 1.0);
  cell_samples sa, sb;
  node_samples(rad, x, &sa);
  node_samples(rad, y, &sb);
  double ca = 0.0, cb = 0.0;
  for (int i = 0; i < 9; i++) {
    ca = fmax(ca, loose_cos(na, a->spread, a->centre, sb.p[i]));
    cb = fmax(cb, loose_cos(nb, b->spread, b->centre, sa.p[i]));
  }
  return b->area * ca * cb / (M_PI * r2 + b->area);
}

static bool can_split(const zr_radiosity *rad, int32_t n) {
  const zr__rad_node *node = &rad->nodes[n];
  if (rad->params.uniform > 0)
    return node->child >= 0;
  return node->child >= 0 ||
         (node->area > rad->area_eps_abs && node->depth < ZR__RAD_DEPTH);
}

static zr_status add_link(zr_radiosity *rad, int32_t p, int rs, int32_t q,
                          int ss);
static zr_status create_links(zr_radiosity *rad, int32_t p, int32_t q,
                              int rs_only);

/* Links every child of p to q (or p to every child of q); rs_only
   (0, 1, or -1 for both) keeps the receiver side of the link split, so
   a receiver linked on both sides does not get its children linked
   twice. */
static zr_status split_and_link(zr_radiosity *rad, int32_t p, int32_t q,
                                bool split_p, int rs_only) {
  int32_t n = split_p ? p : q;
  if (!zr__rad_subdivide(rad, n))
    return ZR_ENOMEM;
  int32_t first = rad->nodes[n].child;
  for (int k = 0; k < 4; k++) {
    zr_status st = split_p ? create_links(rad, first + k, q, rs_only)
                           : create_links(rad, p, first + k, rs_only);
    if (st != ZR_OK)
      return st;
  }
  return ZR_OK;
}

/* Links all pairs of the children of p (after a self link is split). */
static zr_status link_children(zr_radiosity *rad, int32_t p) {
  if (!zr__rad_subdivide(rad, p))
    return ZR_ENOMEM;
  int32_t c = rad->nodes[p].child;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) {
      zr_status st = create_links(rad, c + i, c + j, -1);
      if (st != ZR_OK)
        return st;
    }
  return ZR_OK;
}

static int self_choice(const zr_radiosity *rad, const zr__rad_link *l);

/* A curved cell that sees itself gets a link to itself on each pair of
   sides that face, unless the self transfer is large enough that its
   children should be linked instead. */
static zr_status self_links(zr_radiosity *rad, int32_t p, int counts[4],
                            int rs_only) {
  zr__rad_link probe;
  memset(&probe, 0, sizeof probe);
  probe.recv = probe.src = p;
  for (int k = 0; k < 4; k++)
    if (counts[k] > 0 && probe.sside < (k & 1))
      probe.sside = (uint8_t)(k & 1);
  if (self_choice(rad, &probe) == 3)
    return link_children(rad, p);
  for (int k = 0; k < 4; k++)
    if (counts[k] > 0 && (rs_only < 0 || rs_only == k >> 1)) {
      zr_status st = add_link(rad, p, k >> 1, p, k & 1);
      if (st != ZR_OK)
        return st;
    }
  return ZR_OK;
}

/* Links receiver p to source q on the sides that face each other (only
   receiver side rs_only unless it is -1). */
static zr_status create_links(zr_radiosity *rad, int32_t p, int32_t q,
                              int rs_only) {
  int counts[4];
  classify(rad, p, q, counts);
  if (p == q)
    return counts[0] + counts[1] + counts[2] + counts[3] > 0
               ? self_links(rad, p, counts, rs_only)
               : ZR_OK;
  int front = counts[0] + counts[2], back = counts[1] + counts[3];
  if (front == 0 && back == 0)
    return ZR_OK;
  if (front > 0 && back > 0) {
    /* The receiver straddles the source's plane: split it if it can. */
    if (can_split(rad, p))
      return split_and_link(rad, p, q, true, rs_only);
    if (!rad->surfs[rad->nodes[q].surf].geom.planar && can_split(rad, q))
      return split_and_link(rad, p, q, false, rs_only);
  }
  int ss = back > front;
  for (int rs = 0; rs < 2; rs++)
    if (counts[2 * rs + ss] > 0 && (rs_only < 0 || rs == rs_only)) {
      zr_status st = add_link(rad, p, rs, q, ss);
      if (st != ZR_OK)
        return st;
    }
  return ZR_OK;
}

/*
 * How much the exact unoccluded factor to the source varies over the
 * receiver: the spread (largest minus smallest) of the point-to-polygon
 * factor near the receiver's corners, edge midpoints and centre.  A link
 * hands every point of its receiver the receiver's mean factor, so
 * B_q A_p times this spread bounds the light it misplaces inside the
 * receiver.
 */
static double factor_spread(const zr_radiosity *rad, const zr__rad_link *l) {
  const zr__rad_node *p = &rad->nodes[l->recv], *q = &rad->nodes[l->src];
  double rc[4], sc[4];
  zr__rad_node_cell(p, rc);
  zr__rad_node_cell(q, sc);
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
      double f = zr__ff_point_polygon(pt.p, n, poly, nv);
      lo = fmin(lo, f);
      hi = fmax(hi, f);
    }
  return hi - lo;
}

/* The spread of the largest channel of B over node n's children (0 for
   a leaf): how unevenly a source shines. */
static double radiosity_spread(const zr_radiosity *rad, int32_t n,
                               int side) {
  const zr__rad_node *node = &rad->nodes[n];
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
static int larger_end(const zr_radiosity *rad, const zr__rad_link *l,
                      bool sp, bool sq) {
  double f_pq = oracle(rad, l->recv, l->rside, l->src, l->sside);
  double f_qp = oracle(rad, l->src, l->sside, l->recv, l->rside);
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
static int error_choice(const zr_radiosity *rad, const zr__rad_link *l,
                        bool sp, bool sq, double thr) {
  const zr__rad_node *p = &rad->nodes[l->recv], *q = &rad->nodes[l->src];
  double bq = zr__rad_max3(q->b[l->sside]);
  if (!(bq * p->area > thr))
    return 0; /* no factor can make this link matter */
  if (sp && bq * p->area * factor_spread(rad, l) > thr)
    return 1;
  double f_pq = oracle(rad, l->recv, l->rside, l->src, l->sside);
  bool partial = l->final && l->vis > 0.0 && l->vis < 1.0;
  if (partial && bq * p->area * f_pq > thr)
    return larger_end(rad, l, sp, sq);
  /* An uneven source errs by the same sign at every small receiver near
     it, so this test is per unit area of the receiver: the irradiance
     error against the threshold spread over the scene's area. */
  double thr_area = thr / rad->total_area;
  if (sq && radiosity_spread(rad, l->src, l->sside) * f_pq > thr_area)
    return 2;
  return 0;
}

/*
 * A self link is split (3) while the light it keeps inside the cell may
 * exceed the threshold: B A F_self, with F_self estimated as that of a
 * spherical cap whose normals spread as much, (1 - cos spread) / 2.
 */
static int self_choice(const zr_radiosity *rad, const zr__rad_link *l) {
  const zr__rad_node *p = &rad->nodes[l->recv];
  if (!can_split(rad, l->recv))
    return 0;
  if (rad->params.uniform > 0)
    return 3;
  double f_self = 0.5 * (1.0 - cos(fmin(p->spread, M_PI)));
  double e = zr__rad_max3(p->b[l->sside]) * p->area * f_self;
  return e > rad->params.bf_eps * rad->power_ref ? 3 : 0;
}

/* Whether link l should be split, and which end: 1 receiver, 2 source,
   3 both (a self link). */
static int refine_choice(const zr_radiosity *rad, const zr__rad_link *l) {
  if (l->recv == l->src)
    return self_choice(rad, l);
  bool sp = can_split(rad, l->recv), sq = can_split(rad, l->src);
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
  const zr__rad_node *p = &rad->nodes[l->recv], *q = &rad->nodes[l->src];
  double f_pq = oracle(rad, l->recv, l->rside, l->src, l->sside);
  if (l->final && l->vis > 0.0 && l->vis < 1.0)
    thr *= 0.1;
  if (!(zr__rad_max3(q->b[l->sside]) * f_pq * p->area > thr))
    return 0;
  return larger_end(rad, l, sp, sq);
}

/* Replaces link li by finer links when refinement asks; *split set. */
static zr_status refine_one(zr_radiosity *rad, size_t li, bool *split) {
  zr__rad_link l = rad->links[li];
  int choice = refine_choice(rad, &l);
  *split = choice != 0;
  if (!*split)
    return ZR_OK;
  rad->links[li].dead = 1;
  if (choice == 3) {
    /* Every side pair of the cell is relinked through its children, so
       its other self links go too. */
    for (size_t k = 0; k < rad->n_links; k++)
      if (rad->links[k].recv == l.recv && rad->links[k].src == l.recv)
        rad->links[k].dead = 1;
    return link_children(rad, l.recv);
  }
  return split_and_link(rad, l.recv, l.src, choice == 1, l.rside);
}

/* Appends the link and refines it at once (depth first). */
static zr_status add_link(zr_radiosity *rad, int32_t p, int rs, int32_t q,
                          int ss) {
  if (rad->n_links == rad->cap_links) {
    size_t cap = rad->cap_links ? 2 * rad->cap_links : 256;
    zr__rad_link *a = realloc(rad->links, cap * sizeof *a);
    if (a == NULL)
      return ZR_ENOMEM;
    rad->links = a;
    rad->cap_links = cap;
  }
  size_t li = rad->n_links++;
  zr__rad_link *l = &rad->links[li];
  memset(l, 0, sizeof *l);
  l->recv = p;
  l->src = q;
  l->rside = (uint8_t)rs;
  l->sside = (uint8_t)ss;
  bool split;
  return refine_one(rad, li, &split);
}

zr_status zr__rad_link_all(zr_radiosity *rad) {
  for (size_t i = 0; i < rad->n_surfs; i++)
    for (size_t j = 0; j < rad->n_surfs; j++) {
      if (i == j && rad->surfs[i].geom.planar)
        continue;
      zr_status st =
          create_links(rad, rad->surfs[i].root, rad->surfs[j].root, -1);
      if (st != ZR_OK)
        return st;
    }
  return ZR_OK;
}

zr_status zr__rad_refine_links(zr_radiosity *rad, size_t *changed) {
  size_t n = rad->n_links;
  *changed = 0;
  for (size_t i = 0; i < n; i++) {
    if (rad->links[i].dead)
      continue;
    bool split;
    zr_status st = refine_one(rad, i, &split);
    if (st != ZR_OK)
      return st;
    *changed += split;
  }
  return ZR_OK;
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
  for (size_t n = 0; n < rad->n_nodes; n++)
    if (rad->nodes[n].depth < n_levels && rad->nodes[n].child < 0 &&
        !zr__rad_subdivide(rad, (int32_t)n))
      return ZR_ENOMEM;
  return ZR_OK;
}

/* ---- transfer factors ---- */

typedef struct self_sum {
  const zr__surface *src;
  double cell[4];
  double side;
  const zr__gauss_rule *rule;
  double flux, area;
} self_sum;

static void add_self(const zr__surface_point *pt, double weight,
                     void *user) {
  self_sum *s = user;
  zr_vec3 n = zr_v3_scale(pt->n, s->side);
  s->flux += weight * zr__ff_point_patch_quadrature(
                          pt->p, n, s->src, s->cell[0], s->cell[1],
                          s->cell[2], s->cell[3], s->rule);
  s->area += weight;
}

static double link_factor(const zr_radiosity *rad, const zr__rad_link *l) {
  const zr__rad_node *p = &rad->nodes[l->recv], *q = &rad->nodes[l->src];
  const zr__surface *gp = &rad->surfs[p->surf].geom;
  const zr__surface *gq = &rad->surfs[q->surf].geom;
  double rc[4], sc[4], side = l->rside ? -1.0 : 1.0;
  zr__rad_node_cell(p, rc);
  zr__rad_node_cell(q, sc);
  if (l->recv == l->src) {
    self_sum s = {gq, {sc[0], sc[1], sc[2], sc[3]}, side, &rad->rule_src,
                  0.0, 0.0};
    zr__surface_quadrature(gp, rc[0], rc[1], rc[2], rc[3], 2,
                           &rad->rule_recv, add_self, &s);
    return s.area > 0.0 ? fmin(1.0, s.flux / s.area) : 0.0;
  }
  zr_vec3 d = zr_v3_sub(q->centre, p->centre);
  bool near = zr_v3_dot(d, d) < 4.0 * (p->area + q->area);
  return zr__ff_patch_patch(gp, rc, side, gq, sc, 16, near ? 3 : 1,
                            &rad->rule_recv);
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

/* Stops a crossing walk at the first crossing. */
static bool stop_at_first(const zr_hit *hit, void *user) {
  (void)hit;
  *(bool *)user = true;
  return false;
}

bool zr__rad_occluded(const zr_radiosity *rad, zr_vec3 from, zr_vec3 to) {
  /* Any crossing will do, so the walk stops at the first one instead of
     searching for the nearest: a shadow ray's question. */
  zr_ray ray = {from, zr_v3_sub(to, from)};
  bool blocked = false;
  zr__bvh_all(rad->scene->bvh, &ray, 1e-9, 1.0 - 1e-9, stop_at_first,
              &blocked);
  return blocked;
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
static double link_visibility(zr_radiosity *rad, const zr__rad_link *l) {
  int k = rad->params.visibility_rays, kk = k * k, open = 0, cast = 0;
  double eps = 1e-7 * sqrt(rad->total_area);
  zr_vec3 xp[256], xn[256], yp[256], yn[256];
  grid_points(rad, &rad->nodes[l->recv], k, l->rside, eps, xp, xn);
  grid_points(rad, &rad->nodes[l->src], k, l->sside, eps, yp, yn);
  for (int i = 0; i < kk; i++) {
    int j = (i * (k + 1)) % kk, tries = 0;
    while (tries < kk && !facing(xp[i], xn[i], yp[j], yn[j])) {
      j = (j + 1) % kk;
      tries++;
    }
    if (tries == kk)
      continue;
    cast++;
    if (!zr__rad_occluded(rad, xp[i], yp[j]))
      open++;
  }
  rad->stats.visibility_rays += (uint64_t)cast;
  return cast > 0 ? (double)open / cast : 1.0;
}

void zr__rad_finish_links(zr_radiosity *rad) {
  for (size_t i = 0; i < rad->n_links; i++) {
    zr__rad_link *l = &rad->links[i];
    if (l->dead || l->final)
      continue;
    double f = link_factor(rad, l);
    double vis = 1.0;
    if (f > 0.0 && l->recv != l->src)
      vis = link_visibility(rad, l);
    f *= vis;
    l->vis = vis;
    l->ff = isfinite(f) ? f : 0.0;
    l->final = 1;
  }
}
