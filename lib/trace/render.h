/*
 * render.h - camera rays and antialiasing, the internal side of
 * zr_render_pixels().
 */
#ifndef ZR_TRACE_RENDER_H
#define ZR_TRACE_RENDER_H

#include "scene/scene.h"
#include "trace/intersect.h"
#include "trace/shade.h"

/*
 * The camera ray through image point (x, y), measured in pixels from the
 * top left corner of a width x height image: (x + 0.5, y + 0.5) is the
 * centre of pixel (x, y).  As in POV-Ray 3.7 the image spans exactly the
 * camera's right and up vectors whatever its aspect ratio.
 */
zr_ray zr__camera_ray(const zr_camera *camera, int width, int height,
                      double x, double y);

/*
 * The camera ray through image point (u, v), u right and v up in
 * [-0.5, 0.5], for any projection (lib/trace/camera.c); false where the
 * projection has no ray (outside a fisheye's circle), which renders
 * black.
 */
bool zr__camera_project(const zr_camera *camera, double u, double v,
                        zr_ray *ray);

/* A mesh_camera (lib/trace/camera_mesh.c): how many rays each sample of
   a pixel tries, and ray k through sample point (sx, sy) (pixels from
   the top left corner of a width x height image); false when that ray
   has no face, so is not shot. */
int zr__camera_mesh_rays(const zr_camera *camera);
bool zr__camera_mesh_ray(const zr_camera *camera, int width, int height,
                         double sx, double sy, int k, zr_ray *ray);

/* Moves *ray (a pinhole camera ray) to a point of the lens chosen by a
   and b in [0, 1), aimed at the focal plane: one focal blur sample. */
bool zr__camera_focal_sample(const zr_camera *camera, zr_ray *ray,
                             double a, double b);

/* The objects that enclose the camera's location, outermost first. */
void zr__camera_media(const zr_scene *scene, zr_media *media);

/* The Antialias_Gamma default ("Anti-Aliasing Options", 3.2.8.7). */
#define ZR_AA_GAMMA 2.5
/* The Render_Block_Size default ("Render Block Size", 3.2.8.2). */
#define ZR_AA_BLOCK 32

/* The colour difference for antialiasing ("Anti-Aliasing Options",
   3.2.8.7): the sum of the absolute differences of the red, green and
   blue values, each clipped to [0, 1] and raised to exponent
   (assumed_gamma / antialias gamma, the manual's gamma-adjusted
   comparison). */
double zr__colour_difference(const float *a, const float *b,
                             double exponent);

/* A uniform number in [0, 1) that depends only on its three arguments,
   for jitter that is the same however pixels are shared out. */
double zr__hash_uniform(uint32_t pixel, uint32_t sample, uint32_t axis);

#endif /* ZR_TRACE_RENDER_H */
