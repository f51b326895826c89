/*
 * noise.h - POV-Ray 3.7's noise functions, measured (see noise.c).
 */
#ifndef ZR_CORE_NOISE_H
#define ZR_CORE_NOISE_H

#include <stdint.h>

#include "core/vec.h"

/* The noise of noise_generator 2 (POV-Ray's default) at p, in about
   [0.1, 0.9]: what f_noise3d and the bozo pattern give. */
double zr__noise_lattice(zr_vec3 p);
/* The 12-bit lattice hash of the cell (x, y, z) with the coordinates
   moved by offset (the noise's and crackle's differ). */
/* POV-Ray's lattice cell of a coordinate: floor(v) in the 32-bit range,
   -2^31 outside it and for NaN (measured: f_noise3d, turbulence and
   cells far out). */
int64_t zr__noise_cell(double v);

unsigned zr__noise_hash(int64_t x, int64_t y, int64_t z, int offset);
/* zr__noise_hash of the (2 reach + 1)^3 cells (x + i, y + j, z + k),
   i, j, k from -reach to reach, into out in that order (k fastest):
   the same values, with the lookups the cells share made once. */
void zr__noise_hash_block(int64_t x, int64_t y, int64_t z, int offset,
                          int reach, unsigned *out);
/* crackle's two smallest squared distances from p to the feature
   points (x + o[0], y + o[1], z + o[2]) of the 27 cells (x, y, z)
   around p's own, o = points[zr__noise_hash(x, y, z, offset)], into
   d[0] <= d[1] (with AVX2 four cells at a time, the same numbers). */
void zr__noise_nearest2(zr_vec3 p, const double (*points)[3], int offset,
                        double d[2]);
/* Turbulence's vector noise at p, each component in about [-1, 1]. */
zr_vec3 zr__dnoise_lattice(zr_vec3 p);
/* The sum over octaves i of omega^i zr__dnoise_lattice(lambda^i p):
   turbulence's displacement before its scale (omega and lambda as the
   caller rounds them). */
zr_vec3 zr__dturbulence_lattice(zr_vec3 p, int octaves, double omega,
                                double lambda);
/* noise_generator 3's noise at p, about [0.1, 0.9]. */
double zr__noise_gen3(zr_vec3 p);
/* The noise of generator 1, 2 or 3 (any other number: 2). */
double zr__noise_generator(zr_vec3 p, int generator);
/* zr__noise_generator of the n points p[i] into out[i], the same
   values: with AVX2, four points at a time (the octaves of granite,
   wrinkles and agate). */
void zr__noise_generator_n(const zr_vec3 *p, int n, int generator,
                           double *out);

#endif /* ZR_CORE_NOISE_H */
