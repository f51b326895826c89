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
 *     red; brick mortar grey 0.5 and brick <0.6, 0.15, 0.15> (measured:
 *     bench/provenance/probe.py brick_colours);
 *   - an image map projects its picture, which fills the unit square
 *     (0,0)-(1,1), onto the x-y plane (map_type 0), around the y axis
 *     onto a sphere (1: u the angle from +x, v the latitude from the
 *     south pole), a cylinder (2: u as for the sphere, v = y) or a
 *     torus (5), as lib/scene/bitmap.c says.  The
 *     picture repeats unless "once", outside which it is clear
 *     (transmit 1).  interpolate 2 is bilinear between pixel centres;
 *     filter all / transmit all set those channels for every pixel.
 * Normals follow "Normal" and POV-Ray 3.7's renders as
 * bench/conform/normal_probe.sh measures them: the normal, on the
 * viewer's side of the surface, is taken to pattern space and made of
 * unit length there, the gradient of the pattern's height (its value,
 * or the slope map's curve of it) times bump_size times a measured gain
 * is taken off it, and the result goes back to world space by the
 * inverse transpose of the transform.  So a uniform scale of the pattern
 * leaves the tilt as it is, a non-uniform one changes it.  The gradient
 * comes from the height at the corners of a regular tetrahedron
 * "accuracy" (default 0.02, the manual's "Normals, Accuracy",
 * 3.4.6.2.2.1) pattern units around the point, as povray's renders show
 * (slope_corner); a pattern's warps and turbulence move the point once
 * and the corners are around the moved point, unwarped (povray 3.7
 * renders of bozo, granite, agate, spotted, leopard, gradient and
 * crackle normals with turbulence, warps, or both, read back as
 * tests/normal_warped.pov does, match to a level; marble and wood keep
 * their own turbulence in every sample, which matches too).  bumps, dents and wrinkles add bump_size
 * times a vector noise instead (times the cube of the noise for dents,
 * an octave sum of its absolute value for wrinkles), as
 * bench/conform/bump_fit.py measures.
 *
 * Maps ("Pigment Maps and Pigment Lists", "Normal Maps", "Slope Maps",
 * "Texture Maps", "Average"): the pattern's value v falls between two
 * entries, whose items are evaluated and blended linearly (pigments by
 * colour, normals by direction, textures by their lit colour in
 * lib/trace/shade.c); block patterns pick the entry of their index.
 * average mixes every entry by the weight written as its value.  The
 * items of a pigment or normal map are evaluated in the outer one's
 * pattern space (a pigment's normal carried there and back by the
 * inverse transpose), so transforming the outer pigment or normal moves
 * them too, as the manual says.  A slope_map makes the height a cubic
 * Hermite curve of v through the entries' heights with their slopes
 * (per unit of v), which the normal then tilts against.
 */
#include "scene/texture.h"

#include <math.h>
#include <stddef.h>

#include "scene/bitmap.h"
#include "core/noise.h"
#include "scene/pattern.h"
#include "scene/warp.h"

#define PI 3.14159265358979323846

/* Central difference step of normal slopes, in pattern units. */
#define NORMAL_ACCURACY 0.02
/* Tilt gains, measured (see tilt_gain()). */
#define SLOPE_GAIN 0.13333
#define RIPPLES_GAIN 0.41
#define WAVES_GAIN 0.95
/* The same for ripples and waves normals without a slope map, which
   tilt by zr__pattern_wave_normal(): povray 3.7 takes amount / 10 times
   the sum over the ten waves of the unit vector from the centre times
   the sine of the wave's phase, over the wave's spatial frequency for
   waves, off the normal (bench/conform/waves_normal_fit.py: a least
   squares fit to povray's tilts with a cosine and a sine term per wave
   gives sines of -amount / 10 (/ s_k) and cosines of 0, residual 1e-5,
   at frequencies 1 to 3, phases 0 to 0.3, scales 0.2 and 1;
   tests/test_waves_normal.sh keeps povray's values).  Before, the cosine
   stood there: waves 0.5 at scale 1 leaned the wrong way. */
#define RIPPLES_WAVE_GAIN -1.0
#define WAVES_WAVE_GAIN -1.0
/* Octaves of wrinkles' vector noise (bench/conform/bump_fit.py: 10 fits
   to 2e-5, 8 and 12 to 2e-4). */
#define WRINKLES_OCTAVES 10

static const zr_colour_map_entry grey_ramp[] = {
    {0.0, {0, 0, 0, 0, 0}},
    {1.0, {1, 1, 1, 0, 0}},
};
static const zr_colour_map default_map = {2, grey_ramp};

const zr_colour_map *zr__default_colour_map(void) { return &default_map; }

/*
 * The maps POV-Ray 3.7 gives some patterns written without a colour map
 * (pigments/pigment.pov); read from its #debug output by
 * bench/conform/defmap_probe.sh, which prints each pattern's value and
 * colour at scattered points (every knot below fits them to 1e-5).
 * Other patterns use the grey ramp.  mandel's knots come from its values
 * at 1000 and 5000 iterations, k / 1000 and k / 5000 (the same probe with
 * "mandel 1000" and "mandel 5000", 6000-20000 points): black up to 0.001
 * inclusive, cyan just above, then linear to the knots below; every value
 * of 0.1 and more, the set itself (1) too, is cyan (tests/
 * test_mandel_map.sh).  As a value of exactly 1/1000 (one iteration of
 * 1000) is black, the step stands just above 0.001: at 0.001 in single
 * precision, 0.001 + 4.7e-11, which no value k / n of n < 10^7
 * iterations falls between.
 */
static const zr_colour_map_entry agate_map[] = {
    {0.0, {1, 1, 1, 0, 0}},         {0.5, {0.95, 0.75, 0.5, 0, 0}},
    {0.5, {0.9, 0.7, 0.5, 0, 0}},   {0.6, {0.9, 0.7, 0.4, 0, 0}},
    {0.6, {1, 0.7, 0.4, 0, 0}},     {1.0, {0.6, 0.3, 0, 0, 0}},
};
static const zr_colour_map_entry bozo_map[] = {
    {0.4, {1, 1, 1, 0, 0}}, {0.4, {0, 1, 0, 0, 0}}, {0.6, {0, 1, 0, 0, 0}},
    {0.6, {0, 0, 1, 0, 0}}, {0.8, {0, 0, 1, 0, 0}}, {0.8, {1, 0, 0, 0, 0}},
};
static const zr_colour_map_entry marble_map[] = {
    {0.0, {0.9, 0.8, 0.8, 0, 0}}, {0.9, {0.9, 0.08, 0.08, 0, 0}},
    {0.9, {0, 0, 0, 0, 0}},
};
static const zr_colour_map_entry radial_map[] = {
    {0.0, {0, 1, 1, 0, 0}},       {1.0 / 3, {1, 1, 0, 0, 0}},
    {2.0 / 3, {1, 0, 1, 0, 0}},   {1.0, {0, 1, 1, 0, 0}},
};
static const zr_colour_map_entry mandel_map[] = {
    {0.0, {0, 0, 0, 0, 0}},
    {0.0010000000474974513, {0, 0, 0, 0, 0}},
    {0.0010000000474974513, {0, 1, 1, 0, 0}},
    {0.012, {1, 1, 0, 0, 0}},
    {0.015, {1, 0, 1, 0, 0}}, {0.1, {0, 1, 1, 0, 0}},
};
static const zr_colour_map_entry wood_map[] = {
    {0.6, {0.666, 0.312, 0.2, 0, 0}},
    {0.6, {0.4, 0.1333, 0.066, 0, 0}},
};
#define MAP_OF(e) {sizeof(e) / sizeof(e)[0], e}
static const zr_colour_map agate_default = MAP_OF(agate_map);
static const zr_colour_map bozo_default = MAP_OF(bozo_map);
static const zr_colour_map marble_default = MAP_OF(marble_map);
static const zr_colour_map mandel_default = MAP_OF(mandel_map);
static const zr_colour_map radial_default = MAP_OF(radial_map);
static const zr_colour_map wood_default = MAP_OF(wood_map);

static const zr_colour_map *default_map_of(zr_pattern_kind kind) {
  switch (kind) {
  case ZR_PAT_AGATE:
    return &agate_default;
  case ZR_PAT_BOZO:
    return &bozo_default;
  case ZR_PAT_MARBLE:
    return &marble_default;
  case ZR_PAT_MANDEL:
    return &mandel_default;
  case ZR_PAT_RADIAL:
    return &radial_default;
  case ZR_PAT_WOOD:
    return &wood_default;
  default:
    return &default_map;
  }
}

static zr_colour mix(zr_colour a, zr_colour b, double t) {
  return zr_colour5(a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t,
                    a.b + (b.b - a.b) * t, a.f + (b.f - a.f) * t,
                    a.t + (b.t - a.t) * t);
}

/*
 * The entries a map value v falls between, as POV-Ray 3.7 picks them
 * (measured with its renders): the first entry whose value exceeds v,
 * blended from the entry before it.  On increasing values that is the
 * usual interval; an entry out of order (woods.inc has "[0.95 ...]
 * [0.90 ...] [1.00 ...]") only serves as the start of the next interval,
 * so the blend weight t is always in [0, 1) and its gap never zero.
 * *i = the lower entry; t = 0 at either end.
 */
static void find_interval(const double *values, size_t stride, size_t n,
                          double v, size_t *i, double *t) {
#define VALUE(k) (*(const double *)((const char *)values + (k) * stride))
  size_t j = 0;
  while (j < n && !(VALUE(j) > v))
    j++;
  *t = 0;
  if (j == 0) {
    *i = 0;
  } else if (j == n) {
    *i = n - 1;
  } else {
    *i = j - 1;
    *t = (v - VALUE(j - 1)) / (VALUE(j) - VALUE(j - 1));
  }
#undef VALUE
}

zr_colour zr__colour_map_eval(const zr_colour_map *map, double v) {
  const zr_colour_map_entry *e = map->entries;
  size_t i;
  double t;
  find_interval(&e[0].value, sizeof *e, map->n, v, &i, &t);
  return t > 0 ? mix(e[i].colour, e[i + 1].colour, t) : e[i].colour;
}

void zr__pigment_set_pattern(zr_pigment *pg, zr_pattern_kind kind) {
  pg->kind = ZR_PIGMENT_PATTERN;
  zr__pattern_set_kind(&pg->pattern, kind);
  const zr_colour blue = zr_colour5(0, 0, 1, 0, 0);
  const zr_colour green = zr_colour5(0, 1, 0, 0, 0);
  const zr_colour red = zr_colour5(1, 0, 0, 0, 0);
  if (kind == ZR_PAT_BRICK) {
    /* The manual's "deep red and dark gray" ("Brick"); the values are
       povray's (bench/provenance/probe.py brick_colours). */
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
  size_t i = (size_t)y * (size_t)im->width + (size_t)x;
  float px[3];
  zr__bitmap_rgb(im, i, px);
  /* An alpha channel adds 1 - alpha to "transmit all" (POV-Ray 3.7's
     sum, not clamped: tests/test_image_alpha.sh). */
  if (im->alpha)
    return zr_colour5(px[0], px[1], px[2], im->filter_all,
                      im->transmit_all + 1.0f - im->alpha[i]);
  if (im->indices) {
    const float *ft = im->palette_ft + 2 * (size_t)im->indices[i];
    return zr_colour5(px[0], px[1], px[2], ft[0], ft[1]);
  }
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
  double px, py;
  bool repeat_x, repeat_y;
  if (!zr__bitmap_where(im, p, &px, &py, &repeat_x, &repeat_y))
    return zr_colour5(0, 0, 0, 0, 1);
  bool once_u = !repeat_x, once_v = !repeat_y;
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

void zr__map_find(const zr_map *m, double v, bool block, size_t *i,
                  double *t) {
  const zr_map_entry *e = m->entries;
  size_t n = m->n;
  *t = 0;
  if (block) {
    /* Block patterns give an index: entries are in list order. */
    int k = (int)v;
    *i = k < 0 ? 0 : (size_t)k >= n ? n - 1 : (size_t)k;
    return;
  }
  find_interval(&e[0].value, sizeof *e, n, v, i, t);
}

/* A pattern's value at p (pattern space) on a surface whose normal is
   n.  The normal stays in world space: POV-Ray 3.7 measures slope
   against the world's directions even when the pigment is rotated
   (a plane and its pigment rotated 30 degrees away from the slope's
   direction renders 0.8353, not 1), while the altitude part follows
   the pattern's transforms like any other pattern. */
static double value_at(const zr_pattern *pt, zr_vec3 p, zr_vec3 n) {
  if (pt->kind != ZR_PAT_SLOPE)
    return zr__pattern_eval(pt, p);
  return zr__pattern_eval_n(pt, p, n);
}

/* A pigment_map's colour at p, pattern space of the outer pigment, on a
   surface whose normal is n. */
static zr_colour pigment_map_eval(const zr_pigment *pg, zr_vec3 p,
                                  zr_vec3 n) {
  const zr_map *m = pg->pigment_map;
  /* POV-Ray evaluates the map's pigments at the warped point too
     (lib/scene/warp.c), so the warps move them all, as for average. */
  const zr_pattern *pt = &pg->pattern;
  zr_pattern unwarped;
  if (pt->n_warps > 0) {
    p = zr__warp_point(pt->warps, pt->n_warps, p);
    unwarped = *pt;
    unwarped.n_warps = 0;
    pt = &unwarped;
  }
  if (pg->pattern.kind == ZR_PAT_AVERAGE) {
    zr_colour sum = zr_colour5(0, 0, 0, 0, 0);
    double total = 0;
    for (size_t k = 0; k < m->n; k++) {
      double w = m->entries[k].value;
      zr_colour c = zr__pigment_eval_n(m->entries[k].u.pigment, p, n);
      sum = zr_colour5(sum.r + w * c.r, sum.g + w * c.g, sum.b + w * c.b,
                       sum.f + w * c.f, sum.t + w * c.t);
      total += w;
    }
    if (total == 0)
      return sum;
    return zr_colour5(sum.r / total, sum.g / total, sum.b / total,
                      sum.f / total, sum.t / total);
  }
  double v = value_at(pt, p, n);
  size_t i;
  double t;
  zr__map_find(m, v, zr__pattern_is_block(pg->pattern.kind), &i, &t);
  zr_colour c = zr__pigment_eval_n(m->entries[i].u.pigment, p, n);
  if (t > 0)
    c = mix(c, zr__pigment_eval_n(m->entries[i + 1].u.pigment, p, n), t);
  return c;
}

zr_colour zr__pigment_eval(const zr_pigment *pg, zr_vec3 world) {
  return zr__pigment_eval_n(pg, world, zr_v3(0, 0, 0));
}

zr_colour zr__pigment_eval_n(const zr_pigment *pg, zr_vec3 world,
                             zr_vec3 n) {
  if (pg->kind == ZR_PIGMENT_SOLID)
    return pg->colour;
  zr_vec3 p = to_pattern(pg->transform, world);
  /* An image_map takes the pigment's warps and turbulence like any
     pattern (the manual's "Warps" apply to "any pattern", and
     textures/pigments/warp1.pov shows the picture bent): the point
     moves first, then the picture is looked up. */
  if (pg->kind == ZR_PIGMENT_IMAGE)
    return zr__image_map_eval(pg->image, zr__pattern_point(&pg->pattern, p));
  if (pg->pigment_map && pg->pigment_map->n > 0)
    return pigment_map_eval(pg, p, n);
  double v = value_at(&pg->pattern, p, n);
  if (zr__pattern_is_block(pg->pattern.kind)) {
    int i = (int)v;
    return pg->list[i < 0 ? 0 : i > 2 ? 2 : i];
  }
  return zr__colour_map_eval(
      pg->colour_map ? pg->colour_map : default_map_of(pg->pattern.kind), v);
}

/* ---- normals ---- */

double zr__slope_map_eval(const zr_map *m, double v) {
  size_t i;
  double t;
  zr__map_find(m, v, false, &i, &t);
  const zr_map_entry *a = &m->entries[i];
  if (t == 0)
    return a->u.slope.height;
  const zr_map_entry *b = &m->entries[i + 1];
  double gap = b->value - a->value;
  double t2 = t * t, t3 = t2 * t;
  /* Cubic Hermite basis on [0, 1], slopes scaled to the interval. */
  return (2 * t3 - 3 * t2 + 1) * a->u.slope.height +
         (t3 - 2 * t2 + t) * gap * a->u.slope.slope +
         (-2 * t3 + 3 * t2) * b->u.slope.height +
         (t3 - t2) * gap * b->u.slope.slope;
}

static double height(const zr_normal *nm, zr_vec3 p) {
  const zr_pattern *pt = &nm->pattern;
  double v = pt->kind == ZR_PAT_QUILTED
                 ? zr__pattern_quilt_relief(pt, zr__pattern_point(pt, p))
                 : zr__pattern_eval(pt, p);
  if (nm->slope_map && nm->slope_map->n > 0)
    return zr__slope_map_eval(nm->slope_map, v);
  return v;
}

/* A normal_map's normal at p (this normal's pattern space) for the
   unit normal n there. */
static zr_vec3 normal_map_perturb(const zr_normal *nm, zr_vec3 p,
                                  zr_vec3 n) {
  const zr_map *m = nm->normal_map;
  if (nm->pattern.kind == ZR_PAT_AVERAGE) {
    zr_vec3 sum = zr_v3(0, 0, 0);
    for (size_t k = 0; k < m->n; k++)
      sum = zr_v3_madd(sum, zr__normal_perturb(m->entries[k].u.normal, p, n),
                       m->entries[k].value);
    double len = zr_v3_len(sum);
    return len > 0 ? zr_v3_scale(sum, 1 / len) : n;
  }
  size_t i;
  double t;
  zr__map_find(m, zr__pattern_eval(&nm->pattern, p),
               zr__pattern_is_block(nm->pattern.kind), &i, &t);
  zr_vec3 r = zr__normal_perturb(m->entries[i].u.normal, p, n);
  if (t > 0) {
    zr_vec3 r2 = zr__normal_perturb(m->entries[i + 1].u.normal, p, n);
    r = zr_v3_add(zr_v3_scale(r, 1 - t), zr_v3_scale(r2, t));
    double len = zr_v3_len(r);
    r = len > 0 ? zr_v3_scale(r, 1 / len) : n;
  }
  return r;
}

/*
 * How far a unit slope of the pattern's height (per pattern unit) tilts
 * the normal, per unit of bump_size.  No section of the manual gives
 * these; each is measured by bench/conform/normal_probe.sh, which reads
 * the normal back from POV-Ray 3.7's renders of a plane lit by three
 * coloured parallel lights and compares it with this renderer's:
 *   - patterns through a slope map, given or implied (gradient, granite,
 *     ...): gradient x, A tilts by 0.13333 A (A = 0.25 to 4, any scale,
 *     any accuracy, with or without slope_map);
 *   - ripples and waves, which POV-Ray tilts by its own rules (bumps,
 *     dents and wrinkles are not slopes, see zr__normal_perturb): the gain that makes the root mean square tilt over
 *     a plane match POV-Ray's at bump size 0.5.
 */
static double tilt_gain(const zr_normal *nm) {
  if (nm->slope_map && nm->slope_map->n > 0)
    return SLOPE_GAIN;
  switch (nm->pattern.kind) {
  case ZR_PAT_RIPPLES:
    return RIPPLES_GAIN;
  case ZR_PAT_WAVES:
    return WAVES_GAIN;
  default:
    return SLOPE_GAIN;
  }
}

/*
 * Where the height is sampled around a point, in units of accuracy
 * (pattern space): the corners of a regular tetrahedron, one on +y and
 * three below it at y = -1/3, the first on +x.  Measured by
 * bench/conform/normal_stencil_probe.sh: a gradient pattern's ramp
 * jumps from 1 to 0 at a plane, and povray 3.7 perturbs the normal of
 * the points within reach of the jump by how far its samples reach
 * across each axis: x +0.9428 and -0.4714, y +1 and -1/3, z +-0.8165
 * times accuracy (to 1e-4 accuracy), and the tilts on either side of
 * the jump are those of the corners across it.  Before, central
 * differences reached +-1 along each axis: the perturbed band around
 * each jump was wider and tilted another way, and high frequencies
 * (witch.pov's radial 0.5 frequency 20 sine_wave) tilted otherwise.
 */
static const zr_vec3 slope_corner[4] = {
    {0.94280904158206336, -1.0 / 3, 0},
    {-0.47140452079103168, -1.0 / 3, 0.81649658092772603},
    {-0.47140452079103168, -1.0 / 3, -0.81649658092772603},
    {0, 1, 0},
};

/* The tilt of the slope of the normal's height at p (pattern space),
   times bump_size and the pattern's gain. */
static zr_vec3 slope_tilt(const zr_normal *nm, zr_vec3 p) {
  double h = nm->accuracy > 0 ? nm->accuracy : NORMAL_ACCURACY;
  /* ripples and waves tilt by their wave's phase, not by its frequency:
     POV-Ray 3.7 shows textures/finishes/arches.pov's water (waves 0.05,
     frequency 5000, scale 3000) gently rippled.  So the step follows
     the wavelength and the slope is divided by the frequency. */
  double freq = fabs(nm->pattern.frequency);
  bool wavy = (nm->pattern.kind == ZR_PAT_RIPPLES ||
               nm->pattern.kind == ZR_PAT_WAVES) &&
              freq > 0 && !(nm->slope_map && nm->slope_map->n > 0);
  if (wavy && freq > 1)
    h /= freq;
  /* The height at the four corners of a regular tetrahedron h around
     p, each weighed by its corner: for a linear height the sum is 4/3 h
     times the gradient (the corners' outer products add to 4/3). */
  zr_vec3 g = zr_v3(0, 0, 0);
  const zr_normal *at = nm;
  zr_normal still;
  zr_vec3 t = nm->pattern.turbulence;
  if ((t.x != 0 || t.y != 0 || t.z != 0 || nm->pattern.n_warps > 0) &&
      nm->pattern.kind != ZR_PAT_MARBLE && nm->pattern.kind != ZR_PAT_WOOD) {
    still = *nm;
    p = zr__pattern_point(&nm->pattern, p);
    still.pattern.turbulence = zr_v3(0, 0, 0);
    still.pattern.n_warps = 0;
    at = &still;
  }
  for (int k = 0; k < 4; k++)
    g = zr_v3_madd(g, slope_corner[k],
                   height(at, zr_v3_madd(p, slope_corner[k], h)));
  g = zr_v3_scale(g, nm->amount * tilt_gain(nm) * 0.75 / h);
  if (wavy)
    g = zr_v3_scale(g, 1 / freq);
  return g;
}

/* What a quilted normal adds to the normal at q (pattern space): the
   offset d of q from the middle of its unit cube, times the cubic Bezier
   B(r) of its length r (control points 0, control0, control1, 1, as the
   quilted pigment's, pattern.c), divided by the distance to a corner,
   sqrt 3 / 2.  bench/conform/quilted_normal_probe.py reads it back from
   POV-Ray 3.7's renders to 1.6e-5 (the 16-bit read-back's error) for
   four control pairs, two depths in the cube and either side; B keeps
   its sign (control0 -2, control1 3 dent the middle of a cube). */
static zr_vec3 quilt_push(const zr_pattern *pt, zr_vec3 q) {
  zr_vec3 d = zr_v3(q.x - floor(q.x) - 0.5, q.y - floor(q.y) - 0.5,
                    q.z - floor(q.z) - 0.5);
  double r = zr_v3_len(d), u = 1 - r;
  double b = 3 * pt->control0 * r * u * u + 3 * pt->control1 * r * r * u +
             r * r * r;
  return zr_v3_scale(d, b * 2 / sqrt(3.0));
}

zr_vec3 zr__normal_perturb(const zr_normal *nm, zr_vec3 world, zr_vec3 n) {
  if (nm->bump_map)
    return zr__bump_map_perturb(nm, world, n);
  if (nm->normal_map && nm->normal_map->n > 0) {
    zr_vec3 p = to_pattern(nm->transform, world);
    zr_vec3 np = n;
    if (nm->transform) {
      /* World normals go to pattern space by the transpose of m. */
      np = zr__xform_normal(nm->transform->m, n);
      double len = zr_v3_len(np);
      np = len > 0 ? zr_v3_scale(np, 1 / len) : n;
    }
    zr_vec3 r = normal_map_perturb(nm, p, np);
    if (!nm->transform)
      return r;
    r = zr__xform_normal(nm->transform->inv, r);
    double len = zr_v3_len(r);
    return len > 0 ? zr_v3_scale(r, 1 / len) : n;
  }
  if (nm->amount == 0 || nm->pattern.kind == ZR_PAT_NONE)
    return n;
  zr_vec3 p = to_pattern(nm->transform, world);
  /* The normal in pattern space, of unit length there: the tilt is
     measured against it, so a uniform scale of the pattern changes its
     features' size but not their slope (bench/conform/normal_probe.sh:
     gradient x, 0.5 tilts by 0.0667 at scales 0.01 to 10). */
  zr_vec3 np = n;
  if (nm->transform) {
    np = zr__xform_normal(nm->transform->m, n);
    double len = zr_v3_len(np);
    np = len > 0 ? zr_v3_scale(np, 1 / len) : n;
  }
  bool sloped = nm->slope_map && nm->slope_map->n > 0;
  zr_vec3 g;
  if (!sloped && (nm->pattern.kind == ZR_PAT_BUMPS ||
                  nm->pattern.kind == ZR_PAT_DENTS)) {
    /* bumps and dents are not tilted by the slope of their pattern:
       POV-Ray 3.7 adds bump_size times turbulence's vector noise at the
       point to the normal, times the cube of the noise there for dents
       (bench/conform/bump_fit.py: per-pixel correlation 1.00000 and a
       root mean square error of 2e-5, the 16-bit read-back's, on a
       plane seen from either side at bump sizes 0.1 and 0.5). */
    zr_vec3 q = zr__pattern_point(&nm->pattern, p);
    zr_vec3 d = zr__dnoise_lattice(q);
    if (nm->pattern.kind == ZR_PAT_DENTS) {
      double v = zr__noise_lattice(q);
      d = zr_v3_scale(d, v * v * v);
    }
    g = zr_v3_scale(d, -nm->amount);
  } else if (!sloped && nm->pattern.kind == ZR_PAT_WRINKLES) {
    /* wrinkles add bump_size times the sum over 10 octaves of the
       vector noise's absolute value (each component), octave i at 2^i p
       weighed 2^-i: bench/conform/bump_fit.py, correlation 1.00000 at
       bump size 0.1, 0.99994 at 0.5 where lights graze.  The absolute
       values lean the normal towards +x, +y and +z. */
    zr_vec3 q = zr__pattern_point(&nm->pattern, p);
    zr_vec3 sum = zr_v3(0, 0, 0);
    double w = 1;
    for (int i = 0; i < WRINKLES_OCTAVES; i++, w *= 0.5) {
      zr_vec3 d = zr__dnoise_lattice(zr_v3_scale(q, 1 / w));
      sum = zr_v3_madd(sum, zr_v3(fabs(d.x), fabs(d.y), fabs(d.z)), w);
    }
    g = zr_v3_scale(sum, -nm->amount);
  } else if (!sloped && nm->pattern.kind == ZR_PAT_QUILTED) {
    zr_vec3 q = zr__pattern_point(&nm->pattern, p);
    g = zr_v3_scale(quilt_push(&nm->pattern, q), -nm->amount);
  } else if (!sloped && (nm->pattern.kind == ZR_PAT_RIPPLES ||
                         nm->pattern.kind == ZR_PAT_WAVES)) {
    /* ripples and waves tilt along the sum of their waves' directions,
       each weighed by the sine of its phase (pattern.c), not by the
       slope of their pigment value (measured, see WAVES_WAVE_GAIN). */
    zr_vec3 q = zr__pattern_point(&nm->pattern, p);
    double gain = nm->pattern.kind == ZR_PAT_RIPPLES ? RIPPLES_WAVE_GAIN
                                                      : WAVES_WAVE_GAIN;
    g = zr_v3_scale(zr__pattern_wave_normal(&nm->pattern, q),
                    nm->amount * gain);
  } else {
    g = slope_tilt(nm, p);
  }
  /* no_bump_scale: the depth does not follow the scale (measured: bozo
     32 scale 32 no_bump_scale renders as bozo 1 scale 32, bozo 8 scale
     4 as bozo 2 scale 4; tests/no_bump_scale.pov). */
  if (nm->no_bump_scale && nm->transform) {
    const double (*m)[4] = nm->transform->m;
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                 m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    double s = cbrt(fabs(det));
    if (s > 0 && isfinite(s))
      g = zr_v3_scale(g, 1 / s);
  }
  /* The whole gradient is taken off, its part along the normal too:
     gradient <1,0,1>, 4 on a plane seen along +z tilts by 0.28, and by
     0.61 seen along -z (normal_probe.sh), as n - g predicts (0.27,
     0.61) and the tangential part alone (0.38 both ways) does not. */
  zr_vec3 tilted = zr_v3_sub(np, g);
  if (nm->transform)
    tilted = zr__xform_normal(nm->transform->inv, tilted);
  double len = zr_v3_len(tilted);
  return len > 0 ? zr_v3_scale(tilted, 1 / len) : n;
}

/* ---- textures ---- */

/* f * C + t: what a pigment colour lets through. */
static zr_rgb see_through(zr_colour c) {
  return zr_rgb3(c.f * c.r + c.t, c.f * c.g + c.t, c.f * c.b + c.t);
}

const zr_texture *zr__texture_pick(const zr_texture *tx, zr_vec3 world,
                                   const zr_texture **second, double *t) {
  return zr__texture_pick_n(tx, world, zr_v3(0, 0, 0), second, t);
}

const zr_texture *zr__texture_pick_n(const zr_texture *tx, zr_vec3 world,
                                     zr_vec3 n, const zr_texture **second,
                                     double *t) {
  *second = NULL;
  *t = 0;
  if (!tx->map || tx->map->n == 0)
    return tx;
  zr_vec3 p = to_pattern(tx->transform, world);
  size_t i;
  if (tx->material)
    return tx->map->entries[zr__material_map_entry(tx->material, p,
                                                   tx->map->n)].u.texture;
  zr__map_find(tx->map, value_at(&tx->pattern, p, n),
               zr__pattern_is_block(tx->pattern.kind), &i, t);
  if (*t > 0)
    *second = tx->map->entries[i + 1].u.texture;
  return tx->map->entries[i].u.texture;
}

zr_rgb zr__texture_see_through_layer(const zr_texture *layer,
                                     zr_vec3 world) {
  if (!layer->map || layer->map->n == 0)
    return see_through(zr__pigment_eval(layer->pigment, world));
  if (layer->pattern.kind == ZR_PAT_AVERAGE) {
    zr_rgb sum = zr_rgb3(0, 0, 0);
    double total = 0;
    for (size_t i = 0; i < layer->map->n; i++) {
      const zr_map_entry *e = &layer->map->entries[i];
      sum = zr_rgb_add(sum, zr_rgb_scale(zr__texture_see_through(
                                             e->u.texture, world),
                                         e->value));
      total += e->value;
    }
    return total > 0 ? zr_rgb_scale(sum, 1 / total) : sum;
  }
  const zr_texture *b;
  double t;
  const zr_texture *a = zr__texture_pick(layer, world, &b, &t);
  zr_rgb s = zr__texture_see_through(a, world);
  if (b)
    s = zr_rgb_add(zr_rgb_scale(s, 1 - t),
                   zr_rgb_scale(zr__texture_see_through(b, world), t));
  return s;
}

zr_rgb zr__texture_see_through(const zr_texture *tx, zr_vec3 world) {
  zr_rgb through = zr_rgb3(1, 1, 1);
  for (const zr_texture *layer = tx; layer; layer = layer->over)
    through = zr_rgb_mul(through,
                         zr__texture_see_through_layer(layer, world));
  return through;
}
