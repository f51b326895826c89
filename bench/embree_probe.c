/*
 * embree_probe.c - zRcube's hierarchy against Embree 3 on one triangle
 * mesh, for issue 13's question: would Embree trace bench/peers.sh's
 * terrain (130,050 triangles) fast enough to be worth a dependency?
 *
 *   embree_probe SCENE.pov SIZE
 *
 * The scene's first primitive must be a mesh without a transform (the
 * terrain of bench/peers_gen.py).  Both tracers get the same rays, made
 * here: SIZE x SIZE camera rays through the scene camera's image plane, then one shadow ray
 * from each hit towards the first light.  zRcube answers with
 * zr__bvh_nearest (the tracer's call, normal included) and zr__bvh_all
 * stopping at the first crossing; Embree with rtcIntersect1 and
 * rtcOccluded1 on a single thread, its build included in its setup time
 * as our parse includes ours.  Printed: the build times, rays per second
 * of each, best of three, and how the answers agree (hits missed by
 * one tracer, the largest relative difference of t: Embree works in
 * single precision, so its pictures could not be our bytes).  Timings
 * are printed, never asserted.  Built by bench/embree.sh.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "scene/scene.h"
#include "scene/shapes.h"
#include "trace/bvh.h"

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct ray_set {
  size_t n;
  zr_ray *rays;
  double *t_ours, *t_embree; /* INFINITY: missed */
  zr_ray *shadow;            /* from each of our hits (dir 0: none) */
  int *blocked_ours, *blocked_embree;
} ray_set;

static zr_vec3 unit(zr_vec3 v) { return zr_v3_scale(v, 1.0 / zr_v3_len(v)); }

static void camera_rays(const zr_scene *s, int size, ray_set *rs) {
  /* The perspective camera's image plane ("Placing the Camera"):
     direction to its centre, right and up its full width and height. */
  zr_vec3 eye = s->camera.location, fwd = s->camera.direction;
  zr_vec3 right = s->camera.right, up = s->camera.up;
  rs->n = (size_t)size * (size_t)size;
  rs->rays = malloc(rs->n * sizeof *rs->rays);
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) {
      double u = ((x + 0.5) / size - 0.5), v = (0.5 - (y + 0.5) / size);
      zr_vec3 d = zr_v3_add(fwd, zr_v3_add(zr_v3_scale(right, u),
                                           zr_v3_scale(up, v)));
      rs->rays[(size_t)y * size + x] = (zr_ray){eye, unit(d)};
    }
}

static bool stop_at_first(const zr_hit *hit, void *user) {
  (void)hit;
  *(int *)user = 1;
  return false;
}

static double ours_primary(const zr_scene *s, ray_set *rs) {
  double t0 = now();
  for (size_t i = 0; i < rs->n; i++) {
    zr_hit h;
    rs->t_ours[i] = zr__bvh_nearest(s->bvh, &rs->rays[i], 1e-6, INFINITY, &h)
                        ? h.t
                        : INFINITY;
  }
  return now() - t0;
}

static double ours_shadow(const zr_scene *s, ray_set *rs) {
  double t0 = now();
  for (size_t i = 0; i < rs->n; i++) {
    rs->blocked_ours[i] = 0;
    if (rs->shadow[i].dir.x == 0 && rs->shadow[i].dir.y == 0 &&
        rs->shadow[i].dir.z == 0)
      continue;
    zr__bvh_all(s->bvh, &rs->shadow[i], 0.0, 1.0 - 1e-6, stop_at_first,
                &rs->blocked_ours[i]);
  }
  return now() - t0;
}

static double embree_primary(RTCScene sc, ray_set *rs) {
  struct RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  double t0 = now();
  for (size_t i = 0; i < rs->n; i++) {
    const zr_ray *r = &rs->rays[i];
    struct RTCRayHit rh;
    rh.ray.org_x = (float)r->origin.x;
    rh.ray.org_y = (float)r->origin.y;
    rh.ray.org_z = (float)r->origin.z;
    rh.ray.dir_x = (float)r->dir.x;
    rh.ray.dir_y = (float)r->dir.y;
    rh.ray.dir_z = (float)r->dir.z;
    rh.ray.tnear = 1e-6f;
    rh.ray.tfar = INFINITY;
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xffffffffu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(sc, &ctx, &rh);
    rs->t_embree[i] =
        rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar : INFINITY;
  }
  return now() - t0;
}

static double embree_shadow(RTCScene sc, ray_set *rs) {
  struct RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  double t0 = now();
  for (size_t i = 0; i < rs->n; i++) {
    const zr_ray *r = &rs->shadow[i];
    rs->blocked_embree[i] = 0;
    if (r->dir.x == 0 && r->dir.y == 0 && r->dir.z == 0)
      continue;
    struct RTCRay ray;
    ray.org_x = (float)r->origin.x;
    ray.org_y = (float)r->origin.y;
    ray.org_z = (float)r->origin.z;
    ray.dir_x = (float)r->dir.x;
    ray.dir_y = (float)r->dir.y;
    ray.dir_z = (float)r->dir.z;
    ray.tnear = 0.0f;
    ray.tfar = 1.0f - 1e-6f;
    ray.time = 0.0f;
    ray.mask = 0xffffffffu;
    ray.id = 0;
    ray.flags = 0;
    rtcOccluded1(sc, &ctx, &ray);
    rs->blocked_embree[i] = ray.tfar == -INFINITY;
  }
  return now() - t0;
}

static double best3(double (*f)(const zr_scene *, ray_set *),
                    const zr_scene *s, ray_set *rs) {
  double best = INFINITY;
  for (int k = 0; k < 3; k++) {
    double t = f(s, rs);
    best = t < best ? t : best;
  }
  return best;
}

static double best3e(double (*f)(RTCScene, ray_set *), RTCScene sc,
                     ray_set *rs) {
  double best = INFINITY;
  for (int k = 0; k < 3; k++) {
    double t = f(sc, rs);
    best = t < best ? t : best;
  }
  return best;
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: embree_probe SCENE.pov SIZE\n");
    return 2;
  }
  int size = atoi(argv[2]);
  zr_context *ctx;
  zr_scene *s;
  double t0 = now();
  if (zr_context_new(&ctx) != ZR_OK ||
      zr_scene_parse_file(ctx, argv[1], &s) != ZR_OK) {
    fprintf(stderr, "embree_probe: cannot read %s\n", argv[1]);
    return 1;
  }
  double parse = now() - t0;
  const zr_object *o = s->n_primitives > 0 ? s->primitives[0] : NULL;
  if (!o || o->kind != ZR_OBJ_MESH || o->transform || s->n_lights == 0) {
    fprintf(stderr, "embree_probe: the first primitive is not a plain "
                    "mesh, or there is no light\n");
    return 1;
  }
  const struct zr_mesh *m = o->u.mesh.data;

  t0 = now();
  RTCDevice dev = rtcNewDevice("threads=1");
  RTCScene sc = rtcNewScene(dev);
  RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  float *vb = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                      RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                      m->n_vertices);
  unsigned *ib = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                         RTC_FORMAT_UINT3,
                                         3 * sizeof(unsigned), m->n_faces);
  for (size_t i = 0; i < m->n_vertices; i++) {
    vb[3 * i] = (float)m->vertices[i].x;
    vb[3 * i + 1] = (float)m->vertices[i].y;
    vb[3 * i + 2] = (float)m->vertices[i].z;
  }
  for (size_t i = 0; i < m->n_faces; i++)
    for (int k = 0; k < 3; k++)
      ib[3 * i + k] = m->faces[i][k];
  rtcCommitGeometry(g);
  rtcAttachGeometry(sc, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(sc);
  double embree_build = now() - t0;

  ray_set rs;
  camera_rays(s, size, &rs);
  rs.t_ours = malloc(rs.n * sizeof(double));
  rs.t_embree = malloc(rs.n * sizeof(double));
  rs.shadow = calloc(rs.n, sizeof *rs.shadow);
  rs.blocked_ours = calloc(rs.n, sizeof(int));
  rs.blocked_embree = calloc(rs.n, sizeof(int));
  double ours_p = best3(ours_primary, s, &rs);
  double emb_p = best3e(embree_primary, sc, &rs);
  zr_vec3 light = s->lights[0].location;
  size_t hits = 0, missed_by_one = 0;
  double worst = 0.0;
  for (size_t i = 0; i < rs.n; i++) {
    bool a = isfinite(rs.t_ours[i]), b = isfinite(rs.t_embree[i]);
    missed_by_one += a != b;
    if (a && b) {
      double d = fabs(rs.t_ours[i] - rs.t_embree[i]) / rs.t_ours[i];
      worst = d > worst ? d : worst;
    }
    if (!a)
      continue;
    hits++;
    zr_vec3 p = zr_v3_madd(rs.rays[i].origin, rs.rays[i].dir, rs.t_ours[i]);
    /* Off the surface towards the eye, as a secondary ray leaves. */
    p = zr_v3_madd(p, rs.rays[i].dir, -1e-4);
    rs.shadow[i] = (zr_ray){p, zr_v3_sub(light, p)};
  }
  double ours_s = best3(ours_shadow, s, &rs);
  double emb_s = best3e(embree_shadow, sc, &rs);
  size_t blocked = 0, disagree = 0;
  for (size_t i = 0; i < rs.n; i++) {
    blocked += rs.blocked_ours[i] != 0;
    disagree += (rs.blocked_ours[i] != 0) != (rs.blocked_embree[i] != 0);
  }
  printf("mesh: %zu triangles, %zu vertices; %d x %d camera rays, %zu hit; "
         "%zu shadow rays, %zu blocked\n",
         m->n_faces, m->n_vertices, size, size, hits, hits, blocked);
  printf("build s:   zRcube parse+BVH %.3f   Embree (from our vertices) "
         "%.3f\n", parse, embree_build);
  printf("%-8s %12s %12s %8s\n", "rays", "zRcube_Mray/s", "Embree_Mray/s",
         "ratio");
  printf("%-8s %12.2f %12.2f %8.2f\n", "camera", rs.n / ours_p / 1e6,
         rs.n / emb_p / 1e6, ours_p / emb_p);
  printf("%-8s %12.2f %12.2f %8.2f\n", "shadow", hits / ours_s / 1e6,
         hits / emb_s / 1e6, ours_s / emb_s);
  printf("agreement: %zu camera rays hit in one only; largest relative t "
         "difference %.2e; %zu shadow answers differ\n",
         missed_by_one, worst, disagree);
  rtcReleaseScene(sc);
  rtcReleaseDevice(dev);
  zr_scene_free(s);
  zr_context_free(ctx);
  return 0;
}
