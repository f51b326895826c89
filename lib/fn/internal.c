/*
 * internal.c - the internal functions of functions.inc, `internal(n)`
 * bodies: 17 f_ellipsoid, 25 f_helix1, 26 f_helix2, 45 f_paraboloid, 47
 * f_ph, 57 f_r, 60 f_rounded_box, 61 f_sphere, 68 f_superellipsoid, 69
 * f_th, 70 f_torus and 71 f_torus2, each fitted to povray 3.7's own
 * values at several points (see tests/test_function.c; its source was
 * not consulted); 76 f_noise3d and 78 f_noise_generator (the bozo
 * pattern's noise), 59 f_ridged_mf and 29 f_hetero_mf (Musgrave's
 * multifractals over it), which have our noise's character and ranges
 * but not POV-Ray's exact values.  Any other n still compiles, so
 * functions.inc parses, but a function that uses one reports it by name
 * and number when it is called (lib/sdl/function.c).
 *
 * Split from lib/sdl/function.c (the compiler) so that the machine and
 * its routines sit below the scene model (lib/fn, README "Layering").
 */
#include "config.h"

#include <math.h>

#include "fn/code.h"

#include "core/noise.h"
#include "core/vec.h"

/* Numbers, names and parameter counts as functions.inc declares them. */
static const zr_fn_internal internals[] = {
    {0, "f_algbr_cyl1", 8, false},    {1, "f_algbr_cyl2", 8, false},
    {2, "f_algbr_cyl3", 8, false},    {3, "f_algbr_cyl4", 8, false},
    {4, "f_bicorn", 5, false},        {5, "f_bifolia", 5, false},
    {6, "f_blob", 8, false},          {7, "f_blob2", 7, false},
    {8, "f_boy_surface", 5, false},   {9, "f_comma", 4, false},
    {10, "f_cross_ellipsoids", 7, false},
    {11, "f_crossed_trough", 4, false},
    {12, "f_cubic_saddle", 4, false}, {13, "f_cushion", 4, false},
    {14, "f_devils_curve", 4, false}, {15, "f_devils_curve_2d", 9, false},
    {16, "f_dupin_cyclid", 9, false}, {17, "f_ellipsoid", 6, true},
    {18, "f_enneper", 4, false},      {19, "f_flange_cover", 7, false},
    {20, "f_folium_surface", 6, false},
    {21, "f_folium_surface_2d", 9, false},
    {22, "f_glob", 4, false},         {23, "f_heart", 4, false},
    {24, "f_helical_torus", 13, false},
    {25, "f_helix1", 10, true},       {26, "f_helix2", 10, true},
    {27, "f_hex_x", 4, false},        {28, "f_hex_y", 4, false},
    {29, "f_hetero_mf", 9, true},     {30, "f_hunt_surface", 4, false},
    {31, "f_hyperbolic_torus", 6, false},
    {32, "f_isect_ellipsoids", 7, false},
    {33, "f_kampyle_of_eudoxus", 6, false},
    {34, "f_kampyle_of_eudoxus_2d", 9, false},
    {35, "f_klein_bottle", 4, false},
    {36, "f_kummer_surface_v1", 4, false},
    {37, "f_kummer_surface_v2", 7, false},
    {38, "f_lemniscate_of_gerono", 4, false},
    {39, "f_lemniscate_of_gerono_2d", 9, false},
    {40, "f_mesh1", 8, false},        {41, "f_mitre", 4, false},
    {42, "f_nodal_cubic", 4, false},  {43, "f_odd", 4, false},
    {44, "f_ovals_of_cassini", 7, false},
    {45, "f_paraboloid", 4, true},    {46, "f_parabolic_torus", 6, false},
    {47, "f_ph", 3, true},            {48, "f_pillow", 4, false},
    {49, "f_piriform", 4, false},     {50, "f_piriform_2d", 10, false},
    {51, "f_poly4", 8, false},        {52, "f_polytubes", 9, false},
    {53, "f_quantum", 4, false},      {54, "f_quartic_paraboloid", 4, false},
    {55, "f_quartic_saddle", 4, false},
    {56, "f_quartic_cylinder", 6, false},
    {57, "f_r", 3, true},             {58, "f_ridge", 9, false},
    {59, "f_ridged_mf", 9, true},     {60, "f_rounded_box", 7, true},
    {61, "f_sphere", 4, true},        {62, "f_spikes", 8, false},
    {63, "f_spikes_2d", 7, false},    {64, "f_spiral", 9, false},
    {65, "f_steiners_roman", 4, false},
    {66, "f_strophoid", 7, false},    {67, "f_strophoid_2d", 10, false},
    {68, "f_superellipsoid", 5, true},
    {69, "f_th", 3, true},            {70, "f_torus", 5, true},
    {71, "f_torus2", 6, true},       {72, "f_torus_gumdrop", 4, false},
    {73, "f_umbrella", 4, false},     {74, "f_witch_of_agnesi", 5, false},
    {75, "f_witch_of_agnesi_2d", 9, false},
    {76, "f_noise3d", 3, true},       {78, "f_noise_generator", 4, true},
};

const zr_fn_internal *zr__fn_internal_find(int number) {
  for (size_t i = 0; i < sizeof internals / sizeof internals[0]; i++)
    if (internals[i].number == number)
      return &internals[i];
  return NULL;
}

/* The functions with a "field strength" parameter give values clipped to
   [-10, 10] in povray 3.7 (f_paraboloid(0, 11, 0, 1) is 10); the plain
   distances (f_sphere, f_torus ...) are not clipped
   (bench/provenance/probe.py field_clip). */
static double field(double v) { return v < -10 ? -10 : v > 10 ? 10 : v; }

/*
 * The noise functions.  f_noise3d is the noise the bozo pattern uses
 * (lib/scene/pattern.c, lib/core/noise.c), in [0, 1] as the manual documents ("Functions.inc":
 * f_snoise3d is "just like f_noise3d(), but returns values in the range
 * [-1, 1]", and functions.inc defines it as 2 f_noise3d - 1).  That noise
 * is POV-Ray's default noise_generator 2, reconstructed from measurements
 * (lib/core/noise.c); f_noise_generator's generators 1, 2 and 3 are
 * POV-Ray's too.
 *
 * f_ridged_mf and f_hetero_mf are F. K. Musgrave's ridged multifractal
 * and heterogeneous terrain ("Texturing and Modeling: A Procedural
 * Approach", chapter "Procedural Fractal Terrains"), whose parameters the
 * manual names and describes: octave i has frequency lacunarity^i and
 * weight lacunarity^(-i H) (the manual's f^-H), both over signed noise.
 * The manual's T of f_hetero_mf blends Musgrave's heterogeneous scaling
 * (each octave scaled by the altitude so far: T = 1) with the plain 1/f
 * sum (T = 0).  Octaves are capped at MAX_OCTAVES so that a huge count
 * cannot stall a render: past that the frequencies are beyond what a
 * double's noise lattice resolves for any lacunarity above 1.5.
 */
#define MAX_OCTAVES 100

static double signed_noise(double x, double y, double z) {
  return 2 * zr__noise_lattice(zr_v3(x, y, z)) - 1;
}

/* The whole octaves to sum; octave 0 is always there.  A NaN count is
   one octave. */
static int whole_octaves(double octaves) {
  return octaves >= MAX_OCTAVES ? MAX_OCTAVES
         : octaves >= 1         ? (int)octaves
                                : 1;
}

/* Musgrave's ridge: offset less |noise|, squared. */
static double ridge_signal(double offset, double x, double y, double z) {
  double s = offset - fabs(signed_noise(x, y, z));
  return s * s;
}

/* a: x, y, z, H, lacunarity, octaves, offset, gain, noise generator. */
static double ridged_mf(const double *a) {
  double h = a[3], lacunarity = a[4], offset = a[6], gain = a[7];
  int octaves = whole_octaves(a[5]);
  double x = a[0], y = a[1], z = a[2];
  double signal = ridge_signal(offset, x, y, z), result = signal;
  double step = pow(lacunarity, -h), weight_of_octave = 1;
  for (int i = 1; i < octaves; i++) {
    x *= lacunarity, y *= lacunarity, z *= lacunarity;
    weight_of_octave *= step;
    /* The previous octave's signal, times gain, weighs this one, so
       ridges (high signal) get detail and valleys stay smooth. */
    double weight = fmin(fmax(signal * gain, 0), 1);
    signal = ridge_signal(offset, x, y, z) * weight;
    result += signal * weight_of_octave;
  }
  return result;
}

/* a: x, y, z, H, lacunarity, octaves, offset, T, noise generator. */
static double hetero_mf(const double *a) {
  double h = a[3], lacunarity = a[4], offset = a[6], t = a[7];
  int octaves = whole_octaves(a[5]);
  double x = a[0], y = a[1], z = a[2];
  double value = offset + signed_noise(x, y, z);
  double step = pow(lacunarity, -h), weight_of_octave = 1;
  for (int i = 1; i < octaves; i++) {
    x *= lacunarity, y *= lacunarity, z *= lacunarity;
    weight_of_octave *= step;
    double increment = (signed_noise(x, y, z) + offset) * weight_of_octave;
    value += increment * ((1 - t) + t * value);
  }
  /* A fractional octave count adds that fraction of one more octave, so
     the result is continuous in the count (Musgrave's remainder). */
  double remainder = a[5] - octaves;
  if (remainder > 0 && remainder < 1) {
    x *= lacunarity, y *= lacunarity, z *= lacunarity;
    weight_of_octave *= step;
    double increment = (signed_noise(x, y, z) + offset) * weight_of_octave;
    value += remainder * increment * ((1 - t) + t * value);
  }
  return value;
}

/*
 * The helixes (functions.inc's f_helix1 and f_helix2, about the y axis).
 * The cross section type c picks the norm of a 2-D offset (u, v): the
 * reference manual's "Cross Section Type" lists 0 square, 1 circle, 2
 * diamond and 3 concave diamond, which are the unit balls of
 * (|u|^p + |v|^p)^(1/p) for p = 2 / c (infinity, 2, 1 and 2/3, the
 * astroid); povray 3.7's values follow that formula for every c we
 * measured, negative ones and its underflow for tiny c included.
 */
static double section_norm(double u, double v, double c) {
  u = fabs(u);
  v = fabs(v);
  if (c == 0)
    return fmax(u, v);
  double p = 2 / c;
  return pow(pow(u, p) + pow(v, p), 1 / p);
}

/* (u, v) turned by angle radians. */
static void turn(double *u, double *v, double angle) {
  double c = cos(angle), s = sin(angle), t = *u;
  *u = t * c - *v * s;
  *v = t * s + *v * c;
}

/*
 * f_helix1: a: x, y, z, number of helixes n, period w, minor radius r,
 * major radius R, shape, cross section type and rotation (degrees).
 * Strand k runs at the angle atan2(z, x) = ((2k + 1) pi) / n - w y, so
 * n strands cross each meridian half plane every 2 pi / (n w) in y.  The
 * section is taken in that half plane: u = rho - R and v the distance in
 * y to the nearest crossing, divided by shape (a wider tube in y for
 * shape > 1), then turned by the rotation.  The value, less r, never
 * exceeds rho + R - r (measured: povray 3.7 bounds it so far from the
 * strands, and when n w or shape is 0).
 */
static double helix1(const double *a) {
  double x = a[0], y = a[1], z = a[2];
  double n = a[3], w = a[4], r = a[5], big = a[6], shape = a[7];
  double rho = sqrt(x * x + z * z);
  double bound = rho + big;
  if (n * w == 0 || shape == 0)
    return bound - r;
  double phase = n * (atan2(z, x) + w * y) - M_PI;
  phase -= 2 * M_PI * floor((phase + M_PI) / (2 * M_PI));
  double u = rho - big, v = phase / (n * w) / shape;
  turn(&u, &v, a[9] * (M_PI / 180));
  return fmin(section_norm(u, v, a[8]), bound) - r;
}

/*
 * f_helix2: one strand whose centre is R (cos w y, sin w y) in the plane
 * of constant y, a twisted bar when r > R ("needs a negated function").
 * The section is in that plane, in axes that turn with the strand; the
 * number of helixes, the shape and the rotation do not count (measured:
 * povray 3.7 gives the same values whatever they are).
 */
static double helix2(const double *a) {
  double x = a[0], y = a[1], z = a[2];
  double w = a[4], r = a[5], big = a[6];
  double u = x - big * cos(w * y), v = z - big * sin(w * y);
  turn(&u, &v, -w * y);
  return section_norm(u, v, a[8]) - r;
}

/*
 * The implemented internals.  Each formula was fitted to povray 3.7's
 * values at several points, signs, clipping and edge cases included
 * (tests/test_function.c quotes them): f_r, f_th and f_ph are spherical
 * coordinates (theta from +z towards +x, phi from +y), the others
 * implicit surfaces about the y axis.
 */
double zr__fn_internal_eval(int number, const double *a) {
  double x = a[0], y = a[1], z = a[2];
  double r = sqrt(x * x + y * y + z * z);
  switch (number) {
  case 25:
    return helix1(a);
  case 26:
    return helix2(a);
  case 29:
    return hetero_mf(a);
  case 59:
    return ridged_mf(a);
  case 76: /* f_noise3d */
    return zr__noise_lattice(zr_v3(x, y, z));
  case 78: /* f_noise_generator: generators 1, 2 and 3, measured */
    return zr__noise_generator(zr_v3(x, y, z), (int)a[3]);
  case 17: /* f_ellipsoid: inverse scales; threshold 1 */
    return sqrt(x * x * a[3] * a[3] + y * y * a[4] * a[4] +
                z * z * a[5] * a[5]);
  case 45: /* f_paraboloid: field strength */
    return field(a[3] * (y - x * x - z * z));
  case 47: /* f_ph */
    return r > 0 ? acos(y / r) : 0;
  case 57: /* f_r */
    return r;
  case 60: { /* f_rounded_box: corner radius, then half sizes */
    /* The distance to a box shrunk by the radius, less the radius;
       povray's values are 1e-6 below it at every point we measured
       (bench/provenance/probe.py rounded_box_offset). */
    double dx = fmax(fabs(x) - (a[4] - a[3]), 0);
    double dy = fmax(fabs(y) - (a[5] - a[3]), 0);
    double dz = fmax(fabs(z) - (a[6] - a[3]), 0);
    return sqrt(dx * dx + dy * dy + dz * dz) - a[3] - 1e-6;
  }
  case 61: /* f_sphere: radius */
    return r - a[3];
  case 68: { /* f_superellipsoid: east-west and north-south exponents */
    double e = a[3], n = a[4];
    double xy = pow(pow(fabs(x), 2 / e) + pow(fabs(y), 2 / e), e / n);
    return 1 - pow(xy + pow(fabs(z), 2 / n), n / 2);
  }
  case 69: /* f_th */
    return atan2(x, z);
  case 70: { /* f_torus: major and minor radius, about the y axis */
    double ring = sqrt(x * x + z * z) - a[3];
    return sqrt(ring * ring + y * y) - a[4];
  }
  case 71: { /* f_torus2: field strength, major and minor radius */
    double big = a[4] * a[4], q = r * r + big - a[5] * a[5];
    return field(-a[3] * (q * q - 4 * big * (x * x + z * z)));
  }
  default:
    return NAN; /* never: unimplemented numbers are refused earlier */
  }
}
