/*
 * transform.h - affine transforms as 4x4 matrices with their inverses.
 *
 * POV-Ray's scale, rotate, translate and matrix modifiers compose on the
 * left: "scale 2 translate x" first scales, then translates.  A transform
 * keeps its inverse so rays go to object space without inverting per ray.
 * rotate <a,b,c> turns about x, then y, then z by degrees, left-handed
 * (POV-Ray reference, "Rotate").
 */
#ifndef ZR_CORE_TRANSFORM_H
#define ZR_CORE_TRANSFORM_H

#include <stdbool.h>

#include "core/vec.h"

typedef struct zr_transform {
  double m[4][4];   /* object to world; bottom row 0 0 0 1 */
  double inv[4][4]; /* world to object */
} zr_transform;

void zr__transform_identity(zr_transform *t);
bool zr__transform_is_identity(const zr_transform *t);
void zr__transform_scale(zr_transform *t, zr_vec3 s);
void zr__transform_translate(zr_transform *t, zr_vec3 d);
/* Degrees about x, then y, then z. */
void zr__transform_rotate(zr_transform *t, zr_vec3 degrees);
/*
 * POV-Ray's matrix <m00..m32>: the 12 values in POV-Ray order (column of
 * the point rows first three, then translation).  Returns false when the
 * matrix is singular.
 */
bool zr__transform_matrix(zr_transform *t, const double v[12]);
/* t = then after t (apply t first, then 'then'). */
void zr__transform_compose(zr_transform *t, const zr_transform *then);
/* Swaps m and inv. */
void zr__transform_invert(zr_transform *t);

zr_vec3 zr__xform_point(const double m[4][4], zr_vec3 p);
zr_vec3 zr__xform_dir(const double m[4][4], zr_vec3 d);
/* Normals transform by the inverse transpose: pass t->inv. */
zr_vec3 zr__xform_normal(const double inv[4][4], zr_vec3 n);

#endif /* ZR_CORE_TRANSFORM_H */
