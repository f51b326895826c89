/*
 * texture.c - what a pigment or a normal is at a surface point
 * (reference manual, "Pigment", "Color Maps", "Color List Pigments",
 * "Image Maps", "Bitmap Modifiers", "Normal").
 *
 * A point is taken to pattern space by the inverse of the pigment's
 * transform (which the parser composes with the transforms of the
 * objects the pigment is on), then:
 *   - a colour map interpolates linearly, all five channels, between the
 *     two entries around the value; two entries with the same value make
 *     a sharp edge; below the first entry and above the last the nearest
 *     entry's colour holds.  A pattern without a map uses black to white,
 *     as POV-Ray's renders of gradient show;
 *   - checker, hexagon and brick pick a colour of their list, whose
 *     defaults are POV-Ray's: checker blue, green; hexagon blue, green,
 *     red; brick mortar grey 0.5 and brick <0.6, 0.15, 0.15> (measured);
 *   - an image map projects its picture, which fills the unit square
 *     (0,0)-(1,1), onto the x-y plane (map_type 0), around the y axis
 *     onto a sphere (1: u the angle from +x, v the latitude from the
 *     south pole) or a cylinder (2: u as for the sphere, v = y).  The
 *     picture repeats unless "once", outside which it is clear
 *     (transmit 1).  interpolate 2 is bilinear between pixel centres;
 *     filter all / transmit all set those channels for every pixel.
 * Normals follow "Normal": the surface is taken as displaced by
 * bump_size times the pattern's value, so the normal tilts against the
 * value's gradient, measured by central differences 0.02 pattern units
 * apart (POV-Ray's default "accuracy") and carried to world space by the
 * inverse transpose of the transform.  dents uses the cube of the noise,
 * which leaves flat ground between sharp pits.
 */
#include "scene/texture.h"

#include <math.h>
#include <stddef.h>

#include "scene/pattern.h"

#define PI 3.14159265358979323846

/* Central difference step of normal slopes, in pattern units. */
#define NORMAL_ACCURACY 0.02

static const zr_colour_map_entry grey_ramp[] = {
    {0.0, {0, 0, 0, 0, 0}},
    {1.0, {1, 1, 1, 0, 0}},
};
static const zr_colour_map default_map = {2, grey_ramp};

const zr_colour_map *zr__default_colour_map(void) { return &default_map; }

static zr_colour mix(zr_colour a, zr_colour b, double t) {
  return zr_colour5(a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t,
                    a.b + (b.b - a.b) * t, a.f + (b.f - a.f) * t,
                    a.t + (b.t - a.t) * t);
}

zr_colour zr__colour_map_eval(const zr_colour_map *map, double v) {
  const zr_colour_map_entry *e = map->entries;
  size_t n = map->n;
  if (v <= e[0].value)
    return e[0].colour;
  if (v >= e[n - 1].value)
    return e[n - 1].colour;
  size_t i = 0;
  while (i + 1 < n && e[i + 1].value <= v)
    i++;
  /* Now e[i].value <= v < e[i + 1].value, so the gap is not zero. */
  double t = (v - e[i].value) / (e[i + 1].value - e[i].value);
  return mix(e[i].colour, e[i + 1].colour, t);
}

void zr__pigment_set_pattern(zr_pigment *pg, zr_pattern_kind kind) {
  pg->kind = ZR_PIGMENT_PATTERN;
  zr__pattern_init(&pg->pattern, kind);
  const zr_colour blue = zr_colour5(0, 0, 1, 0, 0);
  const zr_colour green = zr_colour5(0, 1, 0, 0, 0);
  const zr_colour red = zr_colour5(1, 0, 0, 0, 0);
  if (kind == ZR_PAT_BRICK) {
    pg->list[0] = zr_colour5(0.5, 0.5, 0.5, 0, 0);
    pg->list[1] = zr_colour5(0.6, 0.15, 0.15, 0, 0);
  } else {
    pg->list[0] = blue;
    pg->list[1] = green;
    pg->list[2] = red;
  }
}

/* ---- image maps ---- */

static double frac(double v) { return v - floor(v); }

static zr_colour pixel(const zr_image_map *im, int x, int y) {
  const float *px = im->pixels + ((size_t)y * (size_t)im->width +
                                  (size_t)x) * 3;
  return zr_colour5(px[0], px[1], px[2], im->filter_all, im->transmit_all);
}

/* The pixel index of coordinate c (in pixels) along a side of n,
   wrapped when the map repeats, clamped when it is shown once. */
static int index_of(double c, int n, bool repeat) {
  long i = (long)floor(c);
  if (repeat) {
    i %= n;
    return (int)(i < 0 ? i + n : i);
  }
  return (int)(i < 0 ? 0 : i >= n ? n - 1 : i);
}

zr_colour zr__image_map_eval(const zr_image_map *im, zr_vec3 p) {
  double u, v;
  bool once_u = false, once_v = false;
  if (im->map_type == 1 || im->map_type == 2) {
    double a = atan2(p.z, p.x) / (2 * PI);
    u = a < 0 ? a + 1 : a;
    if (im->map_type == 1) {
      double r = zr_v3_len(p);
      double s = r > 0 ? p.y / r : 0;
      s = s < -1 ? -1 : s > 1 ? 1 : s;
      v = 0.5 + asin(s) / PI;
    } else {
      v = p.y;
      once_v = im->once;
    }
  } else {
    u = p.x;
    v = p.y;
    once_u = once_v = im->once;
  }
  if ((once_u && (u < 0 || u >= 1)) || (once_v && (v < 0 || v >= 1)))
    return zr_colour5(0, 0, 0, 0, 1);
  if (!once_u)
    u = frac(u);
  if (!once_v)
    v = frac(v);
  /* Image rows run top to bottom, v bottom to top. */
  double px = u * im->width, py = (1 - v) * im->height;
  if (im->interpolate == 0)
    return pixel(im, index_of(px, im->width, !once_u),
                 index_of(py, im->height, !once_v));
  double fx = px - 0.5, fy = py - 0.5;
  double tx = frac(fx), ty = frac(fy);
  int x0 = index_of(fx, im->width, !once_u);
  int x1 = index_of(fx + 1, im->width, !once_u);
  int y0 = index_of(fy, im->height, !once_v);
  int y1 = index_of(fy + 1, im->height, !once_v);
  zr_colour top = mix(pixel(im, x0, y0), pixel(im, x1, y0), tx);
  zr_colour bottom = mix(pixel(im, x0, y1), pixel(im, x1, y1), tx);
  return mix(top, bottom, ty);
}

/* ---- pigments ---- */

static zr_vec3 to_pattern(const zr_transform *t, zr_vec3 world) {
  return t ? zr__xform_point(t->inv, world) : world;
}

zr_colour zr__pigment_eval(const zr_pigment *pg, zr_vec3 world) {
  if (pg->kind == ZR_PIGMENT_SOLID)
    return pg->colour;
  zr_vec3 p = to_pattern(pg->transform, world);
  if (pg->kind == ZR_PIGMENT_IMAGE)
    return zr__image_map_eval(pg->image, p);
  double v = zr__pattern_eval(&pg->pattern, p);
  if (zr__pattern_is_block(pg->pattern.kind)) {
    int i = (int)v;
    return pg->list[i < 0 ? 0 : i > 2 ? 2 : i];
  }
  return zr__colour_map_eval(
      pg->colour_map ? pg->colour_map : zr__default_colour_map(), v);
}

/* ---- normals ---- */

static double height(const zr_pattern *pt, zr_vec3 p) {
  double v = zr__pattern_eval(pt, p);
  return pt->kind == ZR_PAT_DENTS ? v * v * v : v;
}

zr_vec3 zr__normal_perturb(const zr_normal *nm, zr_vec3 world, zr_vec3 n) {
  if (nm->amount == 0 || nm->pattern.kind == ZR_PAT_NONE)
    return n;
  zr_vec3 p = to_pattern(nm->transform, world);
  const double h = NORMAL_ACCURACY;
  const zr_pattern *pt = &nm->pattern;
  zr_vec3 g = zr_v3(
      height(pt, zr_v3(p.x + h, p.y, p.z)) -
          height(pt, zr_v3(p.x - h, p.y, p.z)),
      height(pt, zr_v3(p.x, p.y + h, p.z)) -
          height(pt, zr_v3(p.x, p.y - h, p.z)),
      height(pt, zr_v3(p.x, p.y, p.z + h)) -
          height(pt, zr_v3(p.x, p.y, p.z - h)));
  g = zr_v3_scale(g, 1 / (2 * h));
  if (nm->transform)
    g = zr__xform_normal(nm->transform->inv, g);
  /* Only the slope along the surface tilts it. */
  zr_vec3 tangential = zr_v3_madd(g, n, -zr_v3_dot(g, n));
  zr_vec3 tilted = zr_v3_madd(n, tangential, -nm->amount);
  double len = zr_v3_len(tilted);
  return len > 0 ? zr_v3_scale(tilted, 1 / len) : n;
}
