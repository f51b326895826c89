/*
 * obj_mesh.h - triangle meshes (mesh, mesh2, smooth_triangle): the shared
 * data of one mesh, its own bounding volume hierarchy, and the ray and
 * inside tests the tracer dispatches to (lib/trace/intersect.c).
 */
#ifndef ZR_TRACE_OBJ_MESH_H
#define ZR_TRACE_OBJ_MESH_H

#include <stdbool.h>
#include <stdint.h>

#include "scene/scene.h"

typedef struct zr_mesh_node zr_mesh_node;

/*
 * One mesh.  Every index array has n_faces rows; the optional ones are
 * NULL when the mesh has no such data.  After zr__mesh_build() the faces
 * (and their rows in every array) are in the order of the BVH's leaves.
 * Objects made from the mesh (object { M ... }) point to the same
 * struct: the triangles are never copied.
 */
struct zr_mesh {
  zr_vec3 *vertices;
  size_t n_vertices, cap_vertices;
  zr_vec3 *normals;
  size_t n_normals, cap_normals;
  double (*uvs)[2]; /* uv_vectors, for uv_mapping */
  size_t n_uvs, cap_uvs;
  uint32_t (*faces)[3];
  size_t n_faces, cap_faces;
  uint32_t (*face_normals)[3]; /* NULL: every face is flat */
  uint32_t (*face_uvs)[3];
  /* Texture list indices of each face's corners, -1 for none (the
     object's own texture); NULL when no face has one. */
  int32_t (*face_textures)[3];
  const zr_texture **textures; /* texture_list */
  size_t n_textures;
  bool has_inside; /* inside_vector given: the mesh encloses a volume */
  zr_vec3 inside_vector;
  /* face_row[i]: the row of the i-th face written, for mesh_camera,
     which numbers faces in the order of the scene file. */
  uint32_t *face_row;
  zr_mesh_node *nodes;
  size_t n_nodes;
  zr_vec3 lo, hi; /* the box of every vertex the faces use */
};

/* One crossing of a ray with a mesh, in the mesh's own coordinates. */
typedef struct zr_mesh_crossing {
  double t;
  zr_vec3 normal;  /* any length, smooth when the face has normals */
  int32_t texture; /* index into the texture list, -1 for none */
  double u, v;     /* surface coordinates ("UV Mapping"); meshes only */
  size_t face;     /* which face (radiosity looks its cell up by it) */
} zr_mesh_crossing;

/* Builds the BVH (reordering the faces) and checks the indices; the
   first bad index is reported in *bad_face (status ZR_ESCENE). */
zr_status zr__mesh_build(struct zr_mesh *mesh, zr_arena *arena,
                         size_t *bad_face);

/* The nearest two crossings with tmin < t < tmax, nearest first. */
int zr__mesh_crossings(const struct zr_mesh *mesh, zr_vec3 org, zr_vec3 dir,
                       double tmin, double tmax, zr_mesh_crossing out[2]);

/* Whether p (mesh coordinates) is inside: an odd number of crossings
   along the inside vector.  False when the mesh has no inside_vector. */
bool zr__mesh_inside(const struct zr_mesh *mesh, zr_vec3 p);

/* The object a crossing with texture index k reports. */
static inline const zr_object *zr__mesh_hit_object(const zr_object *o,
                                                   int32_t k) {
  if (k < 0 || !o->u.mesh.textured)
    return o;
  return &o->u.mesh.textured[k];
}

#endif /* ZR_TRACE_OBJ_MESH_H */
