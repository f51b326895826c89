/*
 * meshimage.c - a picture of the radiosity mesh: each element flat at
 * its radiosity with the element edges drawn over it, the job the
 * seed's OpenGL previewer did (showing where refinement split the
 * surfaces: shadow edges, the rim of a spotlight, corners).
 *
 * It is a plain one-ray-per-pixel render: the camera ray through each
 * pixel centre (lib/trace/render.c) finds the nearest object in the
 * tracer's BVH, and the hit's (object, u, v) names the leaf element
 * that holds it, as the lookup of radiosity.c does.  Edges are found in
 * image space: a pixel whose element differs from its right or lower
 * neighbour's lies on an element edge (or on a silhouette, which is an
 * edge of the surface), so lines are one pixel wide at any distance and
 * a region meshed finer than the pixels shows solid edge colour.  The
 * element shows its full radiosity B (emission, reflected direct light
 * of light sources and interreflection, without the brightness
 * setting), the value the solver computed, rather than the final
 * render's mix.  The picture depends only on the solution, the camera
 * and the size, so it is the same on every rank.
 */
#include "radiosity/radiosity.h"

#include <stdlib.h>
#include <string.h>

#include "trace/bvh.h"
#include "trace/render.h"

/* Leaf indices are >= 0; these mark the pixels that show none. */
enum { NO_SURFACE = -1, NO_RAY = -2 };

/* The leaf (and side) seen through the centre of pixel (x, y). */
static int32_t pixel_leaf(const zr_radiosity *rad, const zr_render_params *p,
                          int x, int y, int *side) {
  const zr_scene *scene = rad->scene;
  zr_ray ray = zr__camera_ray(&scene->camera, p->width, p->height, x + 0.5,
                              y + 0.5);
  if (zr_v3_len(ray.dir) == 0.0)
    return NO_RAY;
  zr_hit hit;
  if (scene->bvh == NULL ||
      !zr__bvh_nearest(scene->bvh, &ray, 0.0, INFINITY, &hit))
    return NO_SURFACE;
  zr_vec3 point = zr_v3_madd(ray.origin, ray.dir, hit.t);
  int32_t leaf = zr__rad_hit_leaf(rad, hit.object, point, ray.dir, side);
  return leaf >= 0 ? leaf : NO_SURFACE;
}

ZR_API zr_status zr_radiosity_mesh_image(const zr_radiosity *rad,
                                         const zr_render_params *params,
                                         float *rgb) {
  if (rad == NULL || params == NULL || rgb == NULL || params->width <= 0 ||
      params->height <= 0 ||
      (uint64_t)params->width * (uint64_t)params->height > UINT32_MAX)
    return ZR_EINVAL;
  size_t w = (size_t)params->width, h = (size_t)params->height;
  /* Leaf and side of each pixel: 2 * leaf + side, or a negative mark. */
  int64_t *id = malloc(w * h * sizeof *id);
  if (id == NULL)
    return ZR_ENOMEM;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++) {
      int side = 0;
      int32_t leaf = pixel_leaf(rad, params, (int)x, (int)y, &side);
      id[y * w + x] = leaf >= 0 ? 2 * (int64_t)leaf + side : leaf;
      float *out = rgb + 3 * (y * w + x);
      out[0] = out[1] = out[2] = 0.0f;
      if (leaf >= 0)
        for (int c = 0; c < 3; c++)
          out[c] = (float)(fmax(0.0, rad->nodes[leaf].b[side][c]) / M_PI);
    }
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++) {
      int64_t me = id[y * w + x];
      bool edge = (x + 1 < w && id[y * w + x + 1] != me) ||
                  (y + 1 < h && id[(y + 1) * w + x] != me);
      if (!edge || me == NO_RAY)
        continue;
      float *out = rgb + 3 * (y * w + x);
      /* Linear luminance (Rec. 709 weights), clipped to [0, 1]. */
      double lum = 0.2126 * fmin(1.0, out[0]) + 0.7152 * fmin(1.0, out[1]) +
                   0.0722 * fmin(1.0, out[2]);
      float ink = lum > 0.2 ? 0.0f : 1.0f;
      out[0] = out[1] = out[2] = ink;
    }
  free(id);
  return ZR_OK;
}
