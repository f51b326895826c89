/*
 * cluster.c - form factors of links that end at a cluster of a mesh's
 * faces.
 *
 * A mesh is one surface whose quadtree groups its faces (surface.c,
 * "meshes"): a cell above the faces' level is a cluster, and a link may
 * join it as a whole, which keeps the initial linking of a large mesh
 * from growing with the square of its faces (Smits, Arvo and Greenberg,
 * "A Clustering Algorithm for Radiosity in Complex Environments",
 * SIGGRAPH 1994, do the same with volume clusters).  Refinement splits a
 * cluster link like any other while the light it may carry exceeds
 * BF_eps, down to the faces and below them, where the exact polygon
 * factors of refine.c take over.
 *
 * A cluster's faces face many ways, so the sides of a cluster link are
 * per face: side 0 of a cluster is the front of each of its faces, side
 * 1 their backs.  The factor from a point to a cluster is the sum of the
 * exact point-to-triangle factors (Lambert's contour formula) of the
 * faces that show the link's side to the point; a cluster receiver is
 * sampled at its faces' centroids, weighted by their areas (a face's own
 * plane holds its centroid, so a face sends nothing to itself).  Faces
 * of one cluster that hide each other are the visibility estimate's
 * business (refine.c), as for any link.
 *
 * Clusters send as a whole but receive as their faces: refinement
 * splits a cluster at the receiving end of a link (refine.c), since
 * handing a cluster's mean factor to each of its faces lights faces
 * that turn away from the source as much as those that face it (per
 * face the factors then summed to 2.7 in a room, and with rho 0.5 the
 * solution diverged).  What remains approximate is a source cluster's
 * mean radiosity, which BF refinement bounds as for any source cell.
 * To bound the work of a link, receiver points times source faces are
 * kept near CLUSTER_BUDGET: first one receiver point, then every n-th
 * source face standing for its neighbours.
 */
#include "radiosity/radiosity.h"

#include "radiosity/formfactor.h"

#define CLUSTER_BUDGET 4096

bool zr__rad_cluster(const zr_radiosity *rad, const zr__rad_node *node,
                     size_t *f0, size_t *f1) {
  double cell[4];
  size_t a, b;
  zr__rad_node_cell(node, cell);
  bool c = zr__surface_mesh_cluster(&rad->surfs[node->surf].geom, cell, &a,
                                    &b);
  if (f0 != NULL)
    *f0 = a;
  if (f1 != NULL)
    *f1 = b;
  return c;
}

bool zr__rad_mixed_cluster(const zr_radiosity *rad,
                           const zr__rad_node *node) {
  return node->spread > 1e-9 && zr__rad_cluster(rad, node, NULL, NULL);
}

/*
 * The factor from p, n to one face.  A face far from p (r^2 at least
 * FAR_RATIO times its area) is taken as a differential area at its
 * centroid, A cos cos / (pi r^2): against the exact disc of the same
 * area seen head-on, A / (pi r^2 + A), it is high by the factor
 * 1 + A / (pi r^2), at most 1 + 1 / (pi FAR_RATIO) = 1.005; the cosines
 * at the centroid stand for the face's, which turn by at most its
 * angular size, sqrt(A) / r < 0.13 radians.  Near faces keep the exact
 * contour integral.  Most faces of a cluster link are far (it is made
 * only between cells far apart), and the differential term costs no
 * arc tangents: at 100k faces this was most of a solve.
 */
#define FAR_RATIO 64.0

static double face_factor(const zr__mesh_face *tri, zr_vec3 p, zr_vec3 n) {
  zr_vec3 g = zr_v3_scale(zr_v3_add(zr_v3_add(tri->p[0], tri->p[1]),
                                    tri->p[2]),
                          1.0 / 3.0);
  zr_vec3 d = zr_v3_sub(g, p);
  double r2 = zr_v3_dot(d, d);
  if (!(r2 >= FAR_RATIO * tri->area))
    return zr__ff_point_polygon(p, n, tri->p, 3);
  double cp = zr_v3_dot(d, n), cq = fabs(zr_v3_dot(d, tri->n));
  if (!(cp > 0.0))
    return 0.0;
  /* cp and cq are cosines times r: r^4 under the fraction. */
  return tri->area * cp * cq / (M_PI * r2 * r2);
}

/* The factor from p, n to every stride-th face of cluster q that shows
   side sside, times stride (an estimate of the sum when stride > 1). */
static double point_factor_strided(const zr_radiosity *rad,
                                   const zr__rad_node *q, int sside,
                                   zr_vec3 p, zr_vec3 n, size_t stride) {
  const zr__surface *g = &rad->surfs[q->surf].geom;
  size_t f0, f1;
  zr__rad_cluster(rad, q, &f0, &f1);
  double sum = 0.0;
  zr__mesh_face tri;
  /* Start mid-stride so thinned samples spread over the cluster. */
  for (size_t f = f0 + (stride - 1) / 2; f < f1; f += stride) {
    if (!zr__surface_mesh_tri(g, f, &tri))
      continue;
    double h = zr_v3_dot(zr_v3_sub(p, tri.p[0]), tri.n);
    if (h == 0.0 || (h < 0.0) != (sside == 1))
      continue;
    sum += face_factor(&tri, p, n);
  }
  return fmin(sum * (double)stride, 1.0);
}

double zr__rad_cluster_point_factor(const zr_radiosity *rad,
                                    const zr__rad_node *q, int sside,
                                    zr_vec3 p, zr_vec3 n) {
  return point_factor_strided(rad, q, sside, p, n, 1);
}

/* The source end of a cluster link, as each receiver point sees it. */
typedef struct cluster_source {
  const zr_radiosity *rad;
  const zr__rad_node *q;
  int sside;
  size_t stride; /* of the faces of a cluster source */
  bool cluster, planar;
  zr_vec3 poly[4 * ZR__FF_MAX_SEGS];
  size_t nv;
  zr_vec3 plane_p, plane_n; /* a planar source's plane */
} cluster_source;

static double source_factor(const cluster_source *src, zr_vec3 p,
                            zr_vec3 n) {
  if (src->cluster)
    return point_factor_strided(src->rad, src->q, src->sside, p, n,
                                src->stride);
  if (src->planar) {
    /* Only the side of the plane the link joins sends light. */
    double h = zr_v3_dot(zr_v3_sub(p, src->plane_p), src->plane_n);
    if (h == 0.0 || (h < 0.0) != (src->sside == 1))
      return 0.0;
  }
  return zr__ff_point_polygon(p, n, src->poly, src->nv);
}

typedef struct receiver_sum {
  const cluster_source *src;
  double side;
  double flux, area;
} receiver_sum;

static void add_receiver_point(const zr__surface_point *pt, double weight,
                               void *user) {
  receiver_sum *r = user;
  zr_vec3 n = zr_v3_scale(pt->n, r->side);
  r->flux += weight * source_factor(r->src, pt->p, n);
  r->area += weight;
}

double zr__rad_cluster_link_factor(const zr_radiosity *rad,
                                   const zr__rad_node *p, int rside,
                                   const zr__rad_node *q, int sside) {
  cluster_source src;
  size_t q0, q1, p0, p1;
  src.rad = rad;
  src.q = q;
  src.sside = sside;
  src.cluster = zr__rad_cluster(rad, q, &q0, &q1);
  src.planar = false;
  src.nv = 0;
  src.stride = 1;
  size_t cost = 1;
  if (src.cluster) {
    cost = q1 - q0 + 1;
    /* More faces than the budget: every stride-th face stands for its
       neighbours, which lie close by (surface.c orders them). */
    src.stride = cost / CLUSTER_BUDGET + 1;
    cost = (cost + src.stride - 1) / src.stride;
  } else {
    const zr__surface *gq = &rad->surfs[q->surf].geom;
    double sc[4];
    zr__rad_node_cell(q, sc);
    src.nv = zr__surface_patch_polygon(gq, sc[0], sc[1], sc[2], sc[3], 16,
                                       src.poly, 4 * ZR__FF_MAX_SEGS);
    src.planar = gq->planar || gq->kind == ZR__SURFACE_MESH;
    src.plane_p = q->centre;
    src.plane_n = q->normal;
  }
  receiver_sum r = {&src, rside ? -1.0 : 1.0, 0.0, 0.0};
  const zr__surface *gp = &rad->surfs[p->surf].geom;
  if (zr__rad_cluster(rad, p, &p0, &p1)) {
    size_t stride = (p1 - p0) * cost / CLUSTER_BUDGET + 1;
    zr__mesh_face tri;
    for (size_t f = p0; f < p1; f += stride) {
      if (!zr__surface_mesh_tri(gp, f, &tri))
        continue;
      zr__surface_point pt;
      pt.p = zr_v3_scale(zr_v3_add(zr_v3_add(tri.p[0], tri.p[1]), tri.p[2]),
                         1.0 / 3.0);
      pt.n = tri.n;
      pt.da = 0.0;
      add_receiver_point(&pt, tri.area, &r);
    }
  } else if (cost * (size_t)(rad->rule_recv.n * rad->rule_recv.n) >
             CLUSTER_BUDGET) {
    /* A face against a large cluster, far from most of its faces: the
       receiver's centre stands for it. */
    zr__surface_point pt;
    zr__surface_eval(gp, 0.5 * (p->iu + p->iu + (ZR__RAD_GRID >> p->depth)) /
                             ZR__RAD_GRID,
                     0.5 * (p->iv + p->iv + (ZR__RAD_GRID >> p->depth)) /
                         ZR__RAD_GRID,
                     &pt);
    add_receiver_point(&pt, 1.0, &r);
  } else {
    double rc[4];
    zr__rad_node_cell(p, rc);
    zr__surface_quadrature(gp, rc[0], rc[1], rc[2], rc[3], 1, &rad->rule_recv,
                           add_receiver_point, &r);
  }
  return r.area > 0.0 ? fmin(1.0, r.flux / r.area) : 0.0;
}
