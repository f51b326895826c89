/*
 * quadtree.c - (u,v) quadtrees of radiosity elements with shared corner
 * vertices, and the smoothing that turns element values into a
 * continuous picture.
 *
 * Hanrahan, Salzman and Aupperle (SIGGRAPH 1991) keep each input surface
 * as a quadtree: a node is split in four only when refinement asks for
 * it, and every node holds the area mean of its subtree, so links can
 * attach at any level.  Here a node is a rectangle of the surface's
 * parameter square on a dyadic grid (2^24 steps per side), so its
 * corners have exact integer coordinates: the corner vertices live in a
 * hash table keyed by (surface, iu, iv), and cells that meet at a point
 * share one vertex instead of holding copies.
 *
 * Smoothing (the Gouraud step of classic radiosity renderers, as in
 * Cohen and Wallace, "Radiosity and Realistic Image Synthesis", 6.3): a
 * vertex takes the area-weighted mean of the leaves around it.  Where a
 * small leaf meets a large one, its corner lies inside the large leaf's
 * edge (a T-vertex); the large leaf interpolates only its own corners
 * there, so the T-vertex is then set to the value on that edge.  Done
 * from the largest leaves down, it makes the interpolated radiosity
 * continuous across every edge of a surface: no cracks.
 */
#include "radiosity/radiosity.h"

#include "core/arena.h"

#include <stdlib.h>
#include <string.h>

/* ---- growable arrays ---- */

static bool grow(zr_radiosity *rad, void **array, size_t *cap, size_t need,
                 size_t size) {
  if (need <= *cap)
    return true;
  size_t cap2 = *cap ? *cap : 64;
  while (cap2 < need)
    cap2 *= 2;
  if (!zr__rad_charge(rad, (cap2 - *cap) * size))
    return false;
  void *p = zr__huge_grow(*array, *cap * size, cap2 * size);
  if (p == NULL)
    return false;
  *array = p;
  *cap = cap2;
  return true;
}

/* ---- vertices ---- */

static size_t vertex_hash(int32_t surf, uint32_t slot, uint32_t iu,
                          uint32_t iv) {
  uint64_t h = ((uint64_t)(uint32_t)surf + ((uint64_t)slot << 32)) *
               0x9E3779B97F4A7C15ull;
  h ^= ((uint64_t)iu << 32 | iv) + 0x632BE59BD9B4E019ull + (h << 6);
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return (size_t)h;
}

/* The slot of (surf, iu, iv): its vertex or the empty slot for it. */
static size_t vertex_slot(const zr_radiosity *rad, int32_t surf,
                          uint32_t slot, uint32_t iu, uint32_t iv) {
  size_t mask = rad->hash_cap - 1;
  size_t i = vertex_hash(surf, slot, iu, iv) & mask;
  for (;;) {
    uint32_t e = rad->vhash[i];
    if (e == 0)
      return i;
    const zr__rad_vertex *v = &rad->verts[e - 1];
    if (v->surf == surf && v->slot == slot && v->iu == iu && v->iv == iv)
      return i;
    i = (i + 1) & mask;
  }
}

static bool rehash(zr_radiosity *rad, size_t cap) {
  uint32_t *table = calloc(cap, sizeof *table);
  if (table == NULL)
    return false;
  free(rad->vhash);
  rad->vhash = table;
  rad->hash_cap = cap;
  for (size_t k = 0; k < rad->n_verts; k++) {
    const zr__rad_vertex *v = &rad->verts[k];
    rad->vhash[vertex_slot(rad, v->surf, v->slot, v->iu, v->iv)] =
        (uint32_t)k + 1;
  }
  return true;
}

/* The index of the vertex (surf, iu, iv), created when new; UINT32_MAX
   when out of memory. */
static uint32_t vertex_get(zr_radiosity *rad, int32_t surf, uint32_t mslot,
                           uint32_t iu, uint32_t iv) {
  if (2 * (rad->n_verts + 1) > rad->hash_cap &&
      !rehash(rad, rad->hash_cap ? 2 * rad->hash_cap : 1024))
    return UINT32_MAX;
  size_t slot = vertex_slot(rad, surf, mslot, iu, iv);
  if (rad->vhash[slot] != 0)
    return rad->vhash[slot] - 1;
  if (!grow(rad, (void **)&rad->verts, &rad->cap_verts, rad->n_verts + 1,
            sizeof *rad->verts))
    return UINT32_MAX;
  zr__rad_vertex *v = &rad->verts[rad->n_verts];
  memset(v, 0, sizeof *v);
  v->surf = surf;
  v->slot = mslot;
  v->iu = iu;
  v->iv = iv;
  rad->vhash[slot] = (uint32_t)++rad->n_verts;
  return (uint32_t)rad->n_verts - 1;
}

/* The vertex at (surf, iu, iv) if it exists, else UINT32_MAX. */
static uint32_t vertex_find(const zr_radiosity *rad, int32_t surf,
                            uint32_t slot, uint32_t iu, uint32_t iv) {
  uint32_t e = rad->vhash[vertex_slot(rad, surf, slot, iu, iv)];
  return e == 0 ? UINT32_MAX : e - 1;
}

/* ---- nodes ---- */

void zr__rad_node_cell(const zr__rad_node *node, double cell[4]) {
  double step = (double)(ZR__RAD_GRID >> node->depth) / ZR__RAD_GRID;
  cell[0] = (double)node->iu / ZR__RAD_GRID;
  cell[1] = cell[0] + step;
  cell[2] = (double)node->iv / ZR__RAD_GRID;
  cell[3] = cell[2] + step;
}

/* Angle between unit vectors, safe against rounding. */
static double angle(zr_vec3 a, zr_vec3 b) {
  double c = zr_v3_dot(a, b);
  return acos(c > 1.0 ? 1.0 : c < -1.0 ? -1.0 : c);
}

/* The vertex slot of a node's corners (see zr__rad_vertex). */
static uint32_t node_slot(const zr_radiosity *rad, int32_t surf,
                          int32_t depth, uint32_t iu, uint32_t iv) {
  const zr__surface *g = &rad->surfs[surf].geom;
  if (g->kind != ZR__SURFACE_MESH || depth < g->slot_depth)
    return 0;
  zr__rad_node probe = {.depth = depth, .iu = iu, .iv = iv};
  double cell[4];
  size_t f0, f1;
  zr__rad_node_cell(&probe, cell);
  zr__surface_mesh_cluster(g, cell, &f0, &f1);
  return (uint32_t)f0 + 1;
}

/* A cluster of a mesh's faces: its aggregate, and no CSG trim (a cell
   with no area is dropped as a removed one is). */
static bool cluster_geometry(const zr__surface *g, const double cell[4],
                             zr__rad_node *node) {
  size_t f0, f1;
  if (!zr__surface_mesh_cluster(g, cell, &f0, &f1))
    return false;
  zr__surface_mesh_aggregate(g, f0, f1, &node->area, &node->centre,
                             &node->normal, &node->spread);
  node->kept = node->area > 0.0 ? 1.0 : 0.0;
  return true;
}

void zr__rad_node_geometry(const zr_radiosity *rad, zr__rad_node *node) {
  const zr__surface *g = &rad->surfs[node->surf].geom;
  double cell[4];
  zr__rad_node_cell(node, cell);
  if (cluster_geometry(g, cell, node))
    return;
  zr__surface_point pt;
  zr__surface_eval(g, 0.5 * (cell[0] + cell[1]), 0.5 * (cell[2] + cell[3]),
                   &pt);
  node->centre = pt.p;
  node->normal = pt.n;
  node->area = zr__surface_area(g, cell[0], cell[1], cell[2], cell[3], 1,
                                &rad->rule_src);
  /* Only the part a CSG keeps counts (trim.c). */
  node->kept = zr__rad_trim_fraction(rad, &rad->surfs[node->surf], cell, 4);
  node->area *= node->kept;
  node->spread = 0.0;
  if (g->kind == ZR__SURFACE_MESH && !(node->area > 0.0))
    node->kept = 0.0; /* an empty slot or a face with no area */
  if (g->planar || g->kind == ZR__SURFACE_MESH)
    return;
  for (int k = 0; k < 4; k++) {
    zr__surface_point c;
    zr__surface_eval(g, cell[k == 1 || k == 2], cell[2 + (k >= 2)], &c);
    node->spread = fmax(node->spread, angle(c.n, pt.n));
  }
}

/* A new node; -1 when out of memory. */
static int32_t node_new(zr_radiosity *rad, int32_t surf, int32_t parent,
                        int32_t depth, uint32_t iu, uint32_t iv) {
  if (!grow(rad, (void **)&rad->nodes, &rad->cap_nodes, rad->n_nodes + 1,
            sizeof *rad->nodes))
    return -1;
  zr__rad_node *node = &rad->nodes[rad->n_nodes];
  memset(node, 0, sizeof *node);
  node->child = -1;
  node->parent = parent;
  node->surf = surf;
  node->depth = depth;
  node->iu = iu;
  node->iv = iv;
  uint32_t step = ZR__RAD_GRID >> depth;
  const uint32_t cu[4] = {iu, iu + step, iu + step, iu};
  const uint32_t cv[4] = {iv, iv, iv + step, iv + step};
  uint32_t slot = node_slot(rad, surf, depth, iu, iv);
  for (int k = 0; k < 4; k++) {
    uint32_t v = vertex_get(rad, surf, slot, cu[k], cv[k]);
    if (v == UINT32_MAX)
      return -1;
    rad->nodes[rad->n_nodes].vert[k] = v;
  }
  node = &rad->nodes[rad->n_nodes];
  zr__rad_node_geometry(rad, node);
  const zr__rad_surface *s = &rad->surfs[surf];
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++)
      node->b[side][c] = s->emission[side][c];
  return (int32_t)rad->n_nodes++;
}

zr_status zr__rad_add_root(zr_radiosity *rad, int32_t s) {
  int32_t n = node_new(rad, s, -1, 0, 0, 0);
  if (n < 0)
    return ZR_ENOMEM;
  rad->surfs[s].root = n;
  return ZR_OK;
}

bool zr__rad_subdivide(zr_radiosity *rad, int32_t n) {
  zr__rad_node parent = rad->nodes[n];
  if (parent.child >= 0)
    return true;
  if (parent.depth >= ZR__RAD_DEPTH)
    return false;
  uint32_t half = (ZR__RAD_GRID >> parent.depth) / 2;
  const uint32_t du[4] = {0, half, half, 0}, dv[4] = {0, 0, half, half};
  int32_t first = -1;
  for (int k = 0; k < 4; k++) {
    int32_t c = node_new(rad, parent.surf, n, parent.depth + 1,
                         parent.iu + du[k], parent.iv + dv[k]);
    if (c < 0)
      return false;
    if (k == 0)
      first = c;
    /* A new element starts from its parent's radiosity. */
    memcpy(rad->nodes[c].b, parent.b, sizeof parent.b);
  }
  rad->nodes[n].child = first;
  return true;
}

int32_t zr__rad_leaf_at(const zr_radiosity *rad, int32_t s, double u,
                        double v) {
  int32_t n = rad->surfs[s].root;
  while (rad->nodes[n].child >= 0) {
    const zr__rad_node *node = &rad->nodes[n];
    double cell[4];
    zr__rad_node_cell(node, cell);
    bool hu = u >= 0.5 * (cell[0] + cell[1]);
    bool hv = v >= 0.5 * (cell[2] + cell[3]);
    n = node->child + (hv ? (hu ? 2 : 3) : (hu ? 1 : 0));
  }
  return n;
}

/* ---- smoothing ---- */

/* Sets the vertices strictly inside the edge a-b of a leaf to the linear
   interpolation of a and b, recursively by midpoints. */
static void fix_edge(zr_radiosity *rad, int32_t surf, uint32_t au,
                     uint32_t av, uint32_t bu, uint32_t bv, uint32_t va,
                     uint32_t vb) {
  if ((bu - au) + (bv - av) < 2)
    return;
  uint32_t mu = au + (bu - au) / 2, mv = av + (bv - av) / 2;
  uint32_t vm = vertex_find(rad, surf, rad->verts[va].slot, mu, mv);
  if (vm == UINT32_MAX)
    return;
  zr__rad_vertex *m = &rad->verts[vm];
  for (int side = 0; side < 2; side++)
    for (int c = 0; c < 3; c++)
      m->b[side][c] =
          0.5 * (rad->verts[va].b[side][c] + rad->verts[vb].b[side][c]);
  fix_edge(rad, surf, au, av, mu, mv, va, vm);
  fix_edge(rad, surf, mu, mv, bu, bv, vm, vb);
}

/* Fixes the four edges of leaf n (corner order as in node->vert). */
static void fix_leaf_edges(zr_radiosity *rad, int32_t n) {
  const zr__rad_node *node = &rad->nodes[n];
  uint32_t step = ZR__RAD_GRID >> node->depth;
  uint32_t u0 = node->iu, v0 = node->iv, u1 = u0 + step, v1 = v0 + step;
  fix_edge(rad, node->surf, u0, v0, u1, v0, node->vert[0], node->vert[1]);
  fix_edge(rad, node->surf, u0, v1, u1, v1, node->vert[3], node->vert[2]);
  fix_edge(rad, node->surf, u0, v0, u0, v1, node->vert[0], node->vert[3]);
  fix_edge(rad, node->surf, u1, v0, u1, v1, node->vert[1], node->vert[2]);
}

void zr__rad_smooth(zr_radiosity *rad) {
  for (size_t k = 0; k < rad->n_verts; k++) {
    memset(rad->verts[k].b, 0, sizeof rad->verts[k].b);
    rad->verts[k].weight = 0.0;
  }
  size_t by_depth[ZR__RAD_DEPTH + 2] = {0};
  for (size_t n = 0; n < rad->n_nodes; n++) {
    const zr__rad_node *node = &rad->nodes[n];
    if (node->child >= 0)
      continue;
    by_depth[node->depth + 1]++;
    /* The light sources' direct light, rho H_d, is left out: the tracer
       adds it per pixel (direct.c). */
    const double *rho = rad->surfs[node->surf].rho;
    for (int k = 0; k < 4; k++) {
      zr__rad_vertex *v = &rad->verts[node->vert[k]];
      for (int side = 0; side < 2; side++)
        for (int c = 0; c < 3; c++)
          v->b[side][c] += node->area * (node->b[side][c] -
                                         rho[c] * node->hd[side][c]);
      v->weight += node->area;
    }
  }
  for (size_t k = 0; k < rad->n_verts; k++) {
    zr__rad_vertex *v = &rad->verts[k];
    double w = v->weight > 0.0 ? 1.0 / v->weight : 0.0;
    for (int side = 0; side < 2; side++)
      for (int c = 0; c < 3; c++)
        v->b[side][c] *= w;
  }
  /* T-vertices, largest leaves first: a counting sort by depth. */
  for (int d = 1; d <= ZR__RAD_DEPTH + 1; d++)
    by_depth[d] += by_depth[d - 1];
  int32_t *order = malloc((by_depth[ZR__RAD_DEPTH + 1] + 1) * sizeof *order);
  if (order == NULL)
    return; /* smoothing without the T-vertex fix is still usable */
  for (size_t n = 0; n < rad->n_nodes; n++)
    if (rad->nodes[n].child < 0)
      order[by_depth[rad->nodes[n].depth]++] = (int32_t)n;
  size_t leaves = by_depth[ZR__RAD_DEPTH];
  for (size_t i = 0; i < leaves; i++)
    fix_leaf_edges(rad, order[i]);
  free(order);
}

void zr__rad_interpolate(const zr_radiosity *rad, int32_t n, int side,
                         double u, double v, double out[3]) {
  const zr__rad_node *node = &rad->nodes[n];
  double cell[4];
  zr__rad_node_cell(node, cell);
  size_t f0, f1;
  if (zr__surface_mesh_cluster(&rad->surfs[node->surf].geom, cell, &f0,
                               &f1)) {
    /* A cluster's corners are no points of its faces: it is flat. */
    const double *rho = rad->surfs[node->surf].rho;
    for (int c = 0; c < 3; c++)
      out[c] = node->b[side][c] - rho[c] * node->hd[side][c];
    return;
  }
  double s = (u - cell[0]) / (cell[1] - cell[0]);
  double t = (v - cell[2]) / (cell[3] - cell[2]);
  s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
  t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
  const double w[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
  for (int c = 0; c < 3; c++) {
    double sum = 0.0;
    for (int k = 0; k < 4; k++)
      sum += w[k] * rad->verts[node->vert[k]].b[side][c];
    out[c] = sum;
  }
}

void zr__rad_free_arrays(zr_radiosity *rad) {
  zr__rad_vol_free(rad);
  free(rad->nodes);
  free(rad->links);
  free(rad->verts);
  free(rad->vhash);
  /* The slot after the last surface (there is always one, mesh.c) may
     hold a cache its surface's failed build left. */
  for (size_t s = 0; rad->surfs != NULL && s <= rad->n_surfs; s++)
    zr__surface_mesh_cache_free(&rad->surfs[s].geom);
  free(rad->surfs);
  free(rad->objects);
  zr__arena_free(&rad->hf_meshes);
  zr__rad_free_poly_cache(rad);
  free(rad->recv_start);
  free(rad->recv_links);
  rad->recv_start = rad->recv_links = NULL;
  rad->nodes = NULL;
  rad->links = NULL;
  rad->verts = NULL;
  rad->vhash = NULL;
  rad->surfs = NULL;
  rad->objects = NULL;
}
