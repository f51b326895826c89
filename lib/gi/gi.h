/*
 * gi.h - the global illumination models other than hierarchical
 * radiosity: Ward's irradiance cache for POV-Ray's radiosity block
 * (cache.c, cachefile.c), sky and background as light (the cache's
 * rays that escape see them), and the choice of model per scene
 * (choose.c).  The tracer reaches a model only through zr_indirect
 * (lib/trace/shade.h).
 */
#ifndef ZR_GI_GI_H
#define ZR_GI_GI_H

#include <stdint.h>

#include "scene/scene.h"
#include "trace/shade.h"

/* One cached irradiance value (Ward, Rubinstein and Clear 1988) with
   its gradients (Ward and Heckbert 1992), per colour channel. */
typedef struct zr__gi_record {
  zr_vec3 p, n;      /* where it was gathered; unit normal */
  double e[3];       /* mean incoming radiance (irradiance / pi) */
  zr_vec3 grad_r[3]; /* rotational gradient of e */
  zr_vec3 grad_t[3]; /* translational gradient of e */
  double r;          /* reuse radius: clamped harmonic mean distance */
  int32_t depth;     /* the bounce it serves: 0 for camera hits */
} zr__gi_record;

/* A growing list of records. */
typedef struct zr__gi_list {
  zr__gi_record *v;
  size_t n, cap;
} zr__gi_list;

bool zr__gi_list_push(zr__gi_list *l, const zr__gi_record *r);
void zr__gi_list_free(zr__gi_list *l);

/* The records of one bounce depth, indexed by an octree whose node of
   half-size h holds records with reuse reach at most h.  A node is two
   parts: what a lookup reads, in one 64-byte line (the lookup went to
   memory for every child it tested, on radiosity2.pov the hottest load
   of the whole render), and its cube, which only adding reads. */
typedef struct zr__gi_node {
  /* The box of the points of the records in this node and below it,
     and the largest radius among them, rounded outwards to floats: a
     lookup whose error bound is a goes down only where its point lies
     within a times that radius of the box (lo > hi while the node holds
     none). */
  float lo[3], hi[3];
  float r_max;
  int32_t first;    /* first record (index into the cache), -1 */
  int32_t child[8]; /* -1: none */
} zr__gi_node;

typedef struct zr__gi_cube {
  zr_vec3 c;
  double h;
} zr__gi_cube;

/* A record's position and radius, for the lookup's first test, and the
   next record of its node (-1: none). */
typedef struct zr__gi_near {
  zr_vec3 p;
  double r;
  int32_t next;
} zr__gi_near;

/* A cell of the final pass's index (zr_gi_cache): its cube, its first
   of eight children (-1: a leaf) and a leaf's list, idx[start, end). */
typedef struct zr__gi_cell {
  zr_vec3 c;
  double h;
  int32_t child;
  uint32_t start, end;
} zr__gi_cell;

struct zr_gi_cache {
  zr_indirect indirect;    /* what the final pass hands the tracer */
  const zr_scene *scene;
  zr_gi_params params;
  zr__gi_list records;     /* all depths, in the order they joined */
  zr__gi_near *near;       /* each record's p, r and next (near_cap) */
  size_t near_cap;
  /* One octree per depth: nodes[d] and their cubes[d], roots are node
     0 of each. */
  zr__gi_node *nodes[20];
  zr__gi_cube *cubes[20];
  /* Where a lookup entering a node may go at once: the node itself, or
     the end of the chain below it of nodes with no record and one child
     (whose boxes are the node's).  The root's size is the scene's, sky
     sphere and far planes included; records sit at nodes of their own
     reach, and radiosity2.pov's lookups visited 35 nodes, 31 of them
     without records, most of them links of such chains. */
  int32_t *jumps[20];
  size_t n_nodes[20], cap_nodes[20];
  zr_vec3 root_c;
  double root_h;
  /* The camera at the pretrace's image size, for reuse distances. */
  int pretrace_passes;
  uint64_t sample_rays;
  int pretracing;          /* 1 while the pretrace runs */
  int pretrace_pass;       /* its pass, from 0 */
  /* The final pass's index of the first bounce's records, built at the
     end of the pretrace (zr__gi_cache_freeze) and dropped when a record
     joins: an octree of cells, split while that shortens their lists,
     whose leaf lists every record that may serve a point in it at an
     error bound up to grid_a, in the order blend_tree meets them, so a
     lookup blends the same records in the same order, testing few
     (sky_outdoor.pov: blend_tree tests 140 records and 8 children of
     17 nodes to blend the 15 within reach). */
  double grid_a;           /* 0: no index */
  zr__gi_cell *grid_nodes; /* node 0 is the root */
  size_t grid_n_nodes;
  int32_t *grid_idx;       /* the leaves' lists */
  size_t grid_n_idx;
};

/* Whether a sky_sphere or a background that is not black lights the
   scene (lib/gi/choose.c). */
bool zr__gi_has_sky(const zr_scene *scene);

/* Adds the record to the cache and its depth's octree. */
bool zr__gi_cache_add(zr_gi_cache *cache, const zr__gi_record *r);
/* Builds the final pass's grid of the first bounce's records (see
   zr_gi_cache); false, and no grid (lookups walk the octree), when it
   would be too large or a record is not finite. */
bool zr__gi_cache_freeze(zr_gi_cache *cache);
/* One lookup at depth d, point p, normal n (unit) and error bound a, as
   the final pass makes it: through the grid (via_grid, when there is one
   and a is within its bound) or the octree; or, with want > 0, as the
   pretrace's first bounce makes it (records counted up to want, sums
   left at 0).  Sets the blend's sums, their weight and the number of
   records that served; for tests. */
void zr__gi_cache_lookup(const zr_gi_cache *cache, int d, zr_vec3 p,
                         zr_vec3 n, double a, bool via_grid, int want,
                         double sum[3], double *wsum, int *count);
/* The octree's extent for scene: its bounds and camera, doubled. */
void zr__gi_cache_extent(zr_gi_cache *cache);

#endif /* ZR_GI_GI_H */
