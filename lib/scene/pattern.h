/*
 * pattern.h - POV-Ray's patterns: noise, turbulence, wave forms and the
 * pattern functions themselves, evaluated in pattern space.
 */
#ifndef ZR_SCENE_PATTERN_H
#define ZR_SCENE_PATTERN_H

#include "core/vec.h"
#include "scene/scene.h"

/* POV-Ray's pattern defaults for kind: frequency 1, phase 0, octaves 6,
   omega 0.5, lambda 2, brick_size <8,3,4.5>, mortar 0.5, agate_turb 1,
   gradient along x. */
void zr__pattern_init(zr_pattern *pt, zr_pattern_kind kind);
/* A new kind named in a pattern that may have modifiers already (a
   pigment or normal block modifying another): the kind's own parameters
   take their defaults, the pattern modifiers (turbulence, octaves,
   omega, lambda, frequency, phase, the wave type, warps) stay, as
   POV-Ray 3.7 draws it (tests/test_pigment_keep.sh).  On a pattern that
   zr__pattern_init made, the same as zr__pattern_init. */
void zr__pattern_set_kind(zr_pattern *pt, zr_pattern_kind kind);

/* POV-Ray's noise (noise_generator 2, lib/core/noise.c), about
   [0.1, 0.9] with mean 0.5. */
double zr__noise(zr_vec3 p);
/* The noise of a noise_generator 1, 2 or 3, POV-Ray's (measured), 0 the
   default 2. */
double zr__noise_gen(zr_vec3 p, int generator);
/* Turbulence's vector noise (lib/core/noise.c), each component in about
   [-1, 1]. */
zr_vec3 zr__dnoise(zr_vec3 p);
/* The fractal sum of dnoise over octaves (omega, lambda): turbulence's
   displacement before it is scaled by the turbulence vector. */
zr_vec3 zr__dturbulence(zr_vec3 p, int octaves, double omega,
                        double lambda);
/* The scalar fractal sum at p over octaves i of omega^i (2 n(lambda^i p)
   - 0.5), n the noise, only the first term clamped to [0, 1]: agate's
   sum, and the one a turbulent fog thins by (lib/trace/atmosphere.c). */
double zr__turbulence_scalar(zr_vec3 p, int octaves, double omega,
                             double lambda);

/* Applies the wave form after frequency and phase ("Frequency and
   Phase", "Waveforms"): the value a colour map is indexed with. */
double zr__pattern_wave(const zr_pattern *pt, double value);

/*
 * The pattern's value at p (pattern space): turbulence, the pattern
 * function, then frequency, phase and wave.  In [0, 1], except block
 * patterns, which give their colour index (checker 0/1, hexagon 0/1/2,
 * brick 0 for mortar, 1 for brick).
 */
double zr__pattern_eval(const zr_pattern *pt, zr_vec3 p);
/* The point the pattern function sees for p (pattern space): after the
   pattern's warps and its turbulence. */
zr_vec3 zr__pattern_point(const zr_pattern *pt, zr_vec3 p);

/* For ripples and waves normals: the mean over the wave centres of the
   unit vector from the centre to p (pattern space, after
   zr__pattern_point) times the sine of that wave's phase divided by
   its spatial frequency (see pattern.c's wave_sum()), over the first
   zr__pattern_wave_count() centres in povray's order. */
zr_vec3 zr__pattern_wave_normal(const zr_pattern *pt, zr_vec3 p);
/* The number of waves a ripples or waves normal sums: number_of_waves,
   at most the 10 centres measured (more are not reproduced). */
int zr__pattern_wave_count(const zr_pattern *pt);

/* The relief a quilted normal tilts by at p (pattern space, after
   zr__pattern_point): not the quilted pigment's value, see pattern.c. */
double zr__pattern_quilt_relief(const zr_pattern *pt, zr_vec3 p);
/* The same at a surface point whose unit normal in world space is n,
   for the patterns that use it (slope); others ignore n. */
double zr__pattern_eval_n(const zr_pattern *pt, zr_vec3 p, zr_vec3 n);

/* mandel and julia (with magnet) and the function pattern before the
   wave (lib/scene/pattern_more.c). */
double zr__pattern_fractal(const zr_pattern *pt, zr_vec3 p);
double zr__pattern_function(const zr_pattern *pt, zr_vec3 p);
/* The tiling pattern number (lib/scene/pattern_tiling.c), before the
   wave: (type + bevel) / types; 0 for a number it does not know. */
double zr__pattern_tiling(int number, zr_vec3 p);
/* Whether tiling number is one of those implemented. */
bool zr__pattern_tiling_known(int number);
/* The object pattern: 1 inside pt->object, else 0. */
double zr__pattern_object(const zr_pattern *pt, zr_vec3 p);
/* The value of pg's pattern at a world point, through pg's transform:
   what function { pattern { ... } } gives. */
double zr__pigment_pattern_value(const zr_pigment *pg, zr_vec3 world);

/* Whether kind is a block pattern (a colour list, no colour map). */
bool zr__pattern_is_block(zr_pattern_kind kind);

#endif /* ZR_SCENE_PATTERN_H */
