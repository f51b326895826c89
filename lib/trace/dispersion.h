/* dispersion.h - the spectrum a refracted ray is split into where an
   interior has dispersion (lib/trace/dispersion.c; used by shade.c). */
#ifndef ZR_TRACE_DISPERSION_H
#define ZR_TRACE_DISPERSION_H

#include "scene/scene.h"

/* Whether in splits the rays refracted into or out of it. */
static inline bool zr__disperses(const zr_interior *in) {
  return in && in->ior_given && in->dispersion != 1.0 &&
         in->dispersion > 0.0;
}

/* The colour that sample i of n (0: red) carries; the n colours add up
   to (0.9938, 1, 0.9962), as in POV-Ray 3.7. */
zr_rgb zr__dispersion_colour(int i, int n);

/* Where sample i of n lies in the spectrum, -0.5 (red) to 0.5 (violet):
   its ior is ior * dispersion^u. */
double zr__dispersion_u(int i, int n);

/* The ior of in for a ray at u of the spectrum (in's own ior where it
   does not disperse; 1 for no interior). */
double zr__dispersed_ior(const zr_interior *in, double u);

#endif
