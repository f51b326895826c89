/*
 * embree_spheres.c - issue 13's second Embree question: would Embree's
 * user geometry (our spheres, our double-precision test, Embree's
 * hierarchy and traversal) trace bench/peers.sh's sphereflake faster
 * than zRcube's own hierarchy?
 *
 *   embree_spheres SCENE.pov SIZE
 *
 * The scene's plain spheres (no transform, no clip) go into one Embree
 * user geometry: bounds rounded outward to single precision, and an
 * intersection callback that solves the sphere's quadratic in double
 * precision from the double ray kept beside Embree's context, as
 * lib/trace/bvh.c does for plain spheres.  Every other primitive (the
 * flake's plane) is left out of both sides: the camera rays of
 * bench/embree_probe.c are asked of zr__bvh_nearest over the spheres'
 * scene and of rtcIntersect1; times are best of three, one thread.
 * Printed: rays per second of each, and how many rays found another
 * nearest t.  Timings are printed, never asserted.  Built by
 * bench/embree.sh when it is given the flake (see there).
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "scene/scene.h"
#include "trace/bvh.h"

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct sphere {
  zr_vec3 c;
  double r;
} sphere;

typedef struct query {
  struct RTCIntersectContext rtc; /* first: Embree passes it back */
  zr_ray ray;
  double tmin, best;
} query;

static float down(double x) {
  float f = (float)x;
  return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

static float up(double x) {
  float f = (float)x;
  return (double)f < x ? nextafterf(f, INFINITY) : f;
}

static void bounds(const struct RTCBoundsFunctionArguments *a) {
  const sphere *s = (const sphere *)a->geometryUserPtr + a->primID;
  a->bounds_o->lower_x = down(s->c.x - s->r);
  a->bounds_o->lower_y = down(s->c.y - s->r);
  a->bounds_o->lower_z = down(s->c.z - s->r);
  a->bounds_o->upper_x = up(s->c.x + s->r);
  a->bounds_o->upper_y = up(s->c.y + s->r);
  a->bounds_o->upper_z = up(s->c.z + s->r);
}

/* The quadratic as lib/trace/bvh.c's sphere_t writes it. */
static void intersect(const struct RTCIntersectFunctionNArguments *a) {
  if (!a->valid[0])
    return;
  query *q = (query *)a->context;
  const sphere *s = (const sphere *)a->geometryUserPtr + a->primID;
  zr_vec3 oc = zr_v3_sub(q->ray.origin, s->c);
  double qa = zr_v3_dot(q->ray.dir, q->ray.dir);
  double qb = 2.0 * zr_v3_dot(q->ray.dir, oc);
  double qc = zr_v3_dot(oc, oc) - s->r * s->r;
  double disc = qb * qb - 4.0 * qa * qc;
  if (!(disc >= 0.0))
    return;
  double sq = sqrt(disc);
  double t0 = (-qb - sq) / (2.0 * qa), t1 = (-qb + sq) / (2.0 * qa);
  double t = t0 > q->tmin ? t0 : t1;
  if (!(t > q->tmin && t < q->best))
    return;
  q->best = t;
  struct RTCRayHit *rh = (struct RTCRayHit *)a->rayhit; /* N is 1 */
  rh->ray.tfar = up(t);
  rh->hit.primID = a->primID;
  rh->hit.geomID = a->geomID;
  rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rh->hit.u = rh->hit.v = 0.0f;
  rh->hit.Ng_x = rh->hit.Ng_y = 0.0f;
  rh->hit.Ng_z = 1.0f;
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: embree_spheres SCENE.pov SIZE\n");
    return 2;
  }
  int size = atoi(argv[2]);
  zr_context *ctx;
  zr_scene *s;
  if (zr_context_new(&ctx) != ZR_OK ||
      zr_scene_parse_file(ctx, argv[1], &s) != ZR_OK) {
    fprintf(stderr, "embree_spheres: cannot read %s\n", argv[1]);
    return 1;
  }
  /* The spheres alone, for both tracers. */
  sphere *sp = malloc(s->n_primitives * sizeof *sp);
  const zr_object **prims = malloc(s->n_primitives * sizeof *prims);
  size_t n = 0;
  for (size_t i = 0; i < s->n_primitives; i++) {
    const zr_object *o = s->primitives[i];
    if (o->kind != ZR_OBJ_SPHERE || o->transform || o->clip)
      continue;
    sp[n] = (sphere){o->u.sphere.centre, o->u.sphere.radius};
    prims[n++] = o;
  }
  const zr_object **all = s->primitives;
  size_t n_all = s->n_primitives;
  s->primitives = prims;
  s->n_primitives = n;
  double t0 = now();
  if (zr__bvh_build(s, ctx) != ZR_OK)
    return 1;
  double ours_build = now() - t0;

  t0 = now();
  RTCDevice dev = rtcNewDevice("threads=1");
  RTCScene sc = rtcNewScene(dev);
  RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(g, (unsigned)n);
  rtcSetGeometryUserData(g, sp);
  rtcSetGeometryBoundsFunction(g, bounds, sp);
  rtcSetGeometryIntersectFunction(g, intersect);
  rtcCommitGeometry(g);
  rtcAttachGeometry(sc, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(sc);
  double embree_build = now() - t0;

  /* The camera rays of bench/embree_probe.c. */
  zr_vec3 eye = s->camera.location, fwd = s->camera.direction;
  zr_vec3 right = s->camera.right, upv = s->camera.up;
  size_t nr = (size_t)size * (size_t)size;
  zr_ray *rays = malloc(nr * sizeof *rays);
  double *ta = malloc(nr * sizeof *ta), *tb = malloc(nr * sizeof *tb);
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) {
      double u = (x + 0.5) / size - 0.5, v = 0.5 - (y + 0.5) / size;
      zr_vec3 d = zr_v3_add(fwd, zr_v3_add(zr_v3_scale(right, u),
                                           zr_v3_scale(upv, v)));
      rays[(size_t)y * size + x] =
          (zr_ray){eye, zr_v3_scale(d, 1.0 / zr_v3_len(d))};
    }
  double ours = INFINITY, emb = INFINITY;
  for (int k = 0; k < 3; k++) {
    t0 = now();
    for (size_t i = 0; i < nr; i++) {
      zr_hit h;
      ta[i] = zr__bvh_nearest(s->bvh, &rays[i], 1e-6, INFINITY, &h)
                  ? h.t
                  : INFINITY;
    }
    double t = now() - t0;
    ours = t < ours ? t : ours;
    t0 = now();
    for (size_t i = 0; i < nr; i++) {
      query q;
      rtcInitIntersectContext(&q.rtc);
      q.ray = rays[i];
      q.tmin = 1e-6;
      q.best = INFINITY;
      struct RTCRayHit rh;
      rh.ray.org_x = (float)rays[i].origin.x;
      rh.ray.org_y = (float)rays[i].origin.y;
      rh.ray.org_z = (float)rays[i].origin.z;
      rh.ray.dir_x = (float)rays[i].dir.x;
      rh.ray.dir_y = (float)rays[i].dir.y;
      rh.ray.dir_z = (float)rays[i].dir.z;
      rh.ray.tnear = 0.0f;
      rh.ray.tfar = INFINITY;
      rh.ray.time = 0.0f;
      rh.ray.mask = 0xffffffffu;
      rh.ray.id = 0;
      rh.ray.flags = 0;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(sc, &q.rtc, &rh);
      tb[i] = q.best;
    }
    t = now() - t0;
    emb = t < emb ? t : emb;
  }
  size_t hits = 0, differ = 0;
  for (size_t i = 0; i < nr; i++) {
    hits += isfinite(ta[i]);
    /* Our quadratic here is the textbook one, bvh.c's the stable one
       (lib/trace/roots.c): a rounding apart. */
    differ += isfinite(ta[i]) != isfinite(tb[i]) ||
              (isfinite(ta[i]) && fabs(ta[i] - tb[i]) > 1e-9 * ta[i]);
  }
  printf("spheres: %zu; %d x %d camera rays, %zu hit\n", n, size, size, hits);
  printf("build s: zRcube BVH %.3f  Embree user geometry %.3f\n", ours_build,
         embree_build);
  printf("camera Mray/s: zRcube %.2f  Embree %.2f  ratio %.2f; %zu rays "
         "found another t (beyond 1e-9 relative)\n",
         nr / ours / 1e6, nr / emb / 1e6, ours / emb, differ);
  rtcReleaseScene(sc);
  rtcReleaseDevice(dev);
  s->primitives = all;
  s->n_primitives = n_all;
  free(prims);
  free(sp);
  free(rays);
  free(ta);
  free(tb);
  zr_scene_free(s);
  zr_context_free(ctx);
  return 0;
}
