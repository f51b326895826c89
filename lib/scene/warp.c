/*
 * warp.c - pattern warps (POV-Ray 3.7 reference manual, "Warp" and the
 * sections under it).
 *
 * A warp moves the point at which a pattern is evaluated.  The manual
 * says that warps and transforms act "in the order in which you specify
 * them"; measured (bench/warp_probe.sh, lines frame_before and
 * frame_after), the point is taken through the list from the last
 * entry back to the first, as through an object's inverse transforms:
 * with "scale 2 warp { repeat x }" world x = 1.5 repeats to 0.5 and is
 * then halved (0.25); with "warp { repeat x } scale 2" it is halved to
 * 0.75 and that repeats to itself.  The transforms stay composed in one
 * matrix (the pigment's, normal's or texture's); each warp keeps the
 * part of it written before the warp (its frame F), so the pattern
 * sees, for each warp from the last to the first, p <- F^-1 warp(F p).
 * The plain turbulence keyword is not in this list: the manual applies
 * it first, whatever its place, which lib/scene/pattern.c does.
 *
 * Every rule below that the manual leaves open was measured with
 * bench/warp_probe.sh, which prints, for POV-Ray 3.7 or zrcube, the
 * warped point of each probe point as three function patterns see it;
 * the comments cite its lines by their case name (the first word).
 * tests/test_warp.c checks these values and tests/test_warp_probe.sh
 * compares the two renderers line by line when POV-Ray is installed.
 */
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "scene/pattern.h"
#include "scene/warp.h"

/*
 * The largest coordinate a pattern is given: each of x, y and z is cut
 * to [-1e17, 1e17].  Measured (warp_probe.sh, far, far_fine, far_in,
 * far_exp): offsets of 1e14 per block reach 9.99e16 unchanged in block
 * 999 and stop at 1e17 from block 1000 on; 2e17, -3e17 and 4e17 come
 * back as +-1e17 even where the warp leaves them alone.  POV-Ray cuts
 * them without any warp too (far_nowarp: a function pattern at
 * y = 2e17 reads 1e17), which lib/scene/pattern.c does with
 * zr__warp_cut.
 */
#define PATTERN_COORD_MAX 1e17

/* Black hole repeat components below this are "do not repeat" (the
   manual: 0 means no repeat; this also keeps floor(x / r) finite). */
#define HOLE_NO_REPEAT 1e-10

void zr__warp_init(zr_warp *w, zr_warp_kind kind) {
  *w = (zr_warp){0};
  w->kind = kind;
  zr__transform_identity(&w->frame);
  /* The manual's defaults: "Default values for pattern modifiers" and
     "Mapping using warps". */
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

static void set_axis(zr_vec3 *v, int axis, double value) {
  if (axis == 0)
    v->x = value;
  else if (axis == 1)
    v->y = value;
  else
    v->z = value;
}

/*
 * repeat <w along one axis> offset <o> flip <f> ("Repeat Warp").  The
 * manual: copy n (counted from 0 at the origin, the copy between 0 and
 * w) shows the slice of the first copy moved by n o, every other copy
 * mirrored on the flipped axes, "the first copy in the positive
 * direction" not flipped.  Measured (warp_probe.sh, repeat*):
 *   - n = floor(p / w) also for negative p and negative w (repeat -2*y
 *     sends y = 0.5 to -1.5, y = 2.5 to -1.5, y = -0.5 to itself), and
 *     the point moves by -n w along the axis;
 *   - copies with odd n are the mirrored ones, on both sides of 0
 *     (n = 1, -1 flip; 2, -2 do not);
 *   - a flipped axis other than the repeat axis changes sign; the
 *     repeat axis itself is mirrored within the copy, local -> w - local
 *     (repeat 2*x flip x: 2.5 and -1.5 read 1.5);
 *   - the offset is added after the mirroring (repeat_flip_offset:
 *     2.5 reads <1.6, -0.05, 0.425>, -1.5 reads <1.4, -0.45, -0.175>).
 * Far from the origin the copy number is exact here: POV-Ray rounds it
 * beyond 2^24 copies (repeat_far: x = 16777217.5 reads 1.5 there, 0.5
 * here), which no scene can see.
 */
static zr_vec3 repeat(const zr_warp *w, zr_vec3 p) {
  double along = zr_v3_get(p, w->axis);
  double copy = floor(along / w->width);
  double local = along - copy * w->width;
  if (fmod(copy, 2.0) != 0.0) {
    zr_vec3 sign = w->flip;
    p = zr_v3_mul(p, sign);
    if (zr_v3_get(sign, w->axis) < 0)
      local = w->width - local;
  }
  set_axis(&p, w->axis, local);
  return zr_v3_madd(p, w->offset, copy);
}

/* A number in [0, 1) for one axis of one block of a repeated black
   hole: a 64-bit mix of the block's indices (the finaliser of
   Steele, Lea and Flood's SplitMix64, "Fast splittable pseudorandom
   number generators", OOPSLA 2014).  The manual asks only for "a
   different random amount ranging from 0 to 1" per axis, the same in
   every render; POV-Ray's own numbers are not matched. */
static double hole_random(const int64_t block[3], int axis) {
  uint64_t h = 0x6A09E667F3BCC909u + (uint64_t)axis;
  for (int k = 0; k < 3; k++) {
    h ^= (uint64_t)block[k] + 0x9E3779B97F4A7C15u + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9u;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBu;
    h ^= h >> 31;
  }
  return (double)(h >> 11) * 0x1p-53;
}

/*
 * black_hole <c>, r ("Black Hole Warp").  From the manual: the
 * closeness k = (r - |d|) / r of a point at d = p - c within the
 * sphere, the force k^falloff times strength, the move "clipped to a
 * maximum of the original distance from the center", inverse pushing
 * the other way; with repeat, c is an offset into each block of the
 * given size (sizes are fitted when the warp is read,
 * lib/sdl/build_warp.c) and turbulence moves each block's centre by
 * the turbulence times a random amount in [0, 1) per axis.  Measured
 * (warp_probe.sh, hole*): the pattern point moves away from the centre
 * by the force times d (black_hole <1,0,0>, 2 sends x = 1.5 to
 * 1.78125, force 0.5625), so the pattern is drawn in; inverse moves it
 * towards the centre (0.25 -> 0.109375); a force of 1 or more moves it
 * by exactly d (strength 3: 0.1 -> 0.2; inverse strength 4: 0.25 -> 0).
 */
static zr_vec3 black_hole(const zr_warp *w, zr_vec3 p) {
  zr_vec3 centre = w->centre;
  const zr_vec3 size = w->repeat;
  if (size.x != 0 || size.y != 0 || size.z != 0) {
    double pc[3] = {p.x, p.y, p.z};
    double sc[3] = {size.x, size.y, size.z};
    double jitter[3] = {w->turbulence.x, w->turbulence.y, w->turbulence.z};
    double shift[3] = {0, 0, 0};
    int64_t block[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
      if (!(sc[k] >= HOLE_NO_REPEAT))
        continue;
      /* Far out (or not a number) the block index is held to 2^62, so
         that it converts to an integer. */
      double b = floor(pc[k] / sc[k]);
      block[k] = (int64_t)(fabs(b) < 0x1p62 ? b : copysign(0x1p62, b));
    }
    for (int k = 0; k < 3; k++)
      shift[k] = (double)block[k] * sc[k] +
                 (jitter[k] != 0 ? jitter[k] * hole_random(block, k) : 0);
    centre = zr_v3_add(centre, zr_v3(shift[0], shift[1], shift[2]));
  }
  zr_vec3 d = zr_v3_sub(p, centre);
  double dist = zr_v3_len(d);
  if (!(dist < w->radius))
    return p;
  double closeness = (w->radius - dist) / w->radius;
  double force = w->strength * pow(closeness, w->falloff);
  if (force > 1)
    force = 1;
  return zr_v3_madd(p, d, w->inverse ? -force : force);
}

/*
 * The mapping warps ("Mapping using warps") turn a point into three map
 * coordinates: u and v "as the image maps use" ("The map_type Option")
 * and a depth, the manual's "distance" (from the origin, the y axis or
 * the torus's ring).  dist_exp e multiplies u and v (cylindrical: u
 * only) by depth^e; e = 0, the default, leaves the manual's box from
 * <0,0> to <1,1>.
 */
typedef struct map_coords {
  double u, v, depth;
} map_coords;

/* The fraction of a turn from the direction (c, s) = (1, 0) towards
   (0, 1), in [0, 1). */
static double turn(double s, double c) {
  double t = atan2(s, c) / (2 * M_PI);
  return t < 0 ? t + 1 : t;
}

static double depth_weight(double depth, double e) {
  return e == 0 ? 1.0 : pow(depth, e);
}

/*
 * Measured (warp_probe.sh, cyl, cyl_exp, cyl_exp2, axis_cyl): u is the
 * turn about y from +x towards +z (<0,0.3,1> has u 0.25, <1,0.3,-1>
 * 0.875), v = y, depth the distance from the y axis; dist_exp scales u
 * alone (<0,0.3,2>, dist_exp 1: u 0.5, v 0.3).  A point on the axis is
 * left where it is, whatever the orientation (axis_cyl).
 */
static bool cylinder_coords(const zr_warp *w, zr_vec3 p, map_coords *m) {
  double r = hypot(p.x, p.z);
  if (r == 0)
    return false;
  m->u = turn(p.z, p.x) * depth_weight(r, w->dist_exp);
  m->v = p.y;
  m->depth = r;
  return true;
}

/*
 * Measured (sph, sph_exp, axis_sph): u as for the cylinder, v from 0 at
 * the -y pole through 0.5 at the equator to 1 at +y, linear in the
 * latitude (<1,1,0>: 0.75), depth the distance from the origin; at a
 * pole u is 0 and the point is mapped like any other (with orientation
 * x, <0,2,0> goes to <2,1,0>); dist_exp scales u and v.  The origin is
 * left where it is.
 */
static bool sphere_coords(const zr_warp *w, zr_vec3 p, map_coords *m) {
  double r = zr_v3_len(p);
  if (r == 0)
    return false;
  double k = depth_weight(r, w->dist_exp);
  double lat = asin(fmax(-1.0, fmin(1.0, p.y / r)));
  m->u = turn(p.z, p.x) * k;
  m->v = (0.5 + lat / M_PI) * k;
  m->depth = r;
  return true;
}

/*
 * Measured (tor, tor_r, axis_tor): u as for the cylinder; v is the turn
 * about the ring at major_radius R in the plane through the y axis,
 * from 0 on the inner side (towards the axis) through 0.25 below, 0.5
 * outside and 0.75 above (R 1: <0.5,0,0> 0, <1,-1,0> 0.25, <2,0,0>
 * 0.5, <1,1,0> 0.75); depth the distance from the ring; dist_exp
 * scales u and v.  A point on the y axis is left where it is.  On the
 * ring itself POV-Ray's v is not a number (tor, <1,0,0>); here it is 0.
 */
static bool torus_coords(const zr_warp *w, zr_vec3 p, map_coords *m) {
  double r = hypot(p.x, p.z);
  if (r == 0)
    return false;
  double out = r - w->major_radius; /* outwards from the ring */
  double depth = hypot(out, p.y);
  double k = depth_weight(depth, w->dist_exp);
  m->u = turn(p.z, p.x) * k;
  m->v = depth == 0 ? 0 : turn(-p.y, -out) * k;
  m->depth = depth;
  return true;
}

/*
 * Where the map coordinates go: the manual's box "stretching to
 * infinity along the orientation vector".  With the default
 * orientation z they are the point (u, v, depth).  Measured
 * (warp_probe.sh, sph_ox, sph_oy, sph_onz, cyl_oy, tor_ox, planar_y):
 * orientation x sends them to (depth, v, -u), orientation y to
 * (u, -depth, v), -z to -(u, v, depth); and for the unit orientations
 * <1,2,3>/sqrt(14), <0.6,0.8,0> and <-1,0.5,0.2>/|...| (sph_o123,
 * sph_o68, sph_oneg) every probe equals o.x times the x placement plus
 * o.y times the y placement plus o.z times the z one (to the 9
 * decimals printed).  So the placement is linear in the orientation;
 * it is not a rotation unless the orientation is an axis.
 */
static zr_vec3 place(zr_vec3 o, map_coords m) {
  zr_vec3 along_x = zr_v3(m.depth, m.v, -m.u);
  zr_vec3 along_y = zr_v3(m.u, -m.depth, m.v);
  zr_vec3 along_z = zr_v3(m.u, m.v, m.depth);
  zr_vec3 q = zr_v3_scale(along_x, o.x);
  q = zr_v3_madd(q, along_y, o.y);
  return zr_v3_madd(q, along_z, o.z);
}

/*
 * planar <n>, d: the manual takes the pattern "from an other plane"
 * (normal n, distance d along it) and extrudes it along z.  Measured
 * (planar, planar_y, planar_n): the point becomes the map coordinates
 * (x, y, d) placed along n as above: by default <x, y, 0>; planar y,
 * 0.5 reads <x, -0.5, y>.
 */
static zr_vec3 planar(const zr_warp *w, zr_vec3 p) {
  map_coords m = {p.x, p.y, w->distance};
  return place(w->orientation, m);
}

/*
 * cubic: the manual maps "an area in the x-y plane between <0,0> and
 * <1,1> around the origin in the same way as uv-mapping an
 * origin-centered cube-shaped box would" (its box map: the faces
 * unfolded as a cross, as lib/trace/intersect.c does for a box).
 * Measured (warp_probe.sh, cubic, cubic_tie, cubic_tie2): the point is
 * pushed out to the cube <-1,-1,-1> to <1,1,1> along its ray from the
 * origin (divided by m, the largest of |x|, |y|, |z|), the face it
 * reaches gives <u, v> with each coordinate c read as (c + 1) / 2, and
 * the third coordinate is m.  Where two faces are equally far the
 * faces win in the order +x, +y, -x, -y, +z, -z (only the ties across
 * the cross's cuts tell: <-1,1,-1> reads from +y, <-1,-1,0.5> from -x,
 * <1,1,0.5> from +x).  At the origin POV-Ray's three values are NaN;
 * here the origin stays where it is.
 */
static zr_vec3 cubic(zr_vec3 p) {
  double m = fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z)));
  if (!(m > 0) || !isfinite(m))
    return p;
  double x = (p.x / m + 1) / 2, y = (p.y / m + 1) / 2, z = (p.z / m + 1) / 2;
  double u, v;
  if (p.x == m) { /* +x */
    u = 0.75 - z / 4;
    v = (1 + y) / 3;
  } else if (p.y == m) { /* +y */
    u = 0.25 + x / 4;
    v = 1 - z / 3;
  } else if (-p.x == m) { /* -x */
    u = z / 4;
    v = (1 + y) / 3;
  } else if (-p.y == m) { /* -y */
    u = 0.25 + x / 4;
    v = z / 3;
  } else if (p.z == m) { /* +z */
    u = 0.25 + x / 4;
    v = (1 + y) / 3;
  } else { /* -z */
    u = 1 - x / 4;
    v = (1 + y) / 3;
  }
  return zr_v3(u, v, m);
}

zr_vec3 zr__warp_apply(const zr_warp *w, zr_vec3 p) {
  map_coords m;
  switch (w->kind) {
  case ZR_WARP_TURBULENCE: /* "Turbulence Warp": p + amount * DNoise */
    return zr_v3_add(p, zr_v3_mul(w->turbulence,
                                  zr__dturbulence(p, w->octaves, w->omega,
                                                  w->lambda)));
  case ZR_WARP_REPEAT:
    return repeat(w, p);
  case ZR_WARP_BLACK_HOLE:
    return black_hole(w, p);
  case ZR_WARP_PLANAR:
    return planar(w, p);
  case ZR_WARP_CYLINDRICAL:
    return cylinder_coords(w, p, &m) ? place(w->orientation, m) : p;
  case ZR_WARP_SPHERICAL:
    return sphere_coords(w, p, &m) ? place(w->orientation, m) : p;
  case ZR_WARP_TOROIDAL:
    return torus_coords(w, p, &m) ? place(w->orientation, m) : p;
  case ZR_WARP_CUBIC:
    return cubic(p);
  }
  return p;
}

static double cut(double c) {
  return fmax(-PATTERN_COORD_MAX, fmin(PATTERN_COORD_MAX, c));
}

zr_vec3 zr__warp_cut(zr_vec3 p) {
  return zr_v3(cut(p.x), cut(p.y), cut(p.z));
}

/* Warps written one after another with no transform between them act in
   the same frame: the point enters it once, goes through all of them
   and leaves once, and a point none of them moved (outside every black
   hole) keeps its exact coordinates.  The HabitablePlanet scene stacks
   1536 black holes in one pigment: three matrix products a warp before. */
zr_vec3 zr__warp_point(const zr_warp *warps, int n, zr_vec3 p) {
  int i = n - 1;
  while (i >= 0) {
    const zr_warp *w = &warps[i];
    zr_vec3 q0 = zr__xform_point(w->frame.m, p);
    zr_vec3 q = zr__warp_apply(w, q0);
    while (--i >= 0 &&
           memcmp(warps[i].frame.m, w->frame.m, sizeof w->frame.m) == 0)
      q = zr__warp_apply(&warps[i], q);
    if (q.x != q0.x || q.y != q0.y || q.z != q0.z)
      p = zr__xform_point(w->frame.inv, q);
  }
  return zr__warp_cut(p);
}
