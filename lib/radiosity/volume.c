/*
 * volume.c - volume clusters of whole surfaces, so that initial linking
 * does not pair every two surfaces of a large scene.
 *
 * Smits, Arvo and Greenberg ("A Clustering Algorithm for Radiosity in
 * Complex Environments", SIGGRAPH 1994) and Sillion ("A Unified
 * Hierarchical Algorithm for Global Illumination with Scattering
 * Volumes and Object Clusters", 1995) put a hierarchy of clusters above
 * the input surfaces and let links join clusters.  Here the hierarchy
 * is a binary tree over the surfaces (median splits of their boxes'
 * centres along the longest axis); a leaf is one surface.  Linking
 * starts from one link of the root cluster to itself and refines it as
 * the 1991 algorithm refines links between cells:
 *
 *   - a cluster's link to itself becomes links between every two of
 *     its children (both orders, and each child to itself);
 *   - a link between two clusters whose boxes meet, or whose light may
 *     exceed the threshold, is split at the cluster with the larger
 *     sphere round its box (a single surface is never split here); the
 *     light is first bounded by P_S A_R / (pi d^2), with P_S the
 *     source's power (area times the larger side's radiosity, summed
 *     over its elements), A_R the receiver's area and d the gap
 *     between the boxes: B F A of Hanrahan's BF refinement with every
 *     cosine taken as 1; where that bound fails, estimated element by
 *     element (vlink_estimate);
 *   - a link between two single surfaces is a pair of surfaces, which
 *     refine.c links as it links every pair without clusters (its
 *     sides, visibility and refinement down the quadtrees).
 *
 * A link kept between clusters carries light as Sillion's clusters do,
 * element by element: the source's radiant intensity towards the
 * receiver's centre is the sum over its elements of B A cos V / pi, and
 * each receiving element gets that intensity times cos V / r^2 as
 * irradiance.  The elements are the nodes that stand for a surface: a
 * planar surface's root, a curved surface's cells of its initial 4 x 4
 * split.  Visibility is three factors, so that what stands between the
 * clusters is not counted twice (once from each end, as one ray per
 * element end from element to the other cluster did: the boxes of a
 * furnace came out dark): each element's one ray towards the other
 * cluster's centre as far as the edge of its own cluster's box (what
 * hides it inside its cluster: a face turned inside a box is dark that
 * way), and for the link BETWEEN_RAYS segments between element centres
 * of the two, each the part outside both boxes.  The irradiance goes
 * into the element node's gathered values (push-pull takes it down)
 * and is kept per element for the final gather.  A single surface ends
 * a cluster link only when it is small against the distance
 * (LEAF_ADMIT), since it is lit and seen as its centre is.
 *
 * In a furnace of 25 boxes (test_radiosity_volume_clusters) every side
 * stays within 1% of B = 2.  Scenes of params.cluster_surfaces surfaces
 * or more (64 by default) are clustered.
 *
 * Meshes keep their own clusters of faces (cluster.c) and are paired
 * with every other surface; small scenes (fewer than
 * params.cluster_surfaces surfaces, 64 by default) pair every two
 * surfaces as before, so their solutions are the same bytes.
 * Everything here runs on one thread in a fixed order
 * (the weights of many links at once, each into its own array), so the
 * solution does not depend on the thread count.  A team of processes
 * (MPI) and the shooting and uniform solvers pair every two surfaces.
 */
#include "radiosity/radiosity.h"

#include <stdlib.h>
#include <string.h>

#include "core/team.h"
#include "radiosity/workers.h"

static bool is_mesh(const zr_radiosity *rad, size_t s) {
  return rad->surfs[s].geom.kind == ZR__SURFACE_MESH;
}

/* ---- building the tree ---- */

typedef struct vol_builder {
  zr_radiosity *rad;
  zr_vec3 *lo, *hi; /* per surface */
  uint32_t *order;  /* surfaces being split */
  size_t cap_vols, cap_elems;
  bool nomem;
} vol_builder;

static bool add_elem(vol_builder *b, int32_t node) {
  zr_radiosity *rad = b->rad;
  if (rad->n_elems == b->cap_elems) {
    size_t cap = b->cap_elems ? 2 * b->cap_elems : 256;
    zr__rad_elem *e = realloc(rad->elems, cap * sizeof *e);
    if (e == NULL)
      return false;
    rad->elems = e;
    b->cap_elems = cap;
  }
  zr__rad_elem *e = &rad->elems[rad->n_elems];
  memset(e, 0, sizeof *e);
  e->node = node;
  rad->nodes[node].elem1 = (uint32_t)++rad->n_elems;
  return true;
}

/* The elements of a surface below node n: a planar surface's root, a
   curved one's cells at depth 2 (or leaves above it). */
static bool surface_elems(vol_builder *b, int32_t n, bool planar) {
  const zr__rad_node *node = &b->rad->nodes[n];
  if (!(node->kept > 0.0) || !(node->area > 0.0))
    return true;
  if (planar || node->child < 0 || node->depth >= 2)
    return add_elem(b, n);
  int32_t first = node->child;
  for (int k = 0; k < 4; k++)
    if (!surface_elems(b, first + k, planar))
      return false;
  return true;
}

/* The box of surface s from a 5 x 5 grid of points of each element's
   cell, padded for the bulge of a curved cell between them. */
static void surface_box(const zr_radiosity *rad, uint32_t e0, uint32_t e1,
                        zr_vec3 *lo, zr_vec3 *hi) {
  zr_vec3 l = zr_v3(INFINITY, INFINITY, INFINITY), h = zr_v3_neg(l);
  for (uint32_t e = e0; e < e1; e++) {
    const zr__rad_node *node = &rad->nodes[rad->elems[e].node];
    double cell[4];
    zr__rad_node_cell(node, cell);
    for (int j = 0; j < 5; j++)
      for (int i = 0; i < 5; i++) {
        zr__surface_point pt;
        zr__surface_eval(&rad->surfs[node->surf].geom,
                         cell[0] + 0.25 * i * (cell[1] - cell[0]),
                         cell[2] + 0.25 * j * (cell[3] - cell[2]), &pt);
        l = zr_v3_min(l, pt.p);
        h = zr_v3_max(h, pt.p);
      }
  }
  double pad = 0.05 * zr_v3_len(zr_v3_sub(h, l));
  zr_vec3 m = zr_v3(pad, pad, pad);
  *lo = zr_v3_sub(l, m);
  *hi = zr_v3_add(h, m);
}

static int32_t new_vol(vol_builder *b) {
  zr_radiosity *rad = b->rad;
  if (rad->n_vols == b->cap_vols) {
    size_t cap = b->cap_vols ? 2 * b->cap_vols : 64;
    zr__rad_vol *v = realloc(rad->vols, cap * sizeof *v);
    if (v == NULL)
      return -1;
    rad->vols = v;
    b->cap_vols = cap;
  }
  zr__rad_vol *v = &rad->vols[rad->n_vols];
  memset(v, 0, sizeof *v);
  v->child[0] = v->child[1] = -1;
  v->surf = -1;
  return (int32_t)rad->n_vols++;
}

static void set_sphere(zr__rad_vol *v) {
  v->centre = zr_v3_scale(zr_v3_add(v->lo, v->hi), 0.5);
  v->radius = 0.5 * zr_v3_len(zr_v3_sub(v->hi, v->lo));
}

/* A surface by one coordinate of its box's centre; ties by index, so
   the tree is the same on every platform. */
typedef struct keyed {
  double key;
  uint32_t surf;
} keyed;

static int by_key(const void *x, const void *y) {
  const keyed *a = x, *b = y;
  if (a->key != b->key)
    return a->key < b->key ? -1 : 1;
  return a->surf < b->surf ? -1 : a->surf > b->surf;
}

/* The cluster of surfaces order[0, n); -1 when out of memory. */
static int32_t build(vol_builder *b, uint32_t *order, size_t n) {
  zr_radiosity *rad = b->rad;
  int32_t v = new_vol(b);
  if (v < 0)
    return -1;
  if (n == 1) {
    uint32_t s = order[0];
    zr__rad_vol *vol = &rad->vols[v];
    vol->surf = (int32_t)s;
    vol->e0 = (uint32_t)rad->n_elems;
    if (!surface_elems(b, rad->surfs[s].root, rad->surfs[s].geom.planar))
      return -1;
    vol = &rad->vols[v];
    vol->e1 = (uint32_t)rad->n_elems;
    vol->lo = b->lo[s];
    vol->hi = b->hi[s];
    for (uint32_t e = vol->e0; e < vol->e1; e++)
      vol->area += rad->nodes[rad->elems[e].node].area;
    set_sphere(vol);
    return v;
  }
  zr_vec3 cl = zr_v3(INFINITY, INFINITY, INFINITY), ch = zr_v3_neg(cl);
  for (size_t i = 0; i < n; i++) {
    zr_vec3 c = zr_v3_scale(zr_v3_add(b->lo[order[i]], b->hi[order[i]]),
                            0.5);
    cl = zr_v3_min(cl, c);
    ch = zr_v3_max(ch, c);
  }
  zr_vec3 ext = zr_v3_sub(ch, cl);
  int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
  keyed *k = malloc(n * sizeof *k);
  if (k == NULL)
    return -1;
  for (size_t i = 0; i < n; i++) {
    k[i].key = zr_v3_get(zr_v3_add(b->lo[order[i]], b->hi[order[i]]), axis);
    k[i].surf = order[i];
  }
  qsort(k, n, sizeof *k, by_key);
  for (size_t i = 0; i < n; i++)
    order[i] = k[i].surf;
  free(k);
  size_t half = n / 2;
  int32_t c0 = build(b, order, half);
  if (c0 < 0)
    return -1;
  int32_t c1 = build(b, order + half, n - half);
  if (c1 < 0)
    return -1;
  zr__rad_vol *vol = &rad->vols[v];
  const zr__rad_vol *a = &rad->vols[c0], *d = &rad->vols[c1];
  vol->child[0] = c0;
  vol->child[1] = c1;
  vol->e0 = a->e0;
  vol->e1 = d->e1;
  vol->lo = zr_v3_min(a->lo, d->lo);
  vol->hi = zr_v3_max(a->hi, d->hi);
  vol->area = a->area + d->area;
  set_sphere(vol);
  return v;
}

zr_status zr__rad_vol_build(zr_radiosity *rad) {
  rad->clustered = false;
  if (rad->params.cluster_surfaces <= 0 ||
      rad->n_surfs < (size_t)rad->params.cluster_surfaces ||
      rad->params.uniform > 0 ||
      rad->params.shooting != 0 || zr__team_size(rad->params.team) > 1)
    return ZR_OK;
  vol_builder b;
  memset(&b, 0, sizeof b);
  b.rad = rad;
  size_t n = 0;
  b.lo = malloc(rad->n_surfs * sizeof *b.lo);
  b.hi = malloc(rad->n_surfs * sizeof *b.hi);
  b.order = malloc(rad->n_surfs * sizeof *b.order);
  zr_status st = b.lo && b.hi && b.order ? ZR_OK : ZR_ENOMEM;
  for (size_t s = 0; st == ZR_OK && s < rad->n_surfs; s++) {
    if (is_mesh(rad, s))
      continue;
    /* The box from the surface's elements, made here and dropped. */
    size_t e0 = rad->n_elems;
    if (!surface_elems(&b, rad->surfs[s].root, rad->surfs[s].geom.planar)) {
      st = ZR_ENOMEM;
      break;
    }
    if (rad->n_elems > e0) {
      surface_box(rad, (uint32_t)e0, (uint32_t)rad->n_elems, &b.lo[s],
                  &b.hi[s]);
      b.order[n++] = (uint32_t)s;
    }
    for (size_t e = e0; e < rad->n_elems; e++)
      rad->nodes[rad->elems[e].node].elem1 = 0;
    rad->n_elems = e0;
  }
  if (st == ZR_OK && n >= 2 && build(&b, b.order, n) < 0)
    st = ZR_ENOMEM;
  free(b.lo);
  free(b.hi);
  free(b.order);
  if (st == ZR_OK && n >= 2)
    rad->clustered = true;
  else
    zr__rad_vol_free(rad);
  return st;
}

void zr__rad_vol_free(zr_radiosity *rad) {
  for (size_t i = 0; i < rad->n_vlinks; i++)
    free(rad->vlinks[i].w);
  free(rad->vlinks);
  rad->vlinks = NULL;
  rad->n_vlinks = rad->cap_vlinks = 0;
  for (size_t e = 0; rad->nodes != NULL && e < rad->n_elems; e++)
    rad->nodes[rad->elems[e].node].elem1 = 0;
  free(rad->elems);
  rad->elems = NULL;
  rad->n_elems = 0;
  free(rad->vols);
  rad->vols = NULL;
  rad->n_vols = 0;
}

size_t zr__rad_vol_live(const zr_radiosity *rad) {
  size_t n = 0;
  for (size_t i = 0; i < rad->n_vlinks; i++)
    n += !rad->vlinks[i].dead;
  return n;
}

/* ---- refinement ---- */

static void pair_push(zr__rad_pairs *p, uint32_t i, uint32_t j) {
  if (p->nomem)
    return;
  if (p->n == p->cap) {
    size_t cap = p->cap ? 2 * p->cap : 1024;
    uint32_t *ij = realloc(p->ij, 2 * cap * sizeof *ij);
    if (ij == NULL) {
      p->nomem = true;
      return;
    }
    p->ij = ij;
    p->cap = cap;
  }
  p->ij[2 * p->n] = i;
  p->ij[2 * p->n + 1] = j;
  p->n++;
}

static bool vlink_push(zr_radiosity *rad, int32_t r, int32_t s) {
  if (rad->n_vlinks == rad->cap_vlinks) {
    size_t cap = rad->cap_vlinks ? 2 * rad->cap_vlinks : 256;
    if (!zr__rad_charge(rad, (cap - rad->cap_vlinks) * sizeof *rad->vlinks))
      return false;
    zr__rad_vlink *v = realloc(rad->vlinks, cap * sizeof *v);
    if (v == NULL)
      return false;
    rad->vlinks = v;
    rad->cap_vlinks = cap;
  }
  zr__rad_vlink *l = &rad->vlinks[rad->n_vlinks++];
  memset(l, 0, sizeof *l);
  l->recv = r;
  l->src = s;
  return true;
}

/* Each cluster's power, area times the larger side's radiosity summed
   over its elements (prefix sums over the elements). */
static double *cluster_power(const zr_radiosity *rad) {
  double *pre = malloc((rad->n_elems + 1) * sizeof *pre);
  if (pre == NULL)
    return NULL;
  pre[0] = 0.0;
  for (size_t e = 0; e < rad->n_elems; e++) {
    const zr__rad_node *n = &rad->nodes[rad->elems[e].node];
    double b = fmax(zr__rad_max3(n->b[0]), zr__rad_max3(n->b[1]));
    pre[e + 1] = pre[e] + n->area * b;
  }
  return pre;
}

typedef struct vol_refiner {
  zr_radiosity *rad;
  const double *pre; /* cluster_power */
  zr__rad_pairs *pairs;
  double thr;
  bool nomem;
} vol_refiner;


/*
 * The light a link r <- s may carry, B F A as Hanrahan's oracle has it
 * for cells, element by element without visibility: the source's
 * intensity towards r's centre (sum of B A |cos| / pi, B of the side
 * facing r) times the receiver's sum of A |cos| / r^2 towards s's
 * centre.  Costs the two clusters' elements; it is asked only where
 * the cheap bound (every cosine 1, the spheres' gap for r) fails.
 */
static double vlink_estimate(const zr_radiosity *rad, const zr__rad_vol *vr,
                             const zr__rad_vol *vs) {
  double src = 0.0;
  for (uint32_t e = vs->e0; e < vs->e1; e++) {
    const zr__rad_node *q = &rad->nodes[rad->elems[e].node];
    zr_vec3 d = zr_v3_sub(vr->centre, q->centre);
    double r = zr_v3_len(d);
    if (!(r > 0.0))
      continue;
    double c = zr_v3_dot(d, q->normal) / r;
    src += q->area * fabs(c) * zr__rad_max3(q->b[c < 0.0]) / M_PI;
  }
  if (!(src > 0.0))
    return 0.0;
  double recv = 0.0;
  for (uint32_t e = vr->e0; e < vr->e1; e++) {
    const zr__rad_node *p = &rad->nodes[rad->elems[e].node];
    zr_vec3 d = zr_v3_sub(vs->centre, p->centre);
    double r2 = zr_v3_dot(d, d);
    if (!(r2 > 0.0))
      continue;
    recv += p->area * fabs(zr_v3_dot(d, p->normal)) / (sqrt(r2) * r2);
  }
  return src * recv;
}

/* The gap between the boxes of two clusters (0 when they meet): no
   point of one is closer to a point of the other. */
static double box_gap(const zr__rad_vol *a, const zr__rad_vol *b) {
  double g2 = 0.0;
  for (int k = 0; k < 3; k++) {
    double g = fmax(zr_v3_get(a->lo, k) - zr_v3_get(b->hi, k),
                    zr_v3_get(b->lo, k) - zr_v3_get(a->hi, k));
    if (g > 0.0)
      g2 += g * g;
  }
  return sqrt(g2);
}

/* Whether a link r <- s may stay between clusters: their boxes apart
   and its light (bound, then estimate) within the threshold. */
static bool is_leaf(const zr__rad_vol *v) { return v->child[0] < 0; }

/* A single surface may end a cluster link only where its sphere's
   radius is at most LEAF_ADMIT times the distance between the two
   clusters' centres: a surface is one element (or 16), its cosine and
   its visibility ray taken at its centre, and a large one near the
   other cluster is not lit (or seen) as its centre is.  In the 25-box
   furnace (test_radiosity_volume_clusters) the room's walls linked to
   the boxes this way, their visibility decided by one ray from the
   wall's centre in the boxes' own plane, and left the boxes' sides
   8% dark; with the rule they are within 0.2% of B = 2. */
#define LEAF_ADMIT 0.5

static bool vlink_keeps(const zr_radiosity *rad, const double *pre,
                        double thr, const zr__rad_vol *vr,
                        const zr__rad_vol *vs) {
  double d = box_gap(vr, vs);
  if (!(d > 0.0))
    return false;
  double dc = zr_v3_len(zr_v3_sub(vr->centre, vs->centre));
  if ((is_leaf(vr) && vr->radius > LEAF_ADMIT * dc) ||
      (is_leaf(vs) && vs->radius > LEAF_ADMIT * dc))
    return false;
  double power = pre[vs->e1] - pre[vs->e0];
  if (!(power * vr->area / (M_PI * d * d) > thr))
    return true;
  return !(vlink_estimate(rad, vr, vs) > thr);
}

/* Links receiver cluster r to source cluster s, or refines the link. */
static void refine_vlink(vol_refiner *w, int32_t r, int32_t s) {
  zr_radiosity *rad = w->rad;
  if (w->nomem)
    return;
  const zr__rad_vol *vr = &rad->vols[r], *vs = &rad->vols[s];
  if (is_leaf(vr) && is_leaf(vs)) {
    /* A planar surface cannot see itself (as link_all skips it). */
    if (r != s || !rad->surfs[vr->surf].geom.planar)
      pair_push(w->pairs, (uint32_t)vr->surf, (uint32_t)vs->surf);
    return;
  }
  if (r == s) {
    for (int i = 0; i < 2; i++)
      for (int j = 0; j < 2; j++)
        refine_vlink(w, vr->child[i], vr->child[j]);
    return;
  }
  if (vlink_keeps(rad, w->pre, w->thr, vr, vs)) {
    if (!vlink_push(rad, r, s))
      w->nomem = true;
    return;
  }
  /* Split the larger sphere's cluster (never a single surface). */
  bool split_r = !is_leaf(vr) && (is_leaf(vs) || vr->radius >= vs->radius);
  const zr__rad_vol *x = split_r ? vr : vs;
  int32_t c0 = x->child[0], c1 = x->child[1];
  if (split_r) {
    refine_vlink(w, c0, s);
    refine_vlink(w, c1, s);
  } else {
    refine_vlink(w, r, c0);
    refine_vlink(w, r, c1);
  }
}

static double threshold(const zr_radiosity *rad) {
  return rad->params.bf_eps * rad->power_ref;
}

zr_status zr__rad_vol_link(zr_radiosity *rad, zr__rad_pairs *pairs) {
  double *pre = cluster_power(rad);
  if (pre == NULL)
    return ZR_ENOMEM;
  vol_refiner w = {rad, pre, pairs, threshold(rad), false};
  refine_vlink(&w, 0, 0);
  free(pre);
  /* Meshes are paired with every surface, themselves included. */
  for (size_t m = 0; m < rad->n_surfs; m++) {
    if (!is_mesh(rad, m))
      continue;
    for (size_t s = 0; s < rad->n_surfs; s++) {
      pair_push(pairs, (uint32_t)m, (uint32_t)s);
      if (s != m)
        pair_push(pairs, (uint32_t)s, (uint32_t)m);
    }
  }
  return w.nomem || pairs->nomem ? ZR_ENOMEM : ZR_OK;
}

zr_status zr__rad_vol_refine(zr_radiosity *rad, zr__rad_pairs *pairs,
                             size_t *changed) {
  *changed = 0;
  double *pre = cluster_power(rad);
  if (pre == NULL)
    return ZR_ENOMEM;
  vol_refiner w = {rad, pre, pairs, threshold(rad), false};
  size_t n = rad->n_vlinks;
  for (size_t i = 0; i < n && !w.nomem; i++) {
    zr__rad_vlink *l = &rad->vlinks[i];
    if (l->dead)
      continue;
    const zr__rad_vol *vr = &rad->vols[l->recv], *vs = &rad->vols[l->src];
    if (vlink_keeps(rad, pre, w.thr, vr, vs))
      continue;
    /* refine_vlink would keep it: split it at once instead. */
    int32_t r = l->recv, s = l->src;
    l->dead = 1;
    free(l->w);
    l->w = NULL;
    (*changed)++;
    bool split_r = !is_leaf(vr) && (is_leaf(vs) || vr->radius >= vs->radius);
    const zr__rad_vol *x = split_r ? vr : vs;
    int32_t c0 = x->child[0], c1 = x->child[1];
    if (split_r) {
      refine_vlink(&w, c0, s);
      refine_vlink(&w, c1, s);
    } else {
      refine_vlink(&w, r, c0);
      refine_vlink(&w, r, c1);
    }
  }
  free(pre);
  /* Drop the split links (their weights are freed). */
  size_t k = 0;
  for (size_t i = 0; i < rad->n_vlinks; i++)
    if (!rad->vlinks[i].dead)
      rad->vlinks[k++] = rad->vlinks[i];
  rad->n_vlinks = k;
  return w.nomem || pairs->nomem ? ZR_ENOMEM : ZR_OK;
}

/* ---- weights ---- */

/* The stretch [*t0, *t1] of the segment x + t d, t in [0, 1], inside
   o's box, by slabs: *t0 is where it enters (0 when x is inside), *t1
   where it leaves (1 when it ends inside). */
static void box_stretch(const zr__rad_vol *o, zr_vec3 x, zr_vec3 d,
                        double *t0, double *t1) {
  double in = 0.0, out = 1.0;
  for (int k = 0; k < 3; k++) {
    double dk = zr_v3_get(d, k), xk = zr_v3_get(x, k);
    double lo = zr_v3_get(o->lo, k), hi = zr_v3_get(o->hi, k);
    if (dk == 0.0)
      continue;
    double a = (lo - xk) / dk, b = (hi - xk) / dk;
    in = fmax(in, fmin(a, b));
    out = fmin(out, fmax(a, b));
  }
  *t0 = fmin(in, 1.0);
  *t1 = fmax(out, 0.0);
}

/* Where the segment enters o's box (d ends at its centre). */
static double box_entry(const zr__rad_vol *o, zr_vec3 x, zr_vec3 d) {
  double t0, t1;
  box_stretch(o, x, d, &t0, &t1);
  return t0;
}

/* Where the segment leaves o's box (x inside). */
static double box_exit(const zr__rad_vol *o, zr_vec3 x, zr_vec3 d) {
  double t0, t1;
  box_stretch(o, x, d, &t0, &t1);
  return t1;
}

#define BETWEEN_RAYS 8

/* The visible fraction of the space between two clusters' boxes:
   BETWEEN_RAYS segments between element centres of the two, each the
   part outside both boxes. */
static double between_vis(const zr_radiosity *rad, const zr__rad_vol *vr,
                          const zr__rad_vol *vs, uint64_t *rays) {
  uint32_t ns = vs->e1 - vs->e0, nr = vr->e1 - vr->e0;
  if (ns == 0 || nr == 0)
    return 1.0;
  int open = 0, cast = 0;
  for (uint32_t i = 0; i < BETWEEN_RAYS; i++) {
    uint32_t a = vs->e0 + (uint32_t)((uint64_t)i * ns / BETWEEN_RAYS);
    uint32_t b = vr->e0 + (uint32_t)((uint64_t)((i * 5 + 3) % BETWEEN_RAYS) *
                                     nr / BETWEEN_RAYS);
    zr_vec3 q = rad->nodes[rad->elems[a].node].centre;
    zr_vec3 p = rad->nodes[rad->elems[b].node].centre;
    zr_vec3 d = zr_v3_sub(p, q);
    double t1 = box_exit(vs, q, d), t2 = box_entry(vr, q, d);
    cast++;
    if (!(t2 > t1)) {
      open++;
      continue;
    }
    (*rays)++;
    if (!zr__rad_occluded(rad, zr_v3_madd(q, d, t1), zr_v3_madd(q, d, t2)))
      open++;
  }
  return (double)open / cast;
}

/* The weights of one end's elements e0..e1 towards the other cluster o:
   at the source end (src) A cos V / pi, at the receiving end cos V /
   r^2, cos and r taken towards o's centre, V one ray towards it as far
   as the edge of v's own box (between_vis does the rest).  Returns the
   count written; the receiving end's weights are then scaled by
   between_vis. */
static uint32_t end_weights(const zr_radiosity *rad, const zr__rad_vol *v,
                            const zr__rad_vol *o, bool src,
                            zr__rad_vweight *out, uint64_t *rays) {
  double eps = 1e-7 * sqrt(rad->total_area);
  uint32_t n = 0;
  for (uint32_t e = v->e0; e < v->e1; e++) {
    const zr__rad_node *node = &rad->nodes[rad->elems[e].node];
    zr_vec3 d = zr_v3_sub(o->centre, node->centre);
    double r = zr_v3_len(d);
    double t = box_entry(o, node->centre, d);
    if (!(r > 0.0) || !(t > 0.0))
      continue;
    double c = zr_v3_dot(d, node->normal) / r;
    /* The side facing o: front for c > 0, back for c < 0. */
    uint32_t side = c < 0.0;
    c = fabs(c);
    if (!(c > 0.0))
      continue;
    zr_vec3 n_side = side ? zr_v3_neg(node->normal) : node->normal;
    zr_vec3 from = zr_v3_madd(node->centre, n_side, eps);
    zr_vec3 to = zr_v3_madd(node->centre, d, box_exit(v, node->centre, d));
    (*rays)++;
    if (zr__rad_occluded(rad, from, to))
      continue;
    double w = src ? node->area * c / M_PI : c / (r * r);
    out[n].elem = e;
    out[n].side = side;
    out[n].w = w;
    n++;
  }
  return n;
}

typedef struct vol_finisher {
  zr_radiosity *rad;
  const uint32_t *todo;
  uint64_t *rays; /* per link */
  bool *failed;   /* per link */
} vol_finisher;

static void finish_range(void *user, size_t begin, size_t end, int worker) {
  (void)worker;
  vol_finisher *f = user;
  zr_radiosity *rad = f->rad;
  for (size_t i = begin; i < end; i++) {
    zr__rad_vlink *l = &rad->vlinks[f->todo[i]];
    const zr__rad_vol *vr = &rad->vols[l->recv], *vs = &rad->vols[l->src];
    size_t cap = (size_t)(vs->e1 - vs->e0) + (vr->e1 - vr->e0);
    zr__rad_vweight *w = malloc((cap + 1) * sizeof *w);
    if (w == NULL) {
      f->failed[i] = true;
      continue;
    }
    uint64_t rays = 0;
    l->ns = end_weights(rad, vs, vr, true, w, &rays);
    l->nr = end_weights(rad, vr, vs, false, w + l->ns, &rays);
    double vb = between_vis(rad, vr, vs, &rays);
    for (uint32_t k = l->ns; k < l->ns + l->nr; k++)
      w[k].w *= vb;
    l->w = w;
    f->rays[i] = rays;
  }
}

zr_status zr__rad_vol_finish(zr_radiosity *rad) {
  size_t n = 0;
  for (size_t i = 0; i < rad->n_vlinks; i++)
    n += rad->vlinks[i].w == NULL;
  if (n == 0)
    return ZR_OK;
  uint32_t *todo = malloc(n * sizeof *todo);
  uint64_t *rays = calloc(n, sizeof *rays);
  bool *failed = calloc(n, sizeof *failed);
  zr_status st = todo && rays && failed ? ZR_OK : ZR_ENOMEM;
  if (st == ZR_OK) {
    size_t k = 0;
    for (size_t i = 0; i < rad->n_vlinks; i++)
      if (rad->vlinks[i].w == NULL)
        todo[k++] = (uint32_t)i;
    vol_finisher f = {rad, todo, rays, failed};
    zr__rad_parallel(rad->params.threads > 1 ? rad->params.threads : 1, n,
                     16, finish_range, &f);
    for (size_t i = 0; i < n; i++) {
      if (failed[i])
        st = ZR_ENOMEM;
      rad->vol_rays += rays[i];
      const zr__rad_vlink *l = &rad->vlinks[todo[i]];
      if (!failed[i] &&
          !zr__rad_charge(rad, (l->ns + l->nr) * sizeof *l->w))
        st = ZR_ENOMEM;
    }
  }
  free(todo);
  free(rays);
  free(failed);
  return st;
}

/* ---- gathering ---- */

void zr__rad_vol_gather(zr_radiosity *rad) {
  for (size_t e = 0; e < rad->n_elems; e++)
    memset(rad->elems[e].hc, 0, sizeof rad->elems[e].hc);
  for (size_t i = 0; i < rad->n_vlinks; i++) {
    const zr__rad_vlink *l = &rad->vlinks[i];
    if (l->dead || l->w == NULL)
      continue;
    double in[3] = {0, 0, 0}, f = 0.0;
    for (uint32_t k = 0; k < l->ns; k++) {
      const zr__rad_vweight *w = &l->w[k];
      const zr__rad_node *q = &rad->nodes[rad->elems[w->elem].node];
      for (int c = 0; c < 3; c++)
        in[c] += w->w * q->b[w->side][c];
      f += w->w;
    }
    if (!(f > 0.0))
      continue;
    for (uint32_t k = l->ns; k < l->ns + l->nr; k++) {
      const zr__rad_vweight *w = &l->w[k];
      zr__rad_elem *el = &rad->elems[w->elem];
      zr__rad_node *p = &rad->nodes[el->node];
      const double *rho = rad->surfs[p->surf].rho;
      for (int c = 0; c < 3; c++) {
        double h = w->w * in[c];
        p->hg[w->side][c] += h;
        p->bg[w->side][c] += rho[c] * h;
        el->hc[w->side][c] += h;
      }
      p->closure[w->side] += w->w * f;
    }
  }
}

void zr__rad_vol_incident(const zr_radiosity *rad, int32_t leaf, int side,
                          double h[3]) {
  for (int32_t a = leaf; a >= 0; a = rad->nodes[a].parent) {
    uint32_t e1 = rad->nodes[a].elem1;
    if (e1 == 0)
      continue;
    for (int c = 0; c < 3; c++)
      h[c] += rad->elems[e1 - 1].hc[side][c];
  }
}
