/*
 * radiosity.h - the hierarchical radiosity solution of a scene (Hanrahan,
 * Salzman and Aupperle, "A Rapid Hierarchical Radiosity Algorithm",
 * SIGGRAPH 1991), shared by the modules of lib/radiosity:
 *
 *   mesh.c      the exact surfaces of the scene's primitives
 *   quadtree.c  (u,v) quadtrees with shared corner vertices, smoothing
 *   refine.c    links between nodes, oracle, visibility, transfer factors
 *   solve.c     gathering with push-pull, Southwell shooting, energy
 *   io.c        saving and loading a solution, the scene fingerprint
 *   direct.c    POV-Ray light sources shooting direct light into the mesh
 *   meshimage.c a picture of the mesh (elements flat, edges drawn)
 *   radiosity.c the public API and the lookup from a ray hit
 *   trim.c      CSG trimming of the parts of intersections and merges
 *   cluster.c   form factors of links to clusters of a mesh's faces
 *   volume.c    volume clusters of whole surfaces and their links
 *   workers.c   the threads of a rank, a parallel loop
 *
 * Every element has two sides, front (along the surface's outward normal)
 * and back, each with its own radiosity: POV-Ray lights both sides of a
 * surface, and a closed room is usually a box seen from inside.  Emission
 * is two-sided too, as POV-Ray shows it from both sides.  Radiosity B is
 * an exitance (W/m^2 in the scene's units): B = pi L for the radiance L
 * that shading uses.
 *
 * Everything is in growable arrays addressed by index, so growing an
 * array never invalidates a reference, and the solution is built in a
 * fixed order (threads compute into slots of their own, workers.c, and
 * one thread combines them in order): the same scene and parameters
 * give the same bytes for any number of threads.
 */
#ifndef ZR_RADIOSITY_RADIOSITY_H
#define ZR_RADIOSITY_RADIOSITY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "core/arena.h"
#include "core/context.h"
#include "core/team.h"
#include "radiosity/quadrature.h"
#include "radiosity/surface.h"
#include "scene/scene.h"
#include "trace/bvh.h"
#include "trace/shade.h"
#include "zrcube.h"

/* Quadtree cells live on a dyadic grid of 2^ZR__RAD_DEPTH steps per
   parameter, deep enough for any A_eps a scene can ask for. */
#define ZR__RAD_DEPTH 24
#define ZR__RAD_GRID (1u << ZR__RAD_DEPTH)

/* One quadtree node: a parameter rectangle of one surface. */
typedef struct zr__rad_node {
  int32_t child;  /* first of four consecutive children, -1 for a leaf */
  int32_t parent; /* -1 for a root */
  int32_t surf;   /* index of its surface */
  int32_t depth;
  uint32_t iu, iv;   /* lower corner on the dyadic grid */
  uint32_t vert[4];  /* corners (u0,v0), (u1,v0), (u1,v1), (u0,v1) */
  double area;
  zr_vec3 centre, normal; /* S and the unit normal at the cell's centre */
  double spread; /* largest angle (radians) between normal and others */
  double b[2][3];  /* radiosity of each side, the subtree's area mean */
  double bg[2][3]; /* reflected radiosity gathered at this level */
  double hg[2][3]; /* incident radiosity (irradiance / pi), this level */
  double un[2][3]; /* unshot radiosity (Southwell shooting) */
  double closure[2]; /* sum of F * visibility gathered at this level */
  /* The fraction of the cell that CSG leaves (trim.c); area is that
     kept part's area.  1 on a surface no CSG trims. */
  double kept;
  /* Irradiance straight from the scene's light sources (direct.c), the
     mean over the cell, per side; set where has_direct is 1 (leaves). */
  double hd[2][3];
  uint8_t has_direct;
  /* 1 + the index of the cluster element this node is (volume.c), 0
     for a node that is none. */
  uint32_t elem1;
} zr__rad_node;

/* A link: node recv (side rside) gathers from node src (side sside). */
typedef struct zr__rad_link {
  int32_t recv, src;
  uint8_t rside, sside;
  uint8_t dead;  /* replaced by finer links */
  uint8_t final; /* transfer factor computed */
  double ff;     /* form factor times visibility, recv <- src */
  double vis;    /* the visible fraction */
} zr__rad_link;

/* A corner vertex shared by the cells that meet at it. */
typedef struct zr__rad_vertex {
  int32_t surf;
  uint32_t iu, iv;
  /* 1 + the face of a mesh surface whose triangle the vertex is a
     corner of (neighbouring slots are no neighbours on the mesh), 0 on
     other surfaces and for clusters' corners. */
  uint32_t slot;
  double b[2][3]; /* smoothed radiosity */
  double weight;  /* area summed while smoothing */
} zr__rad_vertex;

/* One exact surface of a primitive (a box has six). */
typedef struct zr__rad_surface {
  zr__surface geom;
  const zr_object *object;
  /* The CSG primitive (intersection, difference, merge) the surface is
     part of, whose other parts trim it; NULL for none (trim.c). */
  const zr_object *trim;
  /* Emitted exitance pi * emission * pigment of the front and back
     sides as the solver shoots it: with params.one_sided_emission 1
     the back is dark, with 2 (the default) each side's is scaled by the
     share of its light that leaves it (mesh.c, side_openness). */
  double emission[2][3];
  /* The exitance a ray that meets the side sees: the finish's emission
     on every side that emits, unscaled (POV-Ray shows it so). */
  double shown[2][3];
  /* The openness of each side (mesh.c), 1 where none was measured. */
  double open[2];
  double rho[3];      /* reflectance diffuse * pigment */
  int32_t root;
  double area;
} zr__rad_surface;

/* A volume cluster of whole surfaces (volume.c): a node of a binary
   tree over the surfaces; a leaf holds one surface. */
typedef struct zr__rad_vol {
  int32_t child[2]; /* -1 for a leaf */
  int32_t surf;     /* a leaf's surface, -1 above */
  uint32_t e0, e1;  /* its elements, vol_elems[e0, e1) */
  zr_vec3 lo, hi, centre;
  double radius; /* of the sphere round its box */
  double area;
} zr__rad_vol;

/* A node that stands for its surface in links to clusters: a planar
   surface's root, a curved one's cells of its initial 4 x 4 split. */
typedef struct zr__rad_elem {
  int32_t node;
  double hc[2][3]; /* irradiance that cluster links brought, per side */
} zr__rad_elem;

/* One element's weight in a cluster link: at the source end its
   intensity per unit radiosity, A cos V / pi, at the receiving end its
   irradiance per unit intensity, cos V / r^2. */
typedef struct zr__rad_vweight {
  uint32_t elem;
  uint32_t side;
  double w;
} zr__rad_vweight;

/* A link between volume clusters (one end may be one surface). */
typedef struct zr__rad_vlink {
  int32_t recv, src; /* zr__rad_vol indices */
  uint8_t dead;
  uint32_t ns, nr; /* weights: w[0, ns) source, w[ns, ns + nr) receiver */
  zr__rad_vweight *w; /* NULL until computed */
} zr__rad_vlink;

/* Which surfaces belong to an object, sorted by object address. */
typedef struct zr__rad_object_entry {
  const zr_object *object;
  uint32_t first, count;
} zr__rad_object_entry;

struct zr_radiosity {
  /* What the tracer reads (lib/trace/shade.h): the first member, so a
     zr_radiosity * is a zr_radiance_source *. */
  zr_radiance_source source;
  const zr_scene *scene;
  /* During zr_radiosity_solve: the context told of progress (rounds
     done of the most there may be; zr__rad_progress) and asked about a
     cancel.  NULL once solved. */
  zr_context *progress_ctx;
  uint64_t progress_done, progress_total;
  /* The nodes, vertices and links are charged to the budget of the
     context that solved (NULL: none) until the solution is freed;
     over_budget tells that a growth failed for the budget. */
  struct zr_budget *budget;
  size_t charged;
  bool over_budget;
  zr_radiosity_params params;
  zr_radiosity_stats stats;
  uint64_t fingerprint;

  zr__rad_surface *surfs;
  size_t n_surfs;
  zr__rad_object_entry *objects;
  size_t n_objects;
  /* The triangles of the height fields radiosity models (the scene
     keeps only their samples), freed with the arrays. */
  zr_arena hf_meshes;

  zr__rad_node *nodes;
  size_t n_nodes, cap_nodes;
  zr__rad_link *links;
  size_t n_links, cap_links;
  zr__rad_vertex *verts;
  size_t n_verts, cap_verts;
  uint32_t *vhash; /* open addressing, vertex index + 1, 0 = empty */
  size_t hash_cap;

  /* The live links by receiver node, for the final gather at a ray
     hit: links recv_links[recv_start[n] .. recv_start[n + 1]) end at
     node n.  NULL with lookup 1, which reads no links. */
  uint32_t *recv_start, *recv_links;
  /* With the index above: the boundary polygon and its plane of each
     source node the final gather has asked for (a curved cell's 16
     chords an edge are 64 NURBS evaluations, a flat cell's corners 6
     evaluations), and the points of its visibility grid, made once by
     whichever thread asks first and kept (radiosity.c); NULL entries
     are not made yet. */
  struct zr__rad_poly *_Atomic *poly_cache;
  struct zr__rad_vgrid *_Atomic *vis_cache;
  size_t n_poly_cache; /* entries of both: the nodes when they were made */

  /* Volume clusters of surfaces (volume.c); clustered is false when
     initial linking pairs every two surfaces instead. */
  bool clustered;
  zr__rad_vol *vols;
  size_t n_vols;
  zr__rad_elem *elems;
  size_t n_elems;
  zr__rad_vlink *vlinks;
  size_t n_vlinks, cap_vlinks;
  uint64_t vol_rays; /* visibility rays of cluster links */

  /* A team's exchange buffers while it solves (refine.c, solve.c): the
     room the members' parts arrive in, this member's packed part and
     a sweep's send buffer, kept from one exchange to the next (see
     zr__team_room) and freed when the solve ends
     (zr__rad_team_buffers_free). */
  zr__team_room team_room, team_send;
  zr__pack team_pack;

  double light_power;  /* light sources' power onto the surfaces (est.) */
  double total_area;   /* of every surface */
  double power_ref;    /* emitted power (largest channel), BF_eps unit */
  double area_eps_abs; /* params.area_eps * total_area */
  zr__gauss_rule rule_recv, rule_src;
};

/* Frees the team's exchange buffers (team_room, team_send, team_pack). */
void zr__rad_team_buffers_free(zr_radiosity *rad);

/* ---- mesh.c ---- */
zr_status zr__rad_mesh_build(zr_radiosity *rad, zr_context *ctx);
/* The box around every finite primitive (the scene previewer's extent,
   preview.c); false, lo +inf and hi -inf, when there is none. */
bool zr__rad_finite_bounds(const zr_scene *scene, zr_vec3 *lo,
                           zr_vec3 *hi);
/* The bounds that clip infinite planes: the box around every finite
   primitive, stretched to the axis-aligned planes and widened by 10% of
   its diagonal; false when nothing bounds them.  The scene previewer
   (preview.c) clips planes to the same box. */
bool zr__rad_plane_bounds(const zr_scene *scene, zr_vec3 *lo, zr_vec3 *hi);
/* The exact surfaces of one primitive (not a CSG node) into out[] (room
   for 6): mesh is its faces for a mesh or height_field, lo and hi the
   plane bounds (NULL: planes have none).  The count, or -1 when the
   object has no area or is of a kind without surfaces. */
int zr__rad_primitive_surfaces(const zr_object *o, const struct zr_mesh *mesh,
                               const zr_vec3 *lo, const zr_vec3 *hi,
                               zr__surface out[6]);
/* Charges bytes of growth to rad's budget; false (over_budget set) when
   they do not fit. */
bool zr__rad_charge(zr_radiosity *rad, size_t bytes);
/* The surfaces of object (count 0 when it has none). */
const zr__rad_object_entry *zr__rad_object_find(const zr_radiosity *rad,
                                                const zr_object *object);

/* ---- quadtree.c ---- */
/* Adds the root node of surface s (and its vertices). */
zr_status zr__rad_add_root(zr_radiosity *rad, int32_t s);
/* Splits leaf n into four; false when out of memory. */
bool zr__rad_subdivide(zr_radiosity *rad, int32_t n);
/* Fills centre, normal, area and spread of a node from its surf, depth,
   iu and iv (refinement also uses it for cells not yet made). */
void zr__rad_node_geometry(const zr_radiosity *rad, zr__rad_node *node);
/* The cell of node n as {u0, u1, v0, v1}. */
void zr__rad_node_cell(const zr__rad_node *node, double cell[4]);
/* The leaf of surface s holding (u,v). */
int32_t zr__rad_leaf_at(const zr_radiosity *rad, int32_t s, double u,
                        double v);
/* Smoothed corner values from the leaves, with T-vertices made
   continuous along the larger cells' edges. */
void zr__rad_smooth(zr_radiosity *rad);
/* Bilinear interpolation of side's smoothed values inside leaf n. */
void zr__rad_interpolate(const zr_radiosity *rad, int32_t n, int side,
                         double u, double v, double out[3]);
void zr__rad_free_arrays(zr_radiosity *rad);
/* Frees the final gather's polygon cache (radiosity.c). */
void zr__rad_free_poly_cache(zr_radiosity *rad);

/* ---- refine.c ---- */
/* Links every pair of surfaces that see each other, then refines. */
zr_status zr__rad_link_all(zr_radiosity *rad);
/* Re-examines every link against BF_eps with the current radiosity;
   *changed counts the links split. */
zr_status zr__rad_refine_links(zr_radiosity *rad, size_t *changed);
/* Computes the transfer factors of links not yet final (shared among
   params.team's members, which then exchange them). */
zr_status zr__rad_finish_links(zr_radiosity *rad);
/* Whether the segment from..to crosses any surface of the scene. */
bool zr__rad_occluded(const zr_radiosity *rad, zr_vec3 from, zr_vec3 to);
/* The same with a hint of where the last blocker was (zr__bvh_occluded):
   the rays of one point to one source are mostly blocked by one leaf. */
bool zr__rad_occluded_hint(const zr_radiosity *rad, zr_vec3 from,
                           zr_vec3 to, zr_bvh_hint *hint);
/* Drops dead links from the array. */
void zr__rad_compact_links(zr_radiosity *rad);
/* Splits every leaf until it is at depth n_levels (uniform mode). */
zr_status zr__rad_uniform(zr_radiosity *rad, int n_levels);

/* ---- solve.c ---- */
/* Solves for B on the current links; fills iterations and residual. */
zr_status zr__rad_solve(zr_radiosity *rad, zr_context *ctx);
/* Tells the solve's context how far it is (ZR_PHASE_RADIOSITY);
   ZR_ECANCELLED when the solve must stop. */
zr_status zr__rad_progress(zr_radiosity *rad);
/* Emission, absorption and closure figures into rad->stats. */
void zr__rad_energy(zr_radiosity *rad);
/* The largest channel of a radiosity triple. */
static inline double zr__rad_max3(const double c[3]) {
  double m = c[0] > c[1] ? c[0] : c[1];
  return m > c[2] ? m : c[2];
}

/* ---- direct.c ---- */
/* Estimates the power the scene's light sources deliver onto the
   surfaces and adds it to power_ref (nothing without lights). */
void zr__rad_direct_power(zr_radiosity *rad);
/* Splits leaves where the light sources' direct light varies more than
   BF_eps allows, sets hd on every leaf and b to each leaf's source
   (E + rho hd), area means above. */
zr_status zr__rad_direct_refine(zr_radiosity *rad);
/* Sets hd on the leaves that refinement made since (no splitting). */
void zr__rad_direct_update(zr_radiosity *rad);
/* What leaf node emits or reflects of the light sources' direct light
   on side: E + rho hd, the source term of the radiosity equation. */
static inline void zr__rad_leaf_source(const zr_radiosity *rad,
                                       const zr__rad_node *node, int side,
                                       double out[3]) {
  const zr__rad_surface *s = &rad->surfs[node->surf];
  for (int c = 0; c < 3; c++)
    out[c] = s->emission[side][c] + s->rho[c] * node->hd[side][c];
}

/* ---- trim.c ---- */
/* Whether the point p of surface s survives its CSG (true untrimmed). */
bool zr__rad_trim_keeps(const zr__rad_surface *s, zr_vec3 p);
/* The area-weighted fraction of the parameter rectangle cell of s that
   survives, from an n x n grid of samples (1 untrimmed). */
double zr__rad_trim_fraction(const zr_radiosity *rad, const zr__rad_surface *s,
                             const double cell[4], int n);
/* Splits the cells that a trim crosses down to A_eps. */
zr_status zr__rad_trim_split(zr_radiosity *rad);

/* ---- cluster.c ---- */
/* Whether node is a cluster of a mesh's faces (more than one face's
   slot); [*f0, *f1) are its faces (either may be NULL). */
bool zr__rad_cluster(const zr_radiosity *rad, const zr__rad_node *node,
                     size_t *f0, size_t *f1);
/* A cluster whose faces do not all face one way. */
bool zr__rad_mixed_cluster(const zr_radiosity *rad, const zr__rad_node *node);
/* The factor from point p (normal n, the receiving side's) to the faces
   of cluster q that show side sside to p. */
double zr__rad_cluster_point_factor(const zr_radiosity *rad,
                                    const zr__rad_node *q, int sside,
                                    zr_vec3 p, zr_vec3 n);
/* The form factor of a link p (rside) <- q (sside) with a cluster at
   either end, without visibility. */
double zr__rad_cluster_link_factor(const zr_radiosity *rad,
                                   const zr__rad_node *p, int rside,
                                   const zr__rad_node *q, int sside);

/* ---- volume.c ---- */
/* Builds the cluster tree over the surfaces when the scene is large
   enough and the solver gathers alone (sets rad->clustered). */
zr_status zr__rad_vol_build(zr_radiosity *rad);
/* A list of ordered surface pairs (receiver, source) to link as
   link_all links every pair. */
typedef struct zr__rad_pairs {
  uint32_t *ij; /* 2 per pair */
  size_t n, cap;
  bool nomem;
} zr__rad_pairs;
/* The initial linking through the cluster tree: cluster links where
   the light they may carry is below BF_eps, surface pairs elsewhere. */
zr_status zr__rad_vol_link(zr_radiosity *rad, zr__rad_pairs *pairs);
/* Re-examines the cluster links against BF_eps with the current
   radiosity; *changed counts those split. */
zr_status zr__rad_vol_refine(zr_radiosity *rad, zr__rad_pairs *pairs,
                             size_t *changed);
/* Computes the weights of the cluster links that have none. */
zr_status zr__rad_vol_finish(zr_radiosity *rad);
/* Adds what the cluster links carry to their receivers' gathered
   values (after the node links' gather, before push-pull). */
void zr__rad_vol_gather(zr_radiosity *rad);
/* Adds the cluster links' irradiance at leaf and its ancestors on side
   to h (the final gather). */
void zr__rad_vol_incident(const zr_radiosity *rad, int32_t leaf, int side,
                          double h[3]);
void zr__rad_vol_free(zr_radiosity *rad);
/* The cluster links not split (counted with the links). */
size_t zr__rad_vol_live(const zr_radiosity *rad);
/* Links the surface pairs as zr__rad_link_all links all (refine.c). */
zr_status zr__rad_link_pairs(zr_radiosity *rad, const zr__rad_pairs *pairs);

/* ---- io.c ---- */
uint64_t zr__rad_fingerprint(const zr_scene *scene);

/* ---- radiosity.c ---- */
/* A solution object with the scene's surfaces and root nodes, no links. */
zr_status zr__rad_create(zr_context *ctx, const zr_scene *scene,
                         const zr_radiosity_params *params,
                         zr_radiosity **out);
/* The leaf holding a ray's hit of object at point (direction dir) and
   the side the ray arrives on; -1 when the object has no surface. */
int32_t zr__rad_hit_leaf(const zr_radiosity *rad, const zr_object *object,
                         zr_vec3 point, zr_vec3 dir, int *side);
/* Counts nodes, leaves, live links and vertices into rad->stats. */
void zr__rad_count(zr_radiosity *rad);
/* Indexes the live links by receiver (recv_start, recv_links). */
zr_status zr__rad_index_links(zr_radiosity *rad);
/*
 * The outgoing diffuse radiance of the solution where a ray with
 * direction dir hits object at point: (E + rho H) / pi of the side the
 * ray comes from, smoothed (bilinear over the leaf's corner vertices).
 * It holds the surface's emission (POV-Ray's emission * pigment), the
 * diffuse light of every bounce from emitting surfaces, first bounce
 * included, and the light of POV-Ray light sources after at least one
 * diffuse bounce: their direct light is the tracer's, per pixel
 * (direct.c).  It holds no ambient.  Units: the scene's radiance
 * units, as emission.  Returns
 * false (out black) when the object has no surface in the solution.
 */
/* Whether the solver models objects of o's kind; *faces is the number
   of mesh faces o brings (0 for other kinds).  lib/gi/choose.c asks. */
bool zr__rad_models(const zr_object *o, size_t *faces);
/* Whether POV-Ray's radiosity would take media into account in the
   scene: its radiosity block says "media on" and it has atmospheric or
   interior media (mesh.c).  The solver carries no light through media:
   zr_gi_choose then takes the cache, and the solver warns. */
bool zr__rad_media_counts(const zr_scene *scene);
/* POV-Ray's keyword for an object kind ("sphere", "isosurface"). */
const char *zr__rad_kind_name(zr_object_kind kind);
bool zr__radiosity_radiance(const zr_radiosity *rad, const zr_object *object,
                            zr_vec3 point, zr_vec3 dir, zr_rgb *out);

#endif /* ZR_RADIOSITY_RADIOSITY_H */
