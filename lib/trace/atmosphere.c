/*
 * atmosphere.c - POV-Ray 3.7's atmospheric effects (reference manual,
 * "Atmospheric Effects": "Background", "Fog", "Sky Sphere", "Rainbow").
 *
 * A ray that hits nothing sees the sky_sphere: its pigments evaluated at
 * the unit direction of the ray taken as a point (through the inverse
 * of the sky's transform when it has one, as a pigment's transform), the last pigment on top and lower ones showing through
 * its filter and transmit like layered textures, the whole scaled by
 * emission.  Without a sky_sphere it sees the background colour.
 *
 * Every ray, reflected and refracted ones too, then passes through the
 * rainbows and the fogs.  Fogs do not stack: each dims what is behind
 * by its share and adds its colour times that share (povray renders a
 * view through two thick grey fogs as white).  For a constant fog of
 * distance D the share of fog over a path of length d is
 * k = 1 - exp(-d / D) (the manual's
 * formula); for ground fog the exponent is the integral of the density,
 * 1 below fog_offset and 1 / (1 + x^2) above, x = (h - offset) / alt,
 * along the path's heights h on the up axis, whose closed form is
 * alt * atan(x).  (The manual writes the density as 1 / (1 + x)^2 and
 * says it is 25% at offset + alt; povray 3.7 renders of horizontal rays
 * through a ground fog measure 1 / (1 + x^2), 50% there, to 1e-3 from
 * x = 0 to 3.5, and that is what this follows.)  A ray to the sky has
 * d = infinity: full constant fog, and the integral to the top of the
 * ground fog.  With the fog colour F = (r, g, b, filter, transmit):
 *   k' = min(k, 1 - transmit)
 *   seen = (1 - k') * C * (1 - filter + filter * F) + k' * F
 * which matches povray 3.7 renders of a plane at distance 1 behind
 * fogs with transmit 0.5 and 0.8, filter 0.5 and filter 0.3 with
 * transmit 0.2 to 1e-4.  Fog turbulence (turbulence, octaves, omega,
 * lambda, turb_depth) thins either kind of fog by a measured factor
 * (fog_thinning below).
 *
 * A rainbow is a fog of its own: a ray at angle a from the rainbow's
 * direction, with angle - width / 2 <= a <= angle + width / 2, takes the
 * colour_map's colour at (a - angle + width / 2) / width (plus jitter
 * noise), mixed in like fog over the rainbow's distance; the arc keeps
 * the part within arc_angle / 2 of the up vector around the direction
 * and fades it out between falloff_angle / 2 and arc_angle / 2 by the
 * smoothstep 3 t^2 - 2 t^3 (t going from 1 to 0), which matches povray
 * renders of a white arc to 1e-4.
 */
#include "trace/atmosphere.h"

#include <math.h>

#include "scene/pattern.h"
#include "scene/texture.h"

static const double DEG = 3.14159265358979323846 / 180.0;

/* Where the sky's pigments are evaluated for a ray of direction dir:
   the unit direction, taken as a point, through the inverse of the
   sky_sphere's transform, not normalised again.  So a sky_sphere's
   transform is its pigments' transform: povray 3.7 renders sky_sphere
   { pigment { P } T } with the same bytes as sky_sphere { pigment { P T }
   } for scale 0.8, scale 2, scale -1, scale <1, 2, 1>, a translate and
   scale <1,2,1> rotate 30*x translate 0.2*y
   (tests/test_sky_transform.sh).  A scale used to change nothing here
   (the point was normalised again) and a translate was dropped. */
static zr_vec3 sky_point(const zr_sky_sphere *sky, zr_vec3 dir) {
  zr_vec3 d = zr_v3_norm(dir);
  return sky->transform ? zr__xform_point(sky->transform->inv, d) : d;
}

zr_rgb zr__sky_colour(const zr_scene *scene, zr_vec3 dir) {
  const zr_sky_sphere *sky = scene->settings.sky_sphere;
  zr_rgb below = zr_colour_rgb(scene->settings.background);
  if (!sky || sky->n_pigments == 0)
    return below;
  zr_vec3 d = sky_point(sky, dir);
  /* Top layer (the last) first.  A sky layer's filter lets light
     through as its transmit does, untinted, and povray 3.7 keeps the
     products of the layers' filters and of their transmits apart: a
     layer (or the background) is seen with weight F + T, F and T the
     products of filter and of transmit over the layers above, and adds
     its colour times that weight and its opacity 1 - f - t.  Measured
     (tests/test_sky_layers.sh): over
     rgb <0.2,0.4,0.8>, rgbf <0.5,0.5,0.5,0.5> under rgbft
     <0.9,0.1,0.1,0.2,0.3> renders <0.596,0.216,0.255>, the bottom layer
     weighed 0.2*0.5 + 0.3*0 = 0.1 (tinting filters, or one product of
     f + t, would give 0.164 or 0.275 in green). */
  zr_rgb sum = zr_rgb3(0, 0, 0);
  double fprod = 1.0, tprod = 0.0;
  for (size_t i = sky->n_pigments; i-- > 0;) {
    zr_colour c = zr__pigment_eval(sky->pigments[i], d);
    double opacity = fmax(0.0, 1.0 - c.f - c.t);
    double weight = i + 1 == sky->n_pigments ? 1.0 : fprod + tprod;
    sum = zr_rgb_add(sum, zr_rgb_scale(zr_colour_rgb(c), weight * opacity));
    if (i + 1 == sky->n_pigments) {
      fprod = c.f;
      tprod = c.t;
    } else {
      fprod *= c.f;
      tprod *= c.t;
    }
  }
  sum = zr_rgb_add(sum, zr_rgb_scale(below, fprod + tprod));
  return zr_rgb_mul(sum, sky->emission);
}

double zr__grey(zr_rgb c) {
  if (c.r == c.g && c.g == c.b)
    return c.r; /* exactly, so white leaves a pixel wholly clear */
  return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

/*
 * povray 3.7 +UA, measured (tests/test_alpha_povray.sh): in a #version
 * 3.7 scene the background is a colour like any with filter f and
 * transmit t over nothing: it adds (1 - f - t) C and leaves f grey(C) + t
 * of the pixel clear (the default background is clear, rgbt <0,0,0,1>);
 * each sky_sphere layer does the same over what is below it.  Older
 * scenes leave the whole background clear and black ("Output_Alpha":
 * the background is suppressed).
 */
zr_rgb zr__sky_clear(const zr_scene *scene, zr_vec3 dir, double *clear) {
  const zr_settings *gs = &scene->settings;
  if (!gs->version_given || gs->version < 3.7) {
    *clear = 1.0;
    return zr_rgb3(0, 0, 0);
  }
  zr_colour b = gs->background;
  zr_rgb below = zr_rgb_scale(zr_colour_rgb(b), fmax(0.0, 1.0 - b.f - b.t));
  double through = b.f * zr__grey(zr_colour_rgb(b)) + b.t;
  const zr_sky_sphere *sky = gs->sky_sphere;
  if (sky && sky->n_pigments > 0) {
    zr_vec3 d = sky_point(sky, dir);
    for (size_t i = 0; i < sky->n_pigments; i++) {
      zr_colour c = zr__pigment_eval(sky->pigments[i], d);
      double opacity = fmax(0.0, 1.0 - c.f - c.t);
      zr_rgb pass = zr_rgb3(c.f * c.r + c.t, c.f * c.g + c.t,
                            c.f * c.b + c.t);
      below = zr_rgb_add(zr_rgb_scale(zr_colour_rgb(c), opacity),
                         zr_rgb_mul(pass, below));
      through *= c.f * zr__grey(zr_colour_rgb(c)) + c.t;
    }
    below = zr_rgb_mul(below, sky->emission);
  }
  *clear = fmin(1.0, fmax(0.0, through));
  return below;
}

/* What is behind a fog of colour f and share kk (already limited by
   transmit): dimmed by 1 - kk and tinted by the filter. */
static zr_rgb fog_dim(zr_rgb colour, zr_colour f, double kk) {
  zr_rgb tint = zr_rgb3(1.0 - f.f + f.f * f.r, 1.0 - f.f + f.f * f.g,
                        1.0 - f.f + f.f * f.b);
  return zr_rgb_scale(zr_rgb_mul(colour, tint), 1.0 - kk);
}

/* A fog's share k limited by its transmit, scaled by a rainbow's arc
   weight (after the limit, as povray does). */
static double fog_amount(zr_colour f, double k, double weight) {
  return fmax(0.0, fmin(k, 1.0 - f.t)) * weight;
}

/* Mixes colour with fog colour f by fog share k, as POV-Ray does. */
static zr_rgb fog_mix(zr_rgb colour, zr_colour f, double k, double weight) {
  double kk = fog_amount(f, k, weight);
  if (!(kk > 0.0))
    return colour;
  return zr_rgb_add(fog_dim(colour, f, kk), zr_rgb_scale(zr_colour_rgb(f),
                                                         kk));
}

/* The integral of the ground fog's density over heights up to h. */
static double ground_integral(const zr_fog *fog, double h) {
  if (h <= fog->offset)
    return h - fog->offset;
  if (!(fog->alt > 0.0))
    return 0.0; /* no fading layer: density 0 above the offset */
  double x = (h - fog->offset) / fog->alt;
  return fog->alt * atan(x);
}

/* The optical depth of a ground fog (in units of fog distance) along a
   path from height h0 to height h1 of length d. */
static double ground_depth(const zr_fog *fog, double h0, double h1,
                           double d) {
  double dh = h1 - h0;
  if (fabs(dh) < 1e-9 * fmax(1.0, d)) {
    double density = h0 <= fog->offset ? 1.0 : 0.0;
    if (h0 > fog->offset && fog->alt > 0.0) {
      double x = (h0 - fog->offset) / fog->alt;
      density = 1.0 / (1.0 + x * x);
    }
    return density * d;
  }
  double integral = ground_integral(fog, h1) - ground_integral(fog, h0);
  return integral / dh * d;
}

/*
 * Fog turbulence thins the fog: the optical depth of a path of length d
 * is scaled by 1 - min(1, turb_depth s) exp(-d / distance), s the scalar
 * turbulence sum (zr__turbulence_scalar, the fog's octaves, omega and
 * lambda) at the turbulence vector times (componentwise) the middle of
 * the path.  Measured from povray 3.7 renders of a black plane at
 * distance d behind a white fog, through a 0.01 degree camera and read
 * back 16-bit linear (bench/conform/fog_turbulence_probe.sh): for
 * constant and ground fog alike, with turbulence 0, 0.002 to 0.5, d 1
 * to 103, distance 20 and 50, turb_depth 0.25 to 2, octaves 1 to 6 and
 * omega 0.7, the depth matches to 1e-4; the point is the middle whatever
 * turb_depth is (a camera whose middle point is the origin sees s at
 * the origin for any turbulence), and turb_depth only scales.  A ray to
 * the sky (d infinite) is not thinned, so a sky seen through a turbulent
 * ground fog stays smooth.
 */
static double fog_thinning(const zr_fog *fog, zr_vec3 origin, zr_vec3 unit,
                           double d) {
  if (zr_v3_len(fog->turbulence) == 0.0 || isinf(d))
    return 1.0;
  zr_vec3 mid = zr_v3_madd(origin, unit, 0.5 * d);
  if (fog->transform)
    mid = zr__xform_point(fog->transform->inv, mid);
  double s = zr__turbulence_scalar(zr_v3_mul(mid, fog->turbulence),
                                   fog->octaves, fog->omega, fog->lambda);
  return 1.0 - fmin(1.0, fog->turb_depth * s) * exp(-d / fog->distance);
}

static double fog_share(const zr_fog *fog, zr_vec3 origin, zr_vec3 unit,
                        double d) {
  if (!(fog->distance > 0.0))
    return 0.0; /* the manual: a distance of zero turns the fog off */
  if (fog->type != 2)
    return isinf(d) ? 1.0
                    : 1.0 - exp(-d * fog_thinning(fog, origin, unit, d) /
                                fog->distance);
  double h0 = zr_v3_dot(origin, fog->up);
  double slope = zr_v3_dot(unit, fog->up);
  double depth;
  if (isinf(d)) {
    if (slope <= 0.0)
      return 1.0; /* level or downward forever: into the dense layer */
    /* Up to the top: the integral from h0 to infinity, per unit of
       height, over the slope. */
    double top = fog->alt > 0.0 ? fog->alt * M_PI / 2.0 : 0.0;
    double rest = top - ground_integral(fog, h0);
    depth = rest / slope;
  } else {
    depth = ground_depth(fog, h0, h0 + slope * d, d) *
            fog_thinning(fog, origin, unit, d);
  }
  return 1.0 - exp(-depth / fog->distance);
}

static zr_rgb apply_rainbow(const zr_rainbow *rb, zr_vec3 unit, double d,
                            zr_rgb colour) {
  double c = fmax(-1.0, fmin(1.0, zr_v3_dot(unit, rb->direction)));
  double a = acos(c) / DEG;
  double lo = rb->angle - 0.5 * rb->width;
  double index = rb->width > 0.0 ? (a - lo) / rb->width : -1.0;
  /* "random noise" on the index ("Rainbow"): our own noise of the ray's
     direction, which changes over 1/1000 radian (about a pixel of a
     wide view) so that it reads as grain, as povray's random numbers
     do, yet the same direction always gets the same value. */
  if (rb->jitter != 0.0)
    index += rb->jitter * (zr__noise(zr_v3_scale(unit, 1000.0)) - 0.5);
  if (index < 0.0 || index > 1.0 || !rb->colour_map)
    return colour;
  /* Where around the direction the ray lies, from up. */
  double weight = 1.0;
  if (rb->arc_angle < 360.0) {
    zr_vec3 side = zr_v3_sub(unit, zr_v3_scale(rb->direction, c));
    zr_vec3 up = zr_v3_sub(rb->up,
                           zr_v3_scale(rb->direction,
                                       zr_v3_dot(rb->up, rb->direction)));
    if (zr_v3_len(side) == 0.0 || zr_v3_len(up) == 0.0)
      return colour;
    double phi = acos(fmax(-1.0, fmin(1.0, zr_v3_dot(zr_v3_norm(side),
                                                     zr_v3_norm(up))))) /
                 DEG;
    if (phi > 0.5 * rb->arc_angle)
      return colour;
    double soft = 0.5 * (rb->arc_angle - rb->falloff_angle);
    if (phi > 0.5 * rb->falloff_angle && soft > 0.0) {
      double t = 1.0 - (phi - 0.5 * rb->falloff_angle) / soft;
      /* Measured: a smoothstep (bench/provenance/probe.py
         rainbow_falloff). */
      weight = t * t * (3.0 - 2.0 * t);
    }
  }
  zr_colour f = zr__colour_map_eval(rb->colour_map, index);
  double k = rb->distance > 0.0 && !isinf(d)
                 ? 1.0 - exp(-d / rb->distance)
                 : 1.0;
  return fog_mix(colour, f, k, weight);
}

zr_rgb zr__atmosphere_apply(const zr_scene *scene, zr_vec3 origin,
                            zr_vec3 dir, double t, zr_rgb colour) {
  const zr_settings *s = &scene->settings;
  if (!s->fogs && !s->rainbows)
    return colour;
  double len = zr_v3_len(dir);
  if (len == 0.0)
    return colour;
  zr_vec3 unit = zr_v3_scale(dir, 1.0 / len);
  double d = isinf(t) ? t : t * len;
  /* Rainbows lie behind the fogs: povray renders a rainbow seen
     through fog faded by it. */
  for (const zr_rainbow *rb = s->rainbows; rb; rb = rb->next)
    colour = apply_rainbow(rb, unit, d, colour);
  /* Several fogs do not stack one over another: each dims what is
     behind by its share and adds its own colour, so two thick fogs can
     add up to more than either colour (povray renders a view through
     fogs of 0.8 and 0.7 grey as white). */
  zr_rgb behind = colour, added = zr_rgb3(0, 0, 0);
  for (const zr_fog *f = s->fogs; f; f = f->next) {
    double kk = fog_amount(f->colour, fog_share(f, origin, unit, d), 1.0);
    behind = fog_dim(behind, f->colour, kk);
    added = zr_rgb_add(added, zr_rgb_scale(zr_colour_rgb(f->colour), kk));
  }
  if (s->fogs)
    colour = zr_rgb_add(behind, added);
  return colour;
}

zr_rgb zr__fog_attenuate(const zr_scene *scene, zr_vec3 origin, zr_vec3 dir,
                         double t, zr_rgb colour) {
  double len = zr_v3_len(dir);
  if (!scene->settings.fogs || len == 0.0)
    return colour;
  zr_vec3 unit = zr_v3_scale(dir, 1.0 / len);
  double d = isinf(t) ? t : t * len;
  for (const zr_fog *f = scene->settings.fogs; f; f = f->next)
    colour = fog_dim(colour, f->colour,
                     fog_amount(f->colour, fog_share(f, origin, unit, d),
                                1.0));
  return colour;
}
