/*
 * warp.c - pattern warps (POV-Ray 3.7 reference manual, "Warps").
 *
 * A warp moves the point at which a pattern is evaluated.  POV-Ray keeps
 * a pattern's transforms and warps in one list in the order written and
 * takes an evaluation point through it from the last entry to the first,
 * so "warp { repeat x } scale 2" repeats every 2 units and "scale 2
 * warp { repeat x }" every unit.  We keep the transforms composed in one
 * matrix (the pigment's, normal's or texture's) and give each warp the
 * part of that matrix written before it (its frame F).  The point the
 * pattern sees is then reached by starting from the fully transformed
 * point and, for each warp from the last to the first, going forward to
 * its frame, warping, and coming back: p = F^-1 warp(F p).  The classic
 * turbulence keyword is not a warp here: POV-Ray puts it at the head of
 * the list, nearest the pattern, which is where lib/scene/pattern.c
 * applies it, after all of these.
 *
 *   - turbulence: p + t * dturbulence(p) ("Turbulence Warp").
 *   - repeat <d> offset <o> flip <f>: d has one non-zero component w on
 *     axis a; block b = floor(p[a] / w); p[a] -= b w; in odd blocks the
 *     flipped axes change sign (then p[a] += w if a itself flips); then
 *     p += b o ("Repeat Warp").
 *   - black_hole <c>, r: within r of the centre, d = p - c moves p by
 *     s d, s = min(1, ((r - |d|) / r)^falloff * strength), outwards with
 *     inverse; repeat <v> copies the hole every v (components under
 *     1e-10 do not repeat), turbulence <u> shifts each copy's centre by
 *     u times a per-block random number in [0, 1) ("Black Hole Warp").
 *     Our random numbers come from our own hash of the block, so the
 *     shifted holes are not where POV-Ray's are, only alike.
 *   - planar <n>, d; cylindrical, spherical, toroidal [major_radius R]
 *     with orientation <o> and dist_exp e ("Mapping using warps"): the
 *     point maps to (u, v, distance) as the manual's image maps do, u
 *     and v in [0, 1) (times distance^e when e is not 0), then goes
 *     along the orientation (see orient: the manual only says the
 *     mapped box stretches "along the orientation vector"; the map is
 *     POV-Ray 3.7's as measured).  A point on the axis (or at the
 *     centre) is left where it is.
 *
 * Coordinates are clamped to +-1e17 after the warps, which the manual
 * does not say but POV-Ray 3.7 does: a cylindrical warp with dist_exp
 * 20 under function { min(abs(x) * 1e-18, 1) } renders 0.1 at a
 * distance of 17.5, where u * distance^20 is about 4e24 (measured).
 */
#include "config.h"

#include <math.h>
#include <stdint.h>

#include "scene/pattern.h"
#include "scene/warp.h"

#define COORD_LIMIT 1.0e17
#define REPEAT_EPS 1.0e-10

void zr__warp_init(zr_warp *w, zr_warp_kind kind) {
  *w = (zr_warp){0};
  w->kind = kind;
  zr__transform_identity(&w->frame);
  w->octaves = 6;
  w->omega = 0.5;
  w->lambda = 2.0;
  w->axis = 0;
  w->width = 1;
  w->flip = zr_v3(1, 1, 1);
  w->radius = 1;
  w->strength = 1;
  w->falloff = 2;
  w->orientation = zr_v3(0, 0, 1);
  w->major_radius = 1;
}

static double *axis_of(zr_vec3 *v, int a) {
  return a == 0 ? &v->x : a == 1 ? &v->y : &v->z;
}

static zr_vec3 repeat(const zr_warp *w, zr_vec3 p) {
  double *pa = axis_of(&p, w->axis);
  /* The block number is kept in single precision, as POV-Ray 3.7's
     renders show: function { x / 2 } under repeat x is 0.75 at x =
     16777217.5, block 16777216 (measured), not 0.25. */
  float block = (float)floor(*pa / w->width);
  *pa -= block * w->width;
  if ((int)block & 1) {
    p = zr_v3_mul(p, w->flip);
    zr_vec3 f = w->flip;
    if (*axis_of(&f, w->axis) < 0)
      *pa += w->width;
  }
  return zr_v3_madd(p, w->offset, block);
}

/* A number in [0, 1) for a block of a repeated black hole. */
static double block_random(int bx, int by, int bz, int k) {
  uint64_t h = (uint64_t)(uint32_t)bx * 0x9E3779B97F4A7C15u;
  h ^= (uint64_t)(uint32_t)by * 0xC2B2AE3D27D4EB4Fu;
  h ^= (uint64_t)(uint32_t)bz * 0x165667B19E3779F9u;
  h += (uint64_t)k * 0x27D4EB2F165667C5u;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9u;
  h ^= h >> 29;
  return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

static int block_of(double x, double spacing) {
  return spacing >= REPEAT_EPS ? (int)floor(x / spacing) : 0;
}

static zr_vec3 black_hole(const zr_warp *w, zr_vec3 p) {
  zr_vec3 c = w->centre;
  zr_vec3 r = w->repeat;
  if (r.x != 0 || r.y != 0 || r.z != 0) {
    int bx = block_of(p.x, r.x), by = block_of(p.y, r.y),
        bz = block_of(p.z, r.z);
    zr_vec3 u = w->turbulence;
    c = zr_v3_add(c, zr_v3(u.x * block_random(bx, by, bz, 0),
                           u.y * block_random(bx, by, bz, 1),
                           u.z * block_random(bx, by, bz, 2)));
    c = zr_v3_add(c, zr_v3(r.x * bx, r.y * by, r.z * bz));
  }
  zr_vec3 d = zr_v3_sub(p, c);
  double len = sqrt(zr_v3_dot(d, d));
  if (len >= w->radius)
    return p;
  double s = pow((w->radius - len) / w->radius, w->falloff) * w->strength;
  if (s > 1)
    s = 1;
  return zr_v3_madd(p, d, w->inverse ? -s : s);
}

/* The angle about y from +x towards +z, as a fraction of a turn. */
static double turn_xz(double x, double z, double len) {
  double theta;
  if (z == 0)
    theta = x > 0 ? 0 : M_PI;
  else {
    theta = acos(x / len);
    if (z < 0)
      theta = 2 * M_PI - theta;
  }
  return theta / (2 * M_PI);
}

/*
 * The mapping warps' orientation step: (u, v, dist) becomes
 * u e_u + v e_v + dist e_d with, for the unit orientation o,
 *   e_u = (o.y + o.z, 0, -o.x), e_v = (0, o.x + o.z, o.y),
 *   e_d = (o.x, -o.y, o.z),
 * so <0,0,1> leaves the point as it is and <0,1,0> sends (u, v, dist)
 * to (u, -dist, v).  The manual gives no formula; this linear map is
 * POV-Ray 3.7's, measured with function pigments (0.5 + x / 50 and so
 * on, 16-bit linear output) under a spherical warp at five points for
 * each of the orientations x, y, <1,2,3>, <0.6,0.8,0> and <-1,0.5,0.2>:
 * every component within 0.0006 (the output's quantisation) of it.
 * It is not a rotation (e_u and e_v are not unit vectors in general).
 */
static zr_vec3 orient(const zr_warp *w, double u, double v, double dist) {
  zr_vec3 o = w->orientation;
  if (o.x == 0 && o.y == 0 && o.z == 1)
    return zr_v3(u, v, dist);
  zr_vec3 e_u = zr_v3(o.y + o.z, 0, -o.x);
  zr_vec3 e_v = zr_v3(0, o.x + o.z, o.y);
  zr_vec3 e_d = zr_v3(o.x, -o.y, o.z);
  return zr_v3_add(zr_v3_add(zr_v3_scale(e_u, u), zr_v3_scale(e_v, v)),
                   zr_v3_scale(e_d, dist));
}

static double dist_scale(double len, double e) {
  return e == 1 ? len : e != 0 ? pow(len, e) : 1;
}

static zr_vec3 cylindrical(const zr_warp *w, zr_vec3 p) {
  double len = sqrt(p.x * p.x + p.z * p.z);
  if (len == 0)
    return p;
  double u = turn_xz(p.x, p.z, len) * dist_scale(len, w->dist_exp);
  return orient(w, u, p.y, len);
}

static zr_vec3 spherical(const zr_warp *w, zr_vec3 p) {
  double dist = sqrt(zr_v3_dot(p, p));
  if (dist == 0)
    return p;
  double x = p.x / dist, y = p.y / dist, z = p.z / dist;
  double v = 0.5 + asin(y) / M_PI;
  double len = sqrt(x * x + z * z);
  double u = len == 0 ? 0 : turn_xz(x, z, len);
  double k = dist_scale(dist, w->dist_exp);
  return orient(w, u * k, v * k, dist);
}

static zr_vec3 toroidal(const zr_warp *w, zr_vec3 p) {
  double len = sqrt(p.x * p.x + p.z * p.z);
  if (len == 0)
    return p;
  double u = turn_xz(p.x, p.z, len);
  double x = len - w->major_radius;
  double minor = sqrt(x * x + p.y * p.y);
  double phi = minor == 0 ? 0 : acos(-x / minor);
  if (p.y > 0)
    phi = 2 * M_PI - phi;
  double v = phi / (2 * M_PI);
  double k = dist_scale(minor, w->dist_exp);
  return orient(w, u * k, v * k, minor);
}

zr_vec3 zr__warp_apply(const zr_warp *w, zr_vec3 p) {
  switch (w->kind) {
  case ZR_WARP_TURBULENCE:
    return zr_v3_add(p, zr_v3_mul(w->turbulence,
                                  zr__dturbulence(p, w->octaves, w->omega,
                                                  w->lambda)));
  case ZR_WARP_REPEAT:
    return repeat(w, p);
  case ZR_WARP_BLACK_HOLE:
    return black_hole(w, p);
  case ZR_WARP_PLANAR:
    return orient(w, p.x, p.y, w->distance);
  case ZR_WARP_CYLINDRICAL:
    return cylindrical(w, p);
  case ZR_WARP_SPHERICAL:
    return spherical(w, p);
  case ZR_WARP_TOROIDAL:
    return toroidal(w, p);
  }
  return p;
}

static double clamp_coord(double v) {
  return v > COORD_LIMIT ? COORD_LIMIT : v < -COORD_LIMIT ? -COORD_LIMIT : v;
}

zr_vec3 zr__warp_point(const zr_warp *warps, int n, zr_vec3 p) {
  for (int i = n - 1; i >= 0; i--) {
    const zr_warp *w = &warps[i];
    p = zr__xform_point(w->frame.m, p);
    p = zr__warp_apply(w, p);
    p = zr__xform_point(w->frame.inv, p);
  }
  return zr_v3(clamp_coord(p.x), clamp_coord(p.y), clamp_coord(p.z));
}
