/*
 * camera.c - camera rays for POV-Ray 3.7's projections (reference
 * manual, "Camera": "Types of Projection", "Focal Blur", "Camera Ray
 * Perturbation").
 *
 * An image point has coordinates u (right) and v (up) in [-0.5, 0.5];
 * D, R and U are the camera's direction, right and up vectors and a hat
 * marks a unit vector.  The manual describes each projection in words;
 * the formulas below were fitted to povray 3.7 renders of a scene that
 * encodes the ray direction in the pixel colour (a large sphere round
 * the camera whose pigment is a gradient along x, y or z, written as
 * 16-bit images), and agree with them to 1e-4 in every pixel:
 *   perspective       D + u R + v U from location.
 *   orthographic      direction D from location + u R + v U.  Without
 *                     up or right in the block, or with angle, R and U
 *                     are first scaled so the view matches a
 *                     perspective camera's at the look_at distance
 *                     (build_camlight.c does that).
 *   fisheye           r = |(u |R|, v |U|)|; beyond r = 0.5 no ray (black);
 *                     else the angle from D-hat is r * angle (90 unless
 *                     given) toward that point's direction on the image.
 *   ultra_wide_angle  x = u * angle, y = v * angle * |U| / |R|;
 *                     sin x R-hat + sin y U-hat + cos x cos y D-hat.
 *   panoramic         x = u * 180, y = v * 180 degrees;
 *                     cos y (cos x D + sin x R) + sin y U, the vectors at
 *                     their lengths (the manual's ellipsoid).
 *   cylinder 1        cos x D-hat + sin x R-hat + v U, x = u * angle.
 *   cylinder 2        cos y D-hat + sin y U-hat + u R, y = v * angle.
 *   cylinder 3        cos x D-hat + sin x R-hat from location + v U.
 *   cylinder 4        cos y D-hat + sin y U-hat from location + u R.
 *   spherical         longitude u * h, latitude v * v_angle (360 and
 *                     half of h unless given) on the unit vectors.
 *   omnimax           a fisheye about D, in image units scaled by
 *                     a = |R| / |U| across: x = u a, y = v - v0, angle
 *                     from D-hat theta(rho) toward (x, y) on R-hat, U-hat,
 *                     rho = |(x, y)| / r90, where the lens curve
 *                     theta = 1.411284 rho - 0.094448 rho^3
 *                     + 0.256789 rho^5 (radians; a fit to 0.011 degrees)
 *                     reaches 90 degrees near rho = 1.  The 90 degree
 *                     circle spans the width and touches the top:
 *                     r90 = a / 2, v0 = 0.5 - r90, but for a < 1 it is
 *                     centred (v0 = 0) and from a = 1.28344 on it stays
 *                     as wide as there, where the bottom edge is 45
 *                     degrees below D.  No ray (black) beyond rho = 1,
 *                     nor below the plane 45 degrees under D (the ray's
 *                     U and D parts sum below zero).  The mask of every
 *                     render measured (a = 0.75 to 2.67) agrees pixel
 *                     for pixel, the directions within 0.011 degrees.
 *                     The manual gives no curve: the constants are a
 *                     least-squares fit to povray's rays, which
 *                     bench/provenance/probe.py omnimax_curve measures
 *                     and fits again.
 *
 * Focal blur moves each sample's origin within a lens disc of radius
 * aperture / 4 (not the diameter the word suggests: measured, povray's
 * image of a point far behind the focal plane spreads over a disc that
 * size, whatever the direction, right, up and focal distance;
 * bench/conform/focal_blur_probe.sh, tests/test_focal_blur.sh) across
 * R-hat and U-hat and aims it at the point where the pinhole ray
 * crosses the focal plane (through focal_point, normal to D).  Sample k of a pixel uses a hash of (pixel, k): a picture is the
 * same on any number of threads or ranks.  A normal { } on the camera
 * tilts each ray's unit direction as a surface normal would be tilted,
 * with the pattern taken at the point (u, v, 0) of the screen, u from
 * -0.5 (left) to 0.5 (right) and v from -0.5 (bottom) to 0.5 (top)
 * whatever the aspect ratio, camera location or orientation, and the
 * tilt in world axes (measured: povray's ray directions under
 * function { 0.5+0.1*x*x }, y*y, z*z, on a moved and a turned camera,
 * within 0.004 degrees; tests/test_camera_normal.sh keeps five cases).
 */
#include "trace/render.h"

#include <math.h>

#include "scene/texture.h"

static const double DEG = 3.14159265358979323846 / 180.0;

/* The omnimax lens curve (see above) and the widest its circle gets. */
/* Measured (bench/provenance/probe.py omnimax_curve; see above). */
static const double OMNIMAX_CURVE[3] = {1.411284, -0.094448, 0.256789};
static const double OMNIMAX_WIDEST = 1.28344;

static bool omnimax(const zr_camera *c, double u, double v, zr_vec3 dn,
                    zr_vec3 rn, zr_vec3 un, zr_vec3 *d) {
  double ul = zr_v3_len(c->up);
  double a = ul > 0.0 ? zr_v3_len(c->right) / ul : 1.0;
  double span = a < 1.0 ? 1.0 : a > OMNIMAX_WIDEST ? OMNIMAX_WIDEST : a;
  double r90 = 0.5 * fmin(a, span), v0 = -0.5 * (span - 1.0);
  double x = u * a, y = v - v0, r = sqrt(x * x + y * y);
  double rho = r / r90;
  if (!(rho <= 1.0))
    return false;
  double rho2 = rho * rho;
  double theta =
      rho * (OMNIMAX_CURVE[0] +
             rho2 * (OMNIMAX_CURVE[1] + rho2 * OMNIMAX_CURVE[2]));
  double s = sin(theta), cx = r > 0.0 ? x / r : 0.0;
  double cy = r > 0.0 ? y / r : 0.0;
  if (s * cy + cos(theta) < 0.0)
    return false; /* more than 45 degrees below the direction */
  *d = zr_v3_add(zr_v3_scale(dn, cos(theta)),
                 zr_v3_add(zr_v3_scale(rn, s * cx), zr_v3_scale(un, s * cy)));
  return true;
}

static zr_vec3 unit_or(zr_vec3 v, zr_vec3 fallback) {
  double l = zr_v3_len(v);
  return l > 0.0 ? zr_v3_scale(v, 1.0 / l) : fallback;
}

bool zr__camera_project(const zr_camera *c, double u, double v,
                        zr_ray *ray) {
  zr_vec3 o = c->location, d;
  /* The unit frame only for the cameras that bend their rays by angles:
     three square roots a pixel that the perspective and orthographic
     cameras never use (1.5% of bench/peers.sh's sphereflake). */
  zr_vec3 dn = zr_v3(0, 0, 1), rn = zr_v3(1, 0, 0), un = zr_v3(0, 1, 0);
  if (c->kind == ZR_CAMERA_FISHEYE || c->kind == ZR_CAMERA_OMNIMAX ||
      c->kind == ZR_CAMERA_ULTRA_WIDE_ANGLE ||
      c->kind == ZR_CAMERA_CYLINDER || c->kind == ZR_CAMERA_SPHERICAL) {
    dn = unit_or(c->direction, dn);
    rn = unit_or(c->right, rn);
    un = unit_or(c->up, un);
  }
  double h = c->h_angle * DEG, va = c->v_angle * DEG;
  switch (c->kind) {
  case ZR_CAMERA_ORTHOGRAPHIC:
    o = zr_v3_madd(zr_v3_madd(o, c->right, u), c->up, v);
    d = c->direction;
    break;
  case ZR_CAMERA_FISHEYE: {
    double x = u * zr_v3_len(c->right), y = v * zr_v3_len(c->up);
    double r = sqrt(x * x + y * y);
    if (r > 0.5)
      return false;
    double theta = r * h, s = sin(theta);
    double cx = r > 0.0 ? x / r : 0.0, cy = r > 0.0 ? y / r : 0.0;
    d = zr_v3_add(zr_v3_scale(dn, cos(theta)),
                  zr_v3_add(zr_v3_scale(rn, s * cx), zr_v3_scale(un, s * cy)));
    break;
  }
  case ZR_CAMERA_OMNIMAX:
    if (!omnimax(c, u, v, dn, rn, un, &d))
      return false;
    break;
  case ZR_CAMERA_ULTRA_WIDE_ANGLE: {
    double ratio = zr_v3_len(c->up) / zr_v3_len(c->right);
    double x = u * h, y = v * h * ratio;
    d = zr_v3_add(zr_v3_add(zr_v3_scale(rn, sin(x)), zr_v3_scale(un, sin(y))),
                  zr_v3_scale(dn, cos(x) * cos(y)));
    break;
  }
  case ZR_CAMERA_PANORAMIC: {
    double x = u * 180.0 * DEG, y = v * 180.0 * DEG;
    d = zr_v3_add(zr_v3_scale(zr_v3_add(zr_v3_scale(c->direction, cos(x)),
                                        zr_v3_scale(c->right, sin(x))),
                              cos(y)),
                  zr_v3_scale(c->up, sin(y)));
    break;
  }
  case ZR_CAMERA_CYLINDER: {
    double x = u * h, y = v * h;
    switch (c->cylinder_type) {
    case 1:
      d = zr_v3_add(zr_v3_add(zr_v3_scale(dn, cos(x)), zr_v3_scale(rn, sin(x))),
                    zr_v3_scale(c->up, v));
      break;
    case 2:
      d = zr_v3_add(zr_v3_add(zr_v3_scale(dn, cos(y)), zr_v3_scale(un, sin(y))),
                    zr_v3_scale(c->right, u));
      break;
    case 3:
      o = zr_v3_madd(o, c->up, v);
      d = zr_v3_add(zr_v3_scale(dn, cos(x)), zr_v3_scale(rn, sin(x)));
      break;
    default:
      o = zr_v3_madd(o, c->right, u);
      d = zr_v3_add(zr_v3_scale(dn, cos(y)), zr_v3_scale(un, sin(y)));
      break;
    }
    break;
  }
  case ZR_CAMERA_SPHERICAL: {
    double lon = u * h, lat = v * va;
    d = zr_v3_add(zr_v3_scale(zr_v3_add(zr_v3_scale(dn, cos(lon)),
                                        zr_v3_scale(rn, sin(lon))),
                              cos(lat)),
                  zr_v3_scale(un, sin(lat)));
    break;
  }
  default: /* perspective (a mesh camera's rays are camera_mesh.c's) */
    d = zr_v3_madd(zr_v3_madd(c->direction, c->right, u), c->up, v);
    break;
  }
  if (c->normal) {
    zr_vec3 dir = zr_v3_norm(d);
    d = zr__normal_perturb(c->normal, zr_v3(u, v, 0.0), dir);
  }
  ray->origin = o;
  ray->dir = d;
  return true;
}

bool zr__camera_focal_sample(const zr_camera *c, zr_ray *ray, double a,
                             double b) {
  if (!(c->aperture > 0.0))
    return true;
  zr_vec3 dn = unit_or(c->direction, zr_v3(0, 0, 1));
  double along = zr_v3_dot(ray->dir, dn);
  if (!(fabs(along) > 0.0))
    return true;
  double t = zr_v3_dot(zr_v3_sub(c->focal_point, ray->origin), dn) / along;
  zr_vec3 focus = zr_v3_madd(ray->origin, ray->dir, t);
  /* A uniform point on the lens disc from two numbers in [0, 1). */
  double r = 0.25 * c->aperture * sqrt(a), phi = 2.0 * M_PI * b;
  zr_vec3 rn = unit_or(c->right, zr_v3(1, 0, 0));
  zr_vec3 un = unit_or(c->up, zr_v3(0, 1, 0));
  zr_vec3 o = zr_v3_madd(zr_v3_madd(ray->origin, rn, r * cos(phi)), un,
                         r * sin(phi));
  ray->dir = zr_v3_sub(focus, o);
  if (t < 0.0)
    ray->dir = zr_v3_neg(ray->dir);
  ray->origin = o;
  return true;
}
