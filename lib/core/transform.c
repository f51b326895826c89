/*
 * transform.c - affine transforms for POV-Ray's scale, rotate, translate
 * and matrix modifiers (POV-Ray 3.7 reference, "Transformations").
 *
 * Each elementary transform is built together with its exact inverse, so
 * composing never needs a general matrix inversion except for "matrix",
 * where the 3x3 part is inverted by cofactors.
 */
#include "core/transform.h"

#include <math.h>
#include <string.h>

static void set_identity(double m[4][4]) {
  memset(m, 0, sizeof(double) * 16);
  for (int i = 0; i < 4; i++)
    m[i][i] = 1.0;
}

void zr__transform_identity(zr_transform *t) {
  set_identity(t->m);
  set_identity(t->inv);
}

bool zr__transform_is_identity(const zr_transform *t) {
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      if (t->m[i][j] != (i == j ? 1.0 : 0.0))
        return false;
  return true;
}

/* r = a * b for 4x4 matrices; r may alias neither. */
static void mat_mul(double r[4][4], const double a[4][4],
                    const double b[4][4]) {
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) {
      double s = 0.0;
      for (int k = 0; k < 4; k++)
        s += a[i][k] * b[k][j];
      r[i][j] = s;
    }
}

/* Applies the elementary transform (e, e_inv) after t. */
static void apply(zr_transform *t, const double e[4][4],
                  const double e_inv[4][4]) {
  double m[4][4], inv[4][4];
  mat_mul(m, e, t->m);
  mat_mul(inv, t->inv, e_inv);
  memcpy(t->m, m, sizeof m);
  memcpy(t->inv, inv, sizeof inv);
}

void zr__transform_scale(zr_transform *t, zr_vec3 s) {
  double e[4][4], ei[4][4];
  set_identity(e);
  set_identity(ei);
  e[0][0] = s.x;
  e[1][1] = s.y;
  e[2][2] = s.z;
  ei[0][0] = 1.0 / s.x;
  ei[1][1] = 1.0 / s.y;
  ei[2][2] = 1.0 / s.z;
  apply(t, e, ei);
}

void zr__transform_translate(zr_transform *t, zr_vec3 d) {
  double e[4][4], ei[4][4];
  set_identity(e);
  set_identity(ei);
  e[0][3] = d.x;
  e[1][3] = d.y;
  e[2][3] = d.z;
  ei[0][3] = -d.x;
  ei[1][3] = -d.y;
  ei[2][3] = -d.z;
  apply(t, e, ei);
}

/*
 * One rotation about an axis by degrees, POV-Ray's left-hand rule: with
 * the left thumb along the axis, the fingers curl the positive way, so
 * rotate <0, 90, 0> takes +x to -z and rotate <90, 0, 0> takes +y to +z.
 */
static void rotate_axis(zr_transform *t, int axis, double degrees) {
  if (degrees == 0.0)
    return;
  double a = degrees * (M_PI / 180.0);
  double c = cos(a), s = sin(a);
  /* Exact values at multiples of 90 degrees keep boxes axis-aligned. */
  if (fmod(degrees, 90.0) == 0.0) {
    c = round(c);
    s = round(s);
  }
  double e[4][4], ei[4][4];
  set_identity(e);
  int i = (axis + 1) % 3, j = (axis + 2) % 3;
  e[i][i] = c;
  e[i][j] = -s;
  e[j][i] = s;
  e[j][j] = c;
  /* The inverse of a rotation is its transpose. */
  set_identity(ei);
  ei[i][i] = c;
  ei[i][j] = s;
  ei[j][i] = -s;
  ei[j][j] = c;
  apply(t, e, ei);
}

void zr__transform_rotate(zr_transform *t, zr_vec3 degrees) {
  rotate_axis(t, 0, degrees.x);
  rotate_axis(t, 1, degrees.y);
  rotate_axis(t, 2, degrees.z);
}

bool zr__transform_matrix(zr_transform *t, const double v[12]) {
  double e[4][4], ei[4][4];
  set_identity(e);
  /* POV-Ray's rows are the images of the axes: transpose them. */
  for (int row = 0; row < 3; row++)
    for (int col = 0; col < 3; col++)
      e[col][row] = v[row * 3 + col];
  e[0][3] = v[9];
  e[1][3] = v[10];
  e[2][3] = v[11];
  double c00 = e[1][1] * e[2][2] - e[1][2] * e[2][1];
  double c01 = e[1][2] * e[2][0] - e[1][0] * e[2][2];
  double c02 = e[1][0] * e[2][1] - e[1][1] * e[2][0];
  double det = e[0][0] * c00 + e[0][1] * c01 + e[0][2] * c02;
  if (!(fabs(det) > 1e-300))
    return false;
  double id = 1.0 / det;
  set_identity(ei);
  ei[0][0] = c00 * id;
  ei[1][0] = c01 * id;
  ei[2][0] = c02 * id;
  ei[0][1] = (e[0][2] * e[2][1] - e[0][1] * e[2][2]) * id;
  ei[1][1] = (e[0][0] * e[2][2] - e[0][2] * e[2][0]) * id;
  ei[2][1] = (e[0][1] * e[2][0] - e[0][0] * e[2][1]) * id;
  ei[0][2] = (e[0][1] * e[1][2] - e[0][2] * e[1][1]) * id;
  ei[1][2] = (e[0][2] * e[1][0] - e[0][0] * e[1][2]) * id;
  ei[2][2] = (e[0][0] * e[1][1] - e[0][1] * e[1][0]) * id;
  for (int i = 0; i < 3; i++)
    ei[i][3] = -(ei[i][0] * e[0][3] + ei[i][1] * e[1][3] +
                 ei[i][2] * e[2][3]);
  apply(t, e, ei);
  return true;
}

void zr__transform_compose(zr_transform *t, const zr_transform *then) {
  apply(t, then->m, then->inv);
}

void zr__transform_invert(zr_transform *t) {
  double tmp[4][4];
  memcpy(tmp, t->m, sizeof tmp);
  memcpy(t->m, t->inv, sizeof tmp);
  memcpy(t->inv, tmp, sizeof tmp);
}

zr_vec3 zr__xform_point(const double m[4][4], zr_vec3 p) {
  return zr_v3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
               m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
               m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

zr_vec3 zr__xform_dir(const double m[4][4], zr_vec3 d) {
  return zr_v3(m[0][0] * d.x + m[0][1] * d.y + m[0][2] * d.z,
               m[1][0] * d.x + m[1][1] * d.y + m[1][2] * d.z,
               m[2][0] * d.x + m[2][1] * d.y + m[2][2] * d.z);
}

zr_vec3 zr__xform_normal(const double inv[4][4], zr_vec3 n) {
  return zr_v3(inv[0][0] * n.x + inv[1][0] * n.y + inv[2][0] * n.z,
               inv[0][1] * n.x + inv[1][1] * n.y + inv[2][1] * n.z,
               inv[0][2] * n.x + inv[1][2] * n.y + inv[2][2] * n.z);
}
