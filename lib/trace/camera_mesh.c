/*
 * camera_mesh.c - the rays of a mesh_camera (reference manual r3_4,
 * "Mesh projection").  The manual describes the idea; the details below
 * were measured on povray 3.7 renders of small meshes whose faces look at
 * a plane coloured by position (and a sphere coloured by direction), so
 * a pixel's colour tells which face shot it and where to:
 *
 *   - A face's ray leaves its centroid along its normal, which for a
 *     face with corners a, b, c points along (c - a) x (b - a) (the
 *     reverse of the normal the tracer gives the triangle), flat even
 *     when the mesh is smooth.  The camera's location moves the origin
 *     location.z along that normal; a direction with z < 0 reverses the
 *     ray.  The camera's transforms act on location and direction first
 *     (translate z*-6 is location <0,0,-6>); x and y are not used.
 *   - Pixel (x, y) of a W x H image takes face x + W * max(y - 1, 0) of
 *     distribution 0's mesh k for ray k, and the same face of the faces
 *     of all meshes in a row for distribution 1.  So povray's first two
 *     rows show the same faces and the last row of a W x H mesh is never
 *     seen; zRcube does the same.  Rays without a face are not shot; a
 *     pixel with none is black (transparent in povray).
 *   - Distribution 2 splits the image into n vertical strips, strip
 *     (x + 0.5) n / W using mesh number strip, face
 *     x + (W / n) * max(y - 1, 0) (W / n in whole numbers, x counted
 *     from the image's left edge, as povray does).
 *   - Distribution 3 maps sample point (sx, sy) (pixel units, centre
 *     x + 0.5) to u = min(sx - 0.5, W - 1.5) / W and
 *     v = 1 - max(sy - 0.5, 0.5) / H, and shoots from the first face of
 *     the first mesh whose uv triangle holds (u, v): from the point with
 *     the same barycentric coordinates, along the flat normal or, with
 *     smooth, the blend of the corners' unit normals.  (The clamps are
 *     povray's: its last column and first row repeat their neighbours'
 *     half-pixel.)
 *   - max_distance limits how far the ray looks for a surface; beyond
 *     it the ray sees the background.
 */
#include "trace/render.h"

#include <math.h>

#include "trace/obj_mesh.h"

int zr__camera_mesh_rays(const zr_camera *c) {
  return c->mesh->distribution == 0 ? c->mesh->rays_per_pixel : 1;
}

static zr_vec3 unit(zr_vec3 v) {
  double l = zr_v3_len(v);
  return l > 0.0 ? zr_v3_scale(v, 1.0 / l) : v;
}

/* The ray from point p (mesh space) along normal n (mesh space). */
static bool shoot(const zr_camera *c, const zr_camera_mesh *cm, zr_vec3 p,
                  zr_vec3 n, zr_ray *ray) {
  if (cm->transform) {
    p = zr__xform_point(cm->transform->m, p);
    n = zr__xform_normal(cm->transform->inv, n);
  }
  n = unit(n);
  if (!(zr_v3_len(n) > 0.0))
    return false; /* a degenerate face has no direction */
  ray->origin = zr_v3_madd(p, n, c->location.z);
  ray->dir = c->direction.z < -1e-10 ? zr_v3_neg(n) : n;
  return true;
}

static zr_vec3 flat_normal(const struct zr_mesh *d, size_t row) {
  const uint32_t *f = d->faces[row];
  zr_vec3 a = d->vertices[f[0]];
  return zr_v3_cross(zr_v3_sub(d->vertices[f[2]], a),
                     zr_v3_sub(d->vertices[f[1]], a));
}

/* Face i as written of mesh cm: from its centroid. */
static bool face_ray(const zr_camera *c, const zr_camera_mesh *cm,
                     size_t i, zr_ray *ray) {
  const struct zr_mesh *d = cm->data;
  if (i >= d->n_faces)
    return false;
  size_t row = d->face_row[i];
  const uint32_t *f = d->faces[row];
  zr_vec3 centroid = zr_v3_scale(
      zr_v3_add(zr_v3_add(d->vertices[f[0]], d->vertices[f[1]]),
                d->vertices[f[2]]),
      1.0 / 3.0);
  return shoot(c, cm, centroid, flat_normal(d, row), ray);
}

/* Barycentric weights of (u, v) in the uv triangle of a row; false
   when outside (with a little slack for points on an edge). */
static bool uv_weights(const struct zr_mesh *d, size_t row, double u,
                       double v, double w[3]) {
  const uint32_t *t = d->face_uvs[row];
  const double *a = d->uvs[t[0]], *b = d->uvs[t[1]], *e = d->uvs[t[2]];
  double e1u = b[0] - a[0], e1v = b[1] - a[1];
  double e2u = e[0] - a[0], e2v = e[1] - a[1];
  double det = e1u * e2v - e2u * e1v;
  if (!(fabs(det) > 0.0))
    return false;
  double pu = u - a[0], pv = v - a[1];
  double s = (pu * e2v - e2u * pv) / det;
  double r = (e1u * pv - pu * e1v) / det;
  const double eps = 1e-9;
  if (s < -eps || r < -eps || s + r > 1.0 + eps)
    return false;
  w[0] = 1.0 - s - r;
  w[1] = s;
  w[2] = r;
  return true;
}

static bool uv_ray(const zr_camera *c, double u, double v, zr_ray *ray) {
  const zr_mesh_camera *m = c->mesh;
  const zr_camera_mesh *cm = &m->meshes[0];
  const struct zr_mesh *d = cm->data;
  double cu = floor((u - m->grid_lo[0]) / m->cell_size[0]);
  double cv = floor((v - m->grid_lo[1]) / m->cell_size[1]);
  /* A point on the far edge of the box belongs to the last cell. */
  if (cu == m->grid)
    cu = m->grid - 1;
  if (cv == m->grid)
    cv = m->grid - 1;
  if (!(cu >= 0 && cv >= 0 && cu < m->grid && cv < m->grid))
    return false;
  size_t cell = (size_t)cv * (size_t)m->grid + (size_t)cu;
  for (uint32_t k = m->cell_start[cell]; k < m->cell_start[cell + 1]; k++) {
    size_t row = d->face_row[m->cell_faces[k]];
    double w[3];
    if (!uv_weights(d, row, u, v, w))
      continue;
    const uint32_t *f = d->faces[row];
    zr_vec3 p = zr_v3(0, 0, 0), n = zr_v3(0, 0, 0);
    for (int j = 0; j < 3; j++)
      p = zr_v3_madd(p, d->vertices[f[j]], w[j]);
    if (m->smooth && d->face_normals) {
      const uint32_t *ni = d->face_normals[row];
      for (int j = 0; j < 3; j++)
        n = zr_v3_madd(n, unit(d->normals[ni[j]]), w[j]);
    }
    if (!(zr_v3_len(n) > 0.0))
      n = flat_normal(d, row);
    return shoot(c, cm, p, n, ray);
  }
  return false;
}

bool zr__camera_mesh_ray(const zr_camera *c, int width, int height,
                         double sx, double sy, int k, zr_ray *ray) {
  const zr_mesh_camera *m = c->mesh;
  if (m->distribution == 3) {
    double x = fmin(sx - 0.5, width - 1.5), y = fmax(sy - 0.5, 0.5);
    return uv_ray(c, x / width, 1.0 - y / height, ray);
  }
  if (!(sx >= 0 && sy >= 0 && sx < width && sy < height))
    return false;
  size_t x = (size_t)sx, y = (size_t)sy;
  size_t row = y > 0 ? y - 1 : 0;
  switch (m->distribution) {
  case 0:
    if ((size_t)k >= m->n_meshes)
      return false;
    return face_ray(c, &m->meshes[k], row * (size_t)width + x, ray);
  case 1: {
    size_t i = row * (size_t)width + x;
    for (size_t j = 0; j < m->n_meshes; j++) {
      size_t n = m->meshes[j].data->n_faces;
      if (i < n)
        return face_ray(c, &m->meshes[j], i, ray);
      i -= n;
    }
    return false;
  }
  default: {
    size_t n = m->n_meshes;
    size_t strip = (size_t)(sx * (double)n / width);
    if (strip >= n)
      strip = n - 1;
    return face_ray(c, &m->meshes[strip], row * ((size_t)width / n) + x,
                    ray);
  }
  }
}
