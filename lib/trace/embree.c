/*
 * embree.c - Embree 3 as the tracer's search for the triangles of a
 * mesh (configure --with-embree; issue 13).
 *
 * Each mesh (struct zr_mesh, shared by every object placed from it) gets
 * one Embree scene of one triangle geometry: its vertices in single
 * precision and its faces in the rows of the mesh's own hierarchy, so
 * Embree's primID is our face row.  Rays arrive in the mesh's own
 * coordinates, as they do to obj_mesh.c's hierarchy, and are handed to
 * rtcIntersect1 through Embree's public API only (rtcore.h and the
 * headers beside it).
 *
 * Embree answers in single precision, where a ray that meets a surface
 * finds it at a t that may differ from ours by some 1e-6 relative
 * (bench/embree.sh measured 6e-6 on the terrain), and 2 to 13 rays in
 * 512^2 hit in one tracer only.  The images must stay the built-in
 * tracer's, so Embree only names candidate triangles: an intersection
 * filter (rtcSetGeometryIntersectFilterFunction) runs our
 * double-precision test (zr__mesh_face_hit, Moller-Trumbore) on each
 * triangle Embree reports and rejects those it refuses or that lie
 * outside the caller's (tmin, tmax); t, u, v and hence the normal and
 * the surface coordinates are the built-in tracer's, bit for bit.  The
 * interval handed to Embree is widened by a slack that covers its
 * rounding (SLACK times the size of the coordinates over the length of
 * the direction), and the filter applies the exact one.
 *
 * Near an edge the two precisions may disagree on which side a ray
 * passes: Embree may name a triangle that our test finds just outside
 * (its neighbour, which our test would take, unnamed), or name one of
 * two neighbours that both meet the ray at the same t (where the
 * built-in search keeps the least face row).  So a candidate whose
 * barycentric coordinates come within EDGE of its border (scaled by the
 * size of the coordinates over the triangle's) makes the answer unsure,
 * and when that happens before the crossings kept, the ray is handed
 * back (-1) to the mesh's own hierarchy, which gives the built-in
 * answer.  What can still differ: a ray that grazes the outline of a
 * mesh, which Embree's single precision misses altogether.
 * tests/test_embree.c and tests/embree.sh bound what that does.
 *
 * For the nearest crossing the filter accepts every confirmed triangle,
 * so Embree shrinks the ray and prunes behind it, and keeps the least
 * (t, face) it saw, the built-in search's rule.  For the nearest two
 * (shadow rays, CSG, the normal of the winner) it keeps the two least
 * and rejects every triangle, so Embree goes on to all of them.
 *
 * The device is made with one build thread ("threads=1"): the tracer's
 * own threads call rtcIntersect1 on the committed scenes, which Embree
 * allows from any number of threads, and a build on one thread is the
 * same build whatever the number of ranks and threads.
 */
#include "trace/embree.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* Embree's t against ours, relative to the size of the coordinates
   over the length of the direction: single precision rounds at 6e-8,
   and bench/embree.sh found differences up to 6e-6 relative to t. */
#define SLACK 1e-4
/* How near the border of a triangle, in barycentric units for a
   triangle as large as the coordinates, a candidate makes the answer
   unsure: some 16 units of single precision's last place. */
#define EDGE 1e-6

struct zr_embree_mesh {
  RTCScene scene;
  double size; /* the largest absolute vertex coordinate */
};

struct zr_embree {
  RTCDevice device;
  struct zr_embree_mesh **meshes;
  size_t n_meshes, cap_meshes;
};

/* One query: Embree's context first, so the filter gets this back. */
typedef struct query {
  struct RTCIntersectContext rtc;
  const struct zr_mesh *mesh;
  zr_vec3 org, dir;
  double tmin, tmax;
  bool two; /* keep the nearest two and reject every triangle */
  int n;
  zr_mesh_raw_hit best[2];
  double size;   /* the mesh's largest coordinate, or the origin's */
  double unsure; /* the least t of a candidate near an edge */
} query;

static bool before(const zr_mesh_raw_hit *a, const zr_mesh_raw_hit *b) {
  return a->t < b->t || (a->t == b->t && a->face < b->face);
}

static void keep(query *q, const zr_mesh_raw_hit *h) {
  if (!q->two) {
    if (q->n == 0 || before(h, &q->best[0]))
      q->best[0] = *h;
    q->n = 1;
    return;
  }
  /* The same face may be reported more than once (Embree may visit it
     again); keep it once. */
  for (int i = 0; i < q->n; i++)
    if (q->best[i].face == h->face)
      return;
  if (q->n < 2) {
    q->best[q->n++] = *h;
  } else if (before(h, &q->best[1])) {
    q->best[1] = *h;
  } else {
    return;
  }
  if (q->n == 2 && before(&q->best[1], &q->best[0])) {
    zr_mesh_raw_hit t = q->best[0];
    q->best[0] = q->best[1];
    q->best[1] = t;
  }
}

/* The margin in barycentric units within which face f's border is
   unsure: EDGE times the size of the coordinates over the face's. */
static double edge_margin(const query *q, size_t f) {
  const struct zr_mesh *m = q->mesh;
  const uint32_t *idx = m->faces[f];
  zr_vec3 p0 = m->vertices[idx[0]];
  zr_vec3 n = zr_v3_cross(zr_v3_sub(m->vertices[idx[1]], p0),
                          zr_v3_sub(m->vertices[idx[2]], p0));
  double area = sqrt(zr_v3_dot(n, n));
  return area > 0.0 ? EDGE * q->size / sqrt(area) : INFINITY;
}

/* Marks the query unsure from t on when the crossing u, v with face f
   lies within the face's margin of its border, inside or out. */
static void check_edge(query *q, size_t f, double t, double u, double v) {
  if (!(t > q->tmin && t < q->tmax) || !(t < q->unsure))
    return;
  double e = edge_margin(q, f), w = 1.0 - u - v;
  if (u > -e && v > -e && w > -e && (u < e || v < e || w < e))
    q->unsure = t;
}

/* The intersection filter: N rays' hits in Embree's RTCHitN layout
   (rtcore_ray.h: primID is the sixth of its N-wide rows). */
static void confirm(const struct RTCFilterFunctionNArguments *args) {
  query *q = (query *)args->context;
  unsigned n = args->N;
  const unsigned *prim = (const unsigned *)args->hit + 5 * n;
  for (unsigned i = 0; i < n; i++) {
    if (!args->valid[i])
      continue;
    zr_mesh_raw_hit h;
    h.face = prim[i];
    if (h.face >= q->mesh->n_faces) {
      args->valid[i] = 0;
      continue;
    }
    if (!zr__mesh_face_hit(q->mesh, h.face, q->org, q->dir, &h.t, &h.u,
                           &h.v) ||
        !(h.t > q->tmin && h.t < q->tmax)) {
      /* Refused: perhaps just outside, where a neighbour Embree did not
         name would take the ray. */
      if (zr__mesh_face_plane(q->mesh, h.face, q->org, q->dir, &h.t, &h.u,
                              &h.v))
        check_edge(q, h.face, h.t, h.u, h.v);
      args->valid[i] = 0;
      continue;
    }
    check_edge(q, h.face, h.t, h.u, h.v);
    keep(q, &h);
    if (q->two)
      args->valid[i] = 0;
  }
}

static float round_down(double x) {
  float f = (float)x;
  return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

static float round_up(double x) {
  float f = (float)x;
  return (double)f < x ? nextafterf(f, INFINITY) : f;
}

/* Plain comparisons: fmax is a call into the C library (perf showed
   it), and NaN is refused by the callers' own tests. */
static double larger(double a, double b) { return a > b ? a : b; }

static double max_abs(zr_vec3 v) {
  return larger(fabs(v.x), larger(fabs(v.y), fabs(v.z)));
}

/* Asks Embree; false when the ray cannot be put in single precision
   (the caller then searches the built-in hierarchy). */
static bool run(query *q) {
  const struct zr_embree_mesh *e = q->mesh->accel;
  double len = sqrt(zr_v3_dot(q->dir, q->dir));
  double size = larger(e->size, max_abs(q->org));
  if (!(len > 0.0) || !isfinite(len) || !(size < 1e30) ||
      !(q->tmin >= 0.0) || q->tmax != q->tmax)
    return false;
  q->size = size;
  q->unsure = INFINITY;
  double slack = SLACK * size / len;
  double lo = q->tmin - slack - SLACK * q->tmin;
  double hi = q->tmax + slack + SLACK * q->tmax;
  struct RTCRayHit rh;
  rh.ray.org_x = (float)q->org.x;
  rh.ray.org_y = (float)q->org.y;
  rh.ray.org_z = (float)q->org.z;
  rh.ray.dir_x = (float)q->dir.x;
  rh.ray.dir_y = (float)q->dir.y;
  rh.ray.dir_z = (float)q->dir.z;
  rh.ray.tnear = lo > 0.0 ? round_down(lo) : 0.0f;
  rh.ray.tfar = isfinite(hi) && hi < 1e30 ? round_up(hi) : INFINITY;
  rh.ray.time = 0.0f;
  rh.ray.mask = UINT32_MAX;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcInitIntersectContext(&q->rtc);
  q->n = 0;
  rtcIntersect1(e->scene, &q->rtc, &rh);
  return true;
}

int zr__embree_nearest(const struct zr_mesh *m, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, zr_mesh_raw_hit *out) {
  query q = {.mesh = m, .org = org, .dir = dir, .tmin = tmin, .tmax = tmax};
  if (!run(&q))
    return -1;
  /* An unsure candidate at or before the crossing found, or with none
     found: the hierarchy decides. */
  if (q.unsure < INFINITY && (q.n == 0 || q.unsure <= q.best[0].t))
    return -1;
  if (q.n > 0)
    *out = q.best[0];
  return q.n;
}

int zr__embree_crossings(const struct zr_mesh *m, zr_vec3 org, zr_vec3 dir,
                         double tmin, double tmax, zr_mesh_raw_hit out[2]) {
  query q = {.mesh = m, .org = org, .dir = dir, .tmin = tmin, .tmax = tmax,
             .two = true};
  if (!run(&q))
    return -1;
  if (q.unsure < INFINITY && (q.n < 2 || q.unsure <= q.best[1].t))
    return -1;
  for (int i = 0; i < q.n; i++)
    out[i] = q.best[i];
  return q.n;
}

/* ---- building ---- */

static void embree_free(struct zr_embree *e) {
  if (!e)
    return;
  for (size_t i = 0; i < e->n_meshes; i++) {
    rtcReleaseScene(e->meshes[i]->scene);
    free(e->meshes[i]);
  }
  free(e->meshes);
  if (e->device)
    rtcReleaseDevice(e->device);
  free(e);
}

/* The Embree scene of one mesh; NULL when its vertices do not fit in
   single precision, Embree fails, or memory runs out. */
static struct zr_embree_mesh *build_mesh(RTCDevice dev,
                                         const struct zr_mesh *m) {
  double size = 0.0;
  for (size_t i = 0; i < m->n_vertices; i++) {
    double a = max_abs(m->vertices[i]);
    if (!(a < 1e30))
      return NULL;
    size = larger(size, a);
  }
  if (m->n_vertices > UINT32_MAX)
    return NULL;
  struct zr_embree_mesh *e = malloc(sizeof *e);
  RTCScene sc = rtcNewScene(dev);
  RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  float *vb = g ? rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                          RTC_FORMAT_FLOAT3,
                                          3 * sizeof(float), m->n_vertices)
                : NULL;
  unsigned *ib = g ? rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                             RTC_FORMAT_UINT3,
                                             3 * sizeof(unsigned),
                                             m->n_faces)
                   : NULL;
  if (!e || !sc || !vb || !ib) {
    if (g)
      rtcReleaseGeometry(g);
    if (sc)
      rtcReleaseScene(sc);
    free(e);
    return NULL;
  }
  for (size_t i = 0; i < m->n_vertices; i++) {
    vb[3 * i] = (float)m->vertices[i].x;
    vb[3 * i + 1] = (float)m->vertices[i].y;
    vb[3 * i + 2] = (float)m->vertices[i].z;
  }
  for (size_t f = 0; f < m->n_faces; f++)
    for (int k = 0; k < 3; k++)
      ib[3 * f + k] = m->faces[f][k];
  rtcSetGeometryIntersectFilterFunction(g, confirm);
  rtcCommitGeometry(g);
  rtcAttachGeometry(sc, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(sc);
  if (rtcGetDeviceError(dev) != RTC_ERROR_NONE) {
    rtcReleaseScene(sc);
    free(e);
    return NULL;
  }
  e->scene = sc;
  e->size = size;
  return e;
}

static zr_status add_mesh(struct zr_embree *e, const zr_object *o,
                          bool *failed) {
  struct zr_mesh *m = (struct zr_mesh *)o->u.mesh.data;
  if (m->accel || m->n_faces == 0)
    return ZR_OK;
  if (e->n_meshes == e->cap_meshes) {
    size_t cap = e->cap_meshes ? 2 * e->cap_meshes : 8;
    struct zr_embree_mesh **p = realloc(e->meshes, cap * sizeof *p);
    if (!p)
      return ZR_ENOMEM;
    e->meshes = p;
    e->cap_meshes = cap;
  }
  struct zr_embree_mesh *em = build_mesh(e->device, m);
  if (!em) {
    *failed = true;
    return ZR_OK;
  }
  e->meshes[e->n_meshes++] = em;
  /* Set once, before any ray: the scene is read-only while rendering. */
  m->accel = em;
  return ZR_OK;
}

static zr_status visit(struct zr_embree *e, const zr_object *o,
                       bool *failed) {
  if (o->kind == ZR_OBJ_MESH)
    return add_mesh(e, o, failed);
  if (!zr__is_csg(o->kind))
    return ZR_OK;
  for (size_t i = 0; i < o->u.csg.n_children; i++) {
    zr_status s = visit(e, o->u.csg.children[i], failed);
    if (s != ZR_OK)
      return s;
  }
  return ZR_OK;
}

static bool has_mesh(const zr_object *o) {
  if (o->kind == ZR_OBJ_MESH)
    return o->u.mesh.data->n_faces > 0;
  if (zr__is_csg(o->kind))
    for (size_t i = 0; i < o->u.csg.n_children; i++)
      if (has_mesh(o->u.csg.children[i]))
        return true;
  return false;
}

zr_status zr__embree_attach(zr_scene *scene, zr_context *ctx) {
  /* A scene finished without a context (the library's own tests) keeps
     the built-in hierarchy. */
  if (!ctx || ctx->accel != ZR_ACCEL_EMBREE || scene->embree)
    return ZR_OK;
  /* No device (and none of its start-up) for a scene without meshes. */
  bool any = false;
  for (size_t i = 0; i < scene->n_primitives && !any; i++)
    any = has_mesh(scene->primitives[i]);
  if (!any)
    return ZR_OK;
  struct zr_embree *e = calloc(1, sizeof *e);
  if (!e)
    return ZR_ENOMEM;
  e->device = rtcNewDevice("threads=1,verbose=0");
  bool failed = e->device == NULL;
  /* The filter is what keeps the built-in answers; a build without it,
     or that culls back faces, cannot serve. */
  if (!failed &&
      (!rtcGetDeviceProperty(e->device,
                             RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) ||
       rtcGetDeviceProperty(e->device,
                            RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED)))
    failed = true;
  zr_status s = ZR_OK;
  if (!failed)
    for (size_t i = 0; i < scene->n_primitives && s == ZR_OK; i++)
      s = visit(e, scene->primitives[i], &failed);
  scene->embree = e;
  scene->embree_free = embree_free;
  if (s != ZR_OK)
    return zr__diag(ctx, ZR_DIAG_ERROR, s, NULL,
                    "cannot build the meshes' Embree scenes: %s",
                    zr_status_str(s));
  if (failed)
    zr__diag(ctx, ZR_DIAG_WARNING, ZR_OK, NULL,
             "Embree could not take %s: %s traced by zRcube's own "
             "hierarchy",
             e->n_meshes ? "every mesh" : "the meshes",
             e->n_meshes ? "the others are" : "they are");
  return ZR_OK;
}
