/*
 * bitmap.c - pictures wrapped around objects: the map types shared by
 * image_map, bump_map and material_map, the normals of bump maps and
 * the textures material maps pick (reference manual, "Bitmap
 * Modifiers", "Bump Map", "Material Maps").
 *
 * A map's picture fills the unit square (0,0)-(1,1) of its own space.
 * map_type 0 projects it along z onto the x-y plane; 1 wraps it around
 * a sphere at the origin (u the angle about y from +x towards +z, v the
 * latitude from the south pole); 2 around a cylinder on the y axis (u
 * as for the sphere, v = y); 5 around a torus of major radius 1 in the
 * x-z plane (u as for the sphere, v the angle around the tube from its
 * outer equator upwards over a turn, so the top and bottom edges of the
 * picture meet on the inner rim).  POV-Ray 3.7 renders of a picture
 * holding its own (u, v) as red and green on "torus { 1, 0.4 }" read
 * u = 0.125 at 45 degrees from +x towards +z, v = 0.75 on top of the
 * tube, 0.5 on the outer and 0.25 under it.
 *
 * A bump map's height at a pixel is its grey, 0.297 red + 0.589 green
 * + 0.114 blue of the stored codes over their maximum (no transfer
 * function, unless the file name has a gamma), or with use_index the
 * palette index itself (5 for index 5, whatever the palette's size).
 * The normal tilts by bump_size times the slope of the plane through
 * three heights: at the point and one pixel below it in the picture
 * and one to either side, (px -+ 1, py + 1).  So a slope is a height
 * difference per pixel, whatever the picture's size or scale, and a
 * one-pixel step also leans the normal along v.  Everything here was
 * measured with POV-Ray 3.7 renders of a plane lit from five
 * directions, which give the normal at each pixel: a 256-pixel grey
 * ramp tilts it by 1/255 of bump_size, an 8-pixel one by 1/7; a step
 * from 0 to 1 tilts the pixels on either side by bump_size / 2 along u
 * and +-bump_size / 2 along v; a single bright pixel tilts only itself
 * (by bump_size along -v) and its two lower neighbours (bump_size / 2
 * along -+u and +v); pure red, green and blue give 0.297, 0.589 and
 * 0.114; "interpolate 2" takes the three heights bilinearly at those
 * offsets; a uniform scale leaves the tilt alone while "scale <1/4, 1,
 * 1>" makes it four times as steep along x, so the tilt is made in the
 * map's space and carried to the world by the inverse transpose.  Off a
 * "once" picture the normal is left alone.  The default bump_size is
 * 0.5, as for other normals.
 *
 * A material map's index at a pixel is its palette index, or for a
 * picture without a palette its red sample on a 0 .. 255 scale; the
 * texture list is indexed modulo its length, and off a "once" picture
 * the first texture holds.  "interpolate 2" blends the indices
 * bilinearly (wrapping like the picture) and rounds the blend down: a
 * POV-Ray 3.7 render of a four-pixel map of indices 0 to 3 picks
 * textures 1, 0, 1, 2, 1 across it, at the same places as here.
 * interpolate 3 and 4 (bicubic, normalized distance) act as 2, as for
 * image maps.
 */
#include "scene/bitmap.h"

#include <math.h>
#include <stddef.h>

#define PI 3.14159265358979323846

static double frac(double v) { return v - floor(v); }

/* u, the angle about the y axis from +x towards +z over a turn. */
static double around_y(zr_vec3 p) {
  double a = atan2(p.z, p.x) / (2 * PI);
  return a < 0 ? a + 1 : a;
}

bool zr__bitmap_where(const zr_image_map *im, zr_vec3 p, double *px,
                      double *py, bool *repeat_x, bool *repeat_y) {
  double u, v;
  bool once_u = false, once_v = false;
  switch (im->map_type) {
  case 1: {
    u = around_y(p);
    double r = zr_v3_len(p);
    double s = r > 0 ? p.y / r : 0;
    s = s < -1 ? -1 : s > 1 ? 1 : s;
    v = 0.5 + asin(s) / PI;
    break;
  }
  case 2:
    u = around_y(p);
    v = p.y;
    once_v = im->once;
    break;
  case 5: {
    u = around_y(p);
    double rho = sqrt(p.x * p.x + p.z * p.z);
    v = 0.5 + atan2(p.y, rho - 1) / (2 * PI);
    break;
  }
  default:
    u = p.x;
    v = p.y;
    once_u = once_v = im->once;
    break;
  }
  if ((once_u && (u < 0 || u >= 1)) || (once_v && (v < 0 || v >= 1)))
    return false;
  if (!once_u)
    u = frac(u);
  if (!once_v)
    v = frac(v);
  /* Picture rows run top to bottom, v bottom to top. */
  *px = u * im->width;
  *py = (1 - v) * im->height;
  *repeat_x = !once_u;
  *repeat_y = !once_v;
  return true;
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

/* The number of pixel (x, y), from the picture's codes: the same float
   a per-pixel array held before pictures were kept compact. */
static double value(const zr_image_map *im, int x, int y) {
  size_t i = (size_t)y * (size_t)im->width + (size_t)x;
  switch (im->value_kind) {
  case ZR_BITMAP_VALUE_INDEX:
    return im->indices[i];
  case ZR_BITMAP_VALUE_GREY: {
    const double *v = im->code_value;
    if (im->layout == ZR_LAYOUT_GREY) {
      double s = v[zr__bitmap_code(im, i, 0)];
      return (float)(0.297 * s + 0.589 * s + 0.114 * s);
    }
    return (float)(0.297 * v[zr__bitmap_code(im, i, 0)] +
                   0.589 * v[zr__bitmap_code(im, i, 1)] +
                   0.114 * v[zr__bitmap_code(im, i, 2)]);
  }
  case ZR_BITMAP_VALUE_RED:
    return (float)floor(im->code_value[zr__bitmap_code(im, i, 0)] * 255 +
                        0.5);
  case ZR_BITMAP_VALUE_CLEAR:
    return im->alpha ? 1.0 - im->alpha[i] : 0.0;
  default:
    return im->values[i];
  }
}

double zr__bitmap_value(const zr_image_map *im, double px, double py,
                        bool repeat_x, bool repeat_y) {
  if (im->interpolate == 0)
    return value(im, index_of(px, im->width, repeat_x),
                 index_of(py, im->height, repeat_y));
  double fx = px - 0.5, fy = py - 0.5;
  double tx = frac(fx), ty = frac(fy);
  int x0 = index_of(fx, im->width, repeat_x);
  int x1 = index_of(fx + 1, im->width, repeat_x);
  int y0 = index_of(fy, im->height, repeat_y);
  int y1 = index_of(fy + 1, im->height, repeat_y);
  double a = value(im, x0, y0), b = value(im, x1, y0);
  double c = value(im, x0, y1), d = value(im, x1, y1);
  double top = a + (b - a) * tx, bottom = c + (d - c) * tx;
  return top + (bottom - top) * ty;
}

/* The unit directions, in the map's space, in which u and v grow at p. */
static void uv_directions(const zr_image_map *im, zr_vec3 p, zr_vec3 *eu,
                          zr_vec3 *ev) {
  if (im->map_type != 1 && im->map_type != 2 && im->map_type != 5) {
    *eu = zr_v3(1, 0, 0);
    *ev = zr_v3(0, 1, 0);
    return;
  }
  *eu = zr_v3_norm(zr_v3(-p.z, 0, p.x));
  if (im->map_type == 2) {
    *ev = zr_v3(0, 1, 0);
  } else if (im->map_type == 1) {
    /* North along the sphere: y without its radial part. */
    zr_vec3 r = zr_v3_norm(p);
    *ev = zr_v3_norm(zr_v3_madd(zr_v3(0, 1, 0), r, -r.y));
  } else {
    /* Around the tube: (-sin a) outwards + (cos a) up. */
    double rho = sqrt(p.x * p.x + p.z * p.z);
    zr_vec3 out = rho > 0 ? zr_v3(p.x / rho, 0, p.z / rho) : zr_v3(1, 0, 0);
    double a = atan2(p.y, rho - 1);
    *ev = zr_v3_madd(zr_v3(0, cos(a), 0), out, -sin(a));
  }
}

zr_vec3 zr__bump_map_perturb(const zr_normal *nm, zr_vec3 world, zr_vec3 n) {
  const zr_image_map *im = nm->bump_map;
  const zr_transform *t = nm->transform;
  zr_vec3 p = t ? zr__xform_point(t->inv, world) : world;
  double px, py;
  bool rx, ry;
  if (nm->amount == 0 || !zr__bitmap_where(im, p, &px, &py, &rx, &ry))
    return n;
  double h0 = zr__bitmap_value(im, px, py, rx, ry);
  double h1 = zr__bitmap_value(im, px + 1, py + 1, rx, ry);
  double h2 = zr__bitmap_value(im, px - 1, py + 1, rx, ry);
  /* The slope, per pixel, of the plane through the three heights. */
  double du = (h1 - h2) / 2, dv = (2 * h0 - h1 - h2) / 2;
  zr_vec3 eu, ev;
  uv_directions(im, p, &eu, &ev);
  zr_vec3 slope = zr_v3_add(zr_v3_scale(eu, du), zr_v3_scale(ev, dv));
  /* World normals go to the map's space by the transpose of m. */
  zr_vec3 np = t ? zr_v3_norm(zr__xform_normal(t->m, n)) : n;
  zr_vec3 tangential = zr_v3_madd(slope, np, -zr_v3_dot(slope, np));
  zr_vec3 tilted = zr_v3_madd(np, tangential, -nm->amount);
  if (t)
    tilted = zr__xform_normal(t->inv, tilted);
  double len = zr_v3_len(tilted);
  return len > 0 ? zr_v3_scale(tilted, 1 / len) : n;
}

size_t zr__material_map_entry(const zr_image_map *im, zr_vec3 p, size_t n) {
  double px, py;
  bool rx, ry;
  if (!zr__bitmap_where(im, p, &px, &py, &rx, &ry))
    return 0;
  double k = floor(zr__bitmap_value(im, px, py, rx, ry) + 1e-9);
  if (!(k >= 0))
    return 0;
  return (size_t)fmod(k, (double)n);
}

double zr__bitmap_pattern(const zr_image_map *im, zr_vec3 p) {
  double px, py;
  bool rx, ry;
  if (!zr__bitmap_where(im, p, &px, &py, &rx, &ry))
    return 0.0;
  double v = zr__bitmap_value(im, px, py, rx, ry);
  return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}
