/*
 * trim.c - CSG trimming of radiosity surfaces: the parts of an
 * intersection, difference or merge take part in radiosity only where
 * they are the solid's surface (POV-Ray 3.7 reference, "Constructive
 * Solid Geometry"; the tracer's lib/trace/csg.c keeps a crossing by the
 * same rules).
 *
 * A part's exact surface is built whole (mesh.c) and every cell of its
 * quadtree records the fraction of its area that survives, from inside
 * tests at a grid of points (kept, in quadtree.c's cell geometry); its
 * area is that part's area.  A cell wholly removed gets area 0 and no
 * links (refine.c), one straddling the trim is split down to A_eps
 * before linking (zr__rad_trim_split), and a link's factor counts only
 * its source's kept fraction, so removed area neither emits nor
 * receives.  A point p of part L survives when, at every CSG node above
 * L, the node's other children decide so: an intersection keeps p where
 * every other child contains it (a difference is an intersection with
 * the later children inverted), a merge where none does, a union
 * always; and where every clipped_by on the way contains it.  A
 * polygon is trimmed the same way, its rectangle to the polygon.
 */
#include "radiosity/radiosity.h"

#include "trace/intersect.h"
#include "trace/obj_shapes.h"

/* 1 kept, 0 removed, -1 when leaf is not under node. */
static int keeps_under(const zr_object *node, const zr_object *leaf,
                       zr_vec3 p) {
  if (node == leaf) {
    /* A polygon's surface is the rectangle around it (mesh.c), trimmed
       to the polygon here. */
    if (leaf->kind == ZR_OBJ_POLYGON &&
        !zr__polygon_covers(leaf, leaf->transform
                                      ? zr__xform_point(
                                            leaf->transform->inv, p)
                                      : p))
      return 0;
    return leaf->clip == NULL || zr__inside(leaf->clip, p);
  }
  if (!zr__is_csg(node->kind))
    return -1;
  for (size_t i = 0; i < node->u.csg.n_children; i++) {
    int r = keeps_under(node->u.csg.children[i], leaf, p);
    if (r < 0)
      continue;
    if (r == 0)
      return 0;
    if (node->kind != ZR_OBJ_UNION) {
      bool want_inside = node->kind == ZR_OBJ_INTERSECTION;
      for (size_t j = 0; j < node->u.csg.n_children; j++)
        if (j != i && zr__inside(node->u.csg.children[j], p) != want_inside)
          return 0;
    }
    return node->clip == NULL || zr__inside(node->clip, p);
  }
  return -1;
}

bool zr__rad_trim_keeps(const zr__rad_surface *s, zr_vec3 p) {
  return s->trim == NULL || keeps_under(s->trim, s->object, p) != 0;
}

double zr__rad_trim_fraction(const zr_radiosity *rad, const zr__rad_surface *s,
                             const double cell[4], int n) {
  (void)rad;
  if (s->trim == NULL)
    return 1.0;
  double kept = 0.0, all = 0.0;
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      zr__surface_point pt;
      zr__surface_eval(&s->geom, cell[0] + (i + 0.5) / n * (cell[1] - cell[0]),
                       cell[2] + (j + 0.5) / n * (cell[3] - cell[2]), &pt);
      all += pt.da;
      if (zr__rad_trim_keeps(s, pt.p))
        kept += pt.da;
    }
  /* A collapsed edge (a pole) has da 0 at every sample of a tiny cell:
     count the samples then. */
  if (!(all > 0.0)) {
    int in = 0;
    for (int k = 0; k < n * n; k++) {
      zr__surface_point pt;
      zr__surface_eval(&s->geom,
                       cell[0] + (k % n + 0.5) / n * (cell[1] - cell[0]),
                       cell[2] + (k / n + 0.5) / n * (cell[3] - cell[2]), &pt);
      in += zr__rad_trim_keeps(s, pt.p);
    }
    return (double)in / (n * n);
  }
  return kept / all;
}

static zr_status split_straddling(zr_radiosity *rad, int32_t n) {
  const zr__rad_node *node = &rad->nodes[n];
  if (!(node->kept > 0.0 && node->kept < 1.0) ||
      !(node->area > rad->area_eps_abs) || node->depth >= ZR__RAD_DEPTH)
    return ZR_OK;
  if (!zr__rad_subdivide(rad, n))
    return ZR_ENOMEM;
  int32_t first = rad->nodes[n].child;
  for (int k = 0; k < 4; k++) {
    zr_status st = split_straddling(rad, first + k);
    if (st != ZR_OK)
      return st;
  }
  return ZR_OK;
}

/* Leaves only: a curved surface starts split, and its leaves are what
   straddles. */
static zr_status split_leaves(zr_radiosity *rad, int32_t n) {
  if (rad->nodes[n].child < 0)
    return split_straddling(rad, n);
  int32_t first = rad->nodes[n].child;
  for (int k = 0; k < 4; k++) {
    zr_status st = split_leaves(rad, first + k);
    if (st != ZR_OK)
      return st;
  }
  return ZR_OK;
}

zr_status zr__rad_trim_split(zr_radiosity *rad) {
  for (size_t s = 0; s < rad->n_surfs; s++) {
    if (rad->surfs[s].trim == NULL)
      continue;
    zr_status st = split_leaves(rad, rad->surfs[s].root);
    if (st != ZR_OK)
      return st;
  }
  return ZR_OK;
}
