/*
 * df3.c - the density_file pattern (reference manual, "Density File
 * Pattern"): a df3 file's voxels mapped onto the unit cube, 0 outside.
 *
 * A df3 file is three big-endian 16-bit sizes nx, ny, nz and then the
 * nx * ny * nz voxels, x varying fastest, of 1, 2 or 4 bytes each (the
 * size of the file says which), big-endian, scaled to [0, 1] by the
 * largest value of their width.  Without interpolation a point takes
 * its voxel's value (voxel i spans [i / n, (i + 1) / n)); interpolate 1
 * blends the eight voxels from the one holding the point to the next
 * ones up, wrapping round at the far faces, as POV-Ray 3.7 does
 * (interpolate 2, tricubic, is read as 1 and said so by the parser).
 */
#include "scene/df3.h"

#include <math.h>
#include <stdint.h>

zr_status zr__df3_decode(const unsigned char *bytes, size_t size,
                         zr_arena *arena, zr_density_file *out) {
  if (size < 6)
    return ZR_EFORMAT;
  int nx = bytes[0] << 8 | bytes[1], ny = bytes[2] << 8 | bytes[3];
  int nz = bytes[4] << 8 | bytes[5];
  size_t n = (size_t)nx * (size_t)ny * (size_t)nz;
  if (n == 0 || (size - 6) % n != 0)
    return ZR_EFORMAT;
  size_t width = (size - 6) / n;
  if (width != 1 && width != 2 && width != 4)
    return ZR_EFORMAT;
  float *v = zr__arena_alloc(arena, n * sizeof *v);
  if (!v)
    return ZR_ENOMEM;
  double top = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0;
  const unsigned char *p = bytes + 6;
  for (size_t i = 0; i < n; i++, p += width) {
    uint32_t x = 0;
    for (size_t k = 0; k < width; k++)
      x = x << 8 | p[k];
    v[i] = (float)(x / top);
  }
  out->nx = nx;
  out->ny = ny;
  out->nz = nz;
  out->values = v;
  return ZR_OK;
}

static double voxel(const zr_density_file *d, int x, int y, int z) {
  return d->values[((size_t)z * (size_t)d->ny + (size_t)y) * (size_t)d->nx +
                   (size_t)x];
}

double zr__df3_value(const zr_density_file *d, zr_vec3 p) {
  if (!d || !(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0 &&
              p.z >= 0.0 && p.z < 1.0))
    return 0.0;
  double xx = p.x * d->nx, yy = p.y * d->ny, zz = p.z * d->nz;
  int x1 = (int)xx, y1 = (int)yy, z1 = (int)zz;
  if (x1 >= d->nx || y1 >= d->ny || z1 >= d->nz)
    return 0.0;
  if (d->interpolate == 0)
    return voxel(d, x1, y1, z1);
  int x2 = (x1 + 1) % d->nx, y2 = (y1 + 1) % d->ny, z2 = (z1 + 1) % d->nz;
  double fx = xx - x1, fy = yy - y1, fz = zz - z1;
  double a = voxel(d, x1, y1, z1) * (1 - fx) + voxel(d, x2, y1, z1) * fx;
  double b = voxel(d, x1, y2, z1) * (1 - fx) + voxel(d, x2, y2, z1) * fx;
  double c = voxel(d, x1, y1, z2) * (1 - fx) + voxel(d, x2, y1, z2) * fx;
  double e = voxel(d, x1, y2, z2) * (1 - fx) + voxel(d, x2, y2, z2) * fx;
  double lo = a * (1 - fy) + b * fy, hi = c * (1 - fy) + e * fy;
  return lo * (1 - fz) + hi * fz;
}
