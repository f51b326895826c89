/*
 * build_meshcam.c - the parser's side of mesh_camera { } (reference
 * manual r3_4, "Mesh projection"), checked the way povray 3.7 checks it:
 *
 *   - rays per pixel and the distribution type are whole numbers
 *     (povray truncates 1.5 and 2.5 without a word, and so do we); at
 *     least one ray, distribution 0 to 3.
 *   - distribution 0 needs as many meshes as rays per pixel;
 *     distributions 2 and 3 shoot one ray per pixel; smooth goes with
 *     distribution 3 only.  povray refuses all three at parse time.
 *   - distribution 1 with more than one ray per pixel renders as with
 *     one in povray 3.7 (measured: the second ray's face, at
 *     W * H + pixel, never shows), so zRcube shoots one and says so.
 *   - distribution 3 finds a pixel's face from the uv_vectors of the
 *     first mesh: without them no pixel has a face, which is an error
 *     here rather than a black picture.
 *
 * The meshes are mesh or mesh2 objects, usually "mesh { M transforms }"
 * of a declared mesh; only their shared triangle data and transform are
 * kept.  For distribution 3 the first mesh's faces are sorted into a
 * grid over the uv box of its faces (about one face a cell), so finding
 * the first face that holds a pixel's uv (lib/trace/camera_mesh.c)
 * looks at a few faces, not all.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pov-parse.h"
#include "sdl/build_camlight.h"
#include "trace/obj_mesh.h"

/* The value of e truncated toward zero, as povray converts it. */
static bool whole(zr_sdl_parser *p, const zr_sdl_expr *e,
                  const zr_sdl_loc *loc, double *out) {
  if (!zr__sdl_want_float(p, e, loc, out))
    return false;
  *out = trunc(*out);
  return true;
}

bool zr__sdl_mesh_camera(zr_sdl_parser *p, const zr_sdl_loc *at,
                         const zr_sdl_expr *rays, const zr_sdl_loc *rays_at,
                         const zr_sdl_expr *dist, const zr_sdl_loc *dist_at,
                         const zr_sdl_expr *max, const zr_sdl_loc *max_at) {
  double n, d, limit = 0.0;
  if (!whole(p, rays, rays_at, &n) || !whole(p, dist, dist_at, &d) ||
      (max && !zr__sdl_want_float(p, max, max_at, &limit)))
    return false;
  if (!(n >= 1 && n <= 1e6)) {
    zr__sdl_error(p, ZR_ESCENE, rays_at, "a mesh_camera shoots at least "
                  "1 ray per pixel, not %g", n);
    return false;
  }
  if (!(d >= 0 && d <= 3)) {
    zr__sdl_error(p, ZR_ESCENE, dist_at, "a mesh_camera's distribution "
                  "type is 0, 1, 2 or 3, not %g", d);
    return false;
  }
  zr_mesh_camera *m = zr__sdl_alloc(p, sizeof *m);
  if (!m)
    return false;
  memset(m, 0, sizeof *m);
  m->rays_per_pixel = (int)n;
  m->distribution = (int)d;
  /* "if greater than EPSILON" ("Max Distance", 3.4.2.2.3.3), the
     manual's 1e-10 ("Numeric Expressions"): anything else is no
     limit. */
  m->max_distance = limit > 1e-10 ? limit : 0.0;
  p->camera.mesh = m;
  p->camera.mesh_at = *at;
  p->camera.cap_meshes = 0;
  zr_camera *c = &p->scene->camera;
  c->kind = ZR_CAMERA_MESH;
  c->mesh = m;
  p->camera.type_given = true;
  return true;
}

bool zr__sdl_mesh_camera_add(zr_sdl_parser *p, const zr_object *mesh,
                             const zr_sdl_loc *loc) {
  zr_mesh_camera *m = p->camera.mesh;
  if (mesh->kind != ZR_OBJ_MESH) {
    zr__sdl_error(p, ZR_ESCENE, loc, "a mesh_camera takes mesh or mesh2 "
                  "objects only");
    return false;
  }
  if (m->n_meshes == p->camera.cap_meshes) {
    size_t cap = m->n_meshes ? 2 * m->n_meshes : 4;
    zr_camera_mesh *grown = zr__sdl_alloc(p, cap * sizeof *grown);
    if (!grown)
      return false;
    if (m->n_meshes)
      memcpy(grown, m->meshes, m->n_meshes * sizeof *grown);
    m->meshes = grown;
    p->camera.cap_meshes = cap;
  }
  zr_camera_mesh *slot = (zr_camera_mesh *)&m->meshes[m->n_meshes++];
  slot->data = mesh->u.mesh.data;
  slot->transform = mesh->transform;
  m->n_faces += mesh->u.mesh.data->n_faces;
  return true;
}

bool zr__sdl_mesh_camera_smooth(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  (void)loc;
  p->camera.mesh->smooth = true;
  return true;
}

/* The uv box of face f (a row of the mesh). */
static void face_uv_box(const struct zr_mesh *d, size_t row, double lo[2],
                        double hi[2]) {
  lo[0] = lo[1] = INFINITY;
  hi[0] = hi[1] = -INFINITY;
  for (int k = 0; k < 3; k++) {
    const double *uv = d->uvs[d->face_uvs[row][k]];
    for (int a = 0; a < 2; a++) {
      lo[a] = fmin(lo[a], uv[a]);
      hi[a] = fmax(hi[a], uv[a]);
    }
  }
}

/* The cell range [c0, c1] that [lo, hi] covers on an axis of the grid. */
static void cell_span(double lo, double hi, double from, double size,
                      int grid, int *c0, int *c1) {
  double a = (lo - from) / size, b = (hi - from) / size;
  *c0 = a < 0 ? 0 : a >= grid ? grid - 1 : (int)a;
  *c1 = b < 0 ? 0 : b >= grid ? grid - 1 : (int)b;
}

/*
 * Sorts the first mesh's faces into a grid of cells over their uv box:
 * each cell lists, in the order the faces were written, the faces whose
 * uv box touches it.  About sqrt(n) x sqrt(n) cells for n faces, at most
 * 1024 a side (our own lookup structure: the cap only bounds its memory).
 */
static bool uv_grid(zr_sdl_parser *p, zr_mesh_camera *m) {
  const struct zr_mesh *d = m->meshes[0].data;
  size_t n = d->n_faces;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t i = 0; i < n; i++) {
    double flo[2], fhi[2];
    face_uv_box(d, i, flo, fhi);
    for (int a = 0; a < 2; a++) {
      lo[a] = fmin(lo[a], flo[a]);
      hi[a] = fmax(hi[a], fhi[a]);
    }
  }
  int grid = (int)ceil(sqrt((double)n));
  grid = grid < 1 ? 1 : grid > 1024 ? 1024 : grid;
  double size[2];
  for (int a = 0; a < 2; a++) {
    size[a] = (hi[a] - lo[a]) / grid;
    if (!(size[a] > 0.0))
      size[a] = 1.0;
  }
  size_t cells = (size_t)grid * (size_t)grid;
  uint32_t *start = zr__sdl_alloc(p, (cells + 1) * sizeof *start);
  if (!start)
    return false;
  memset(start, 0, (cells + 1) * sizeof *start);
  /* Two passes: count each cell's faces, then place them. */
  size_t total = 0;
  for (int pass = 0; pass < 2; pass++) {
    uint32_t *faces = NULL;
    if (pass == 1) {
      for (size_t c = 0; c < cells; c++)
        start[c + 1] += start[c];
      total = start[cells];
      if (total > UINT32_MAX)
        return false;
      faces = zr__sdl_alloc(p, (total ? total : 1) * sizeof *faces);
      if (!faces)
        return false;
      m->cell_faces = faces;
    }
    uint32_t *fill = pass == 1 ? calloc(cells, sizeof *fill) : NULL;
    if (pass == 1 && !fill)
      return false;
    for (size_t i = 0; i < n; i++) {
      double flo[2], fhi[2];
      face_uv_box(d, d->face_row[i], flo, fhi);
      int u0, u1, v0, v1;
      cell_span(flo[0], fhi[0], lo[0], size[0], grid, &u0, &u1);
      cell_span(flo[1], fhi[1], lo[1], size[1], grid, &v0, &v1);
      for (int cv = v0; cv <= v1; cv++)
        for (int cu = u0; cu <= u1; cu++) {
          size_t c = (size_t)cv * (size_t)grid + (size_t)cu;
          if (pass == 0)
            start[c + 1]++;
          else
            faces[start[c] + fill[c]++] = (uint32_t)i;
        }
    }
    free(fill);
  }
  for (int a = 0; a < 2; a++) {
    m->grid_lo[a] = lo[a];
    m->cell_size[a] = size[a];
  }
  m->grid = grid;
  m->cell_start = start;
  return true;
}

bool zr__sdl_mesh_camera_end(zr_sdl_parser *p, const zr_sdl_loc *loc) {
  zr_mesh_camera *m = p->camera.mesh;
  const zr_sdl_loc *at = &p->camera.mesh_at;
  if (m->n_meshes == 0) {
    zr__sdl_error(p, ZR_ESCENE, at, "a mesh_camera needs at least one mesh "
                  "or mesh2");
    return false;
  }
  if (m->distribution == 0 && (size_t)m->rays_per_pixel > m->n_meshes) {
    zr__sdl_error(p, ZR_ESCENE, at, "distribution type 0 needs as many "
                  "meshes as rays per pixel (%d rays, %zu meshes)",
                  m->rays_per_pixel, m->n_meshes);
    return false;
  }
  if (m->distribution >= 2 && m->rays_per_pixel != 1) {
    zr__sdl_error(p, ZR_ESCENE, at, "distribution type %d shoots 1 ray "
                  "per pixel, not %d", m->distribution, m->rays_per_pixel);
    return false;
  }
  if (m->smooth && m->distribution != 3) {
    zr__sdl_error(p, ZR_ESCENE, at, "'smooth' only works with "
                  "distribution type 3");
    return false;
  }
  if (m->distribution == 1 && m->rays_per_pixel > 1) {
    zr__sdl_warning(p, at, "distribution type 1 shoots 1 ray per pixel, "
                    "as povray 3.7 renders it, not %d", m->rays_per_pixel);
    m->rays_per_pixel = 1;
  }
  if (m->distribution == 3) {
    const struct zr_mesh *d = m->meshes[0].data;
    if (!d->uvs || !d->face_uvs) {
      zr__sdl_error(p, ZR_ESCENE, at, "distribution type 3 needs a first "
                    "mesh with uv_vectors");
      return false;
    }
    if (!uv_grid(p, m)) {
      zr__sdl_error(p, ZR_ENOMEM, loc, "out of memory");
      return false;
    }
  }
  p->camera.mesh = NULL;
  return true;
}
