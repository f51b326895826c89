/*
 * shapes.h - the data of the shapes that carry more than a few numbers:
 * meshes (mesh, mesh2, smooth_triangle), height fields, text,
 * sphere sweeps and julia fractals.  It is part of the scene model
 * (zr_object points to it); the tracer's operations on it are in
 * lib/trace (obj_mesh.h, obj_text.h, obj_sweep.h), which the parser
 * calls to finish it.
 */
#ifndef ZR_SCENE_SHAPES_H
#define ZR_SCENE_SHAPES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "scene/scene.h"

/* ---- meshes (lib/trace/obj_mesh.c) ---- */

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
  /* The mesh's Embree scene when lib/trace/embree.c traces it (NULL:
     the hierarchy above does); the scene's embree member owns it. */
  const struct zr_embree_mesh *accel;
  zr_vec3 lo, hi; /* the box of every vertex the faces use */
};

/* ---- height fields (lib/trace/obj_height_field.c) ---- */

/* The most levels a height field's block hierarchy has: a side of 65536
   samples is 8192 blocks, halved 13 times to one. */
#define ZR_HF_MAX_LEVELS 20
/* A leaf block is ZR_HF_BLOCK x ZR_HF_BLOCK squares of the grid. */
#define ZR_HF_BLOCK 8

/*
 * A height field's samples, kept as the file stores them (8 or 16-bit
 * codes, or floats for a function), and the least and greatest height
 * of each block of the grid: level 0 holds the leaf blocks, each level
 * above holds blocks of 2 x 2 of the one below, up to one block.  The
 * triangles are made from the samples where a ray needs them: a grid of
 * w x h samples costs w h (bits / 8) bytes and 8 bytes a leaf block
 * (1/8 of a byte a square, 1/6 with the levels above).
 */
struct zr_hf_grid {
  const void *samples; /* w * h, image order: row r at z = 1 - r/(h-1) */
  int bits;            /* 8: code / 255, 16: code / 65535, 32: float */
  int w, h;
  float lo, hi; /* the least and greatest sample */
  int levels;
  struct {
    size_t start; /* of the level's blocks in range (pairs) */
    int nx, nz;
  } level[ZR_HF_MAX_LEVELS];
  float *range; /* least, greatest height of each block */
};

/* ---- text (lib/trace/obj_text.c) ---- */

/* One piece of an outline in text coordinates: a quadratic Bezier curve
   p0 p1 p2, or the line p0 p2 when line is set. */
typedef struct zr_text_segment {
  double p0[2], p1[2], p2[2];
  bool line;
} zr_text_segment;

/* A placed glyph: segments[first .. first + n) and their 2D box. */
typedef struct zr_text_glyph {
  size_t first, n;
  double lo[2], hi[2];
} zr_text_glyph;

struct zr_text {
  zr_text_segment *segments;
  size_t n_segments;
  zr_text_glyph *glyphs;
  size_t n_glyphs;
  double thickness;
  zr_vec3 lo, hi; /* the box of every glyph, empty when none */
};

/* ---- sphere_sweep (lib/trace/obj_sweep.c) ---- */

/* One piece of a sphere sweep: the ball of centre c(u) and radius r(u)
   moving for u in [0, 1], c(u) = c[0] + c[1] u + c[2] u^2 + c[3] u^3,
   r(u) likewise (c[2], c[3], r[2], r[3] zero for a linear one). */
typedef struct zr_sweep_segment {
  zr_vec3 c[4];
  double r[4];
  zr_vec3 lo, hi; /* a box holding every ball of the piece */
} zr_sweep_segment;

typedef enum zr_sweep_spline {
  ZR_SWEEP_LINEAR = 0,
  ZR_SWEEP_B_SPLINE,
  ZR_SWEEP_CUBIC /* cubic_spline: Catmull-Rom */
} zr_sweep_spline;

struct zr_sphere_sweep {
  zr_sweep_spline spline;
  /* tolerance: the manual's "depth tolerance" against self-shading
     ("Sphere Sweep", 3.4.5.1.13), kept for the record; the crossings
     here are exact, so it changes nothing. */
  double tolerance;
  /* The spheres as written (kept while parsing). */
  zr_vec3 *centres;
  double *radii;
  size_t n_spheres, n_expected;
  bool centre_pending; /* a centre was read, its radius not yet */
  zr_sweep_segment *segments;
  size_t n_segments;
  zr_vec3 lo, hi;
};

/* ---- julia_fractal (lib/trace/obj_julia.c) ---- */

typedef enum zr_julia_algebra {
  ZR_JULIA_QUATERNION = 0,
  ZR_JULIA_HYPERCOMPLEX
} zr_julia_algebra;

typedef enum zr_julia_function {
  ZR_JULIA_SQR = 0,
  ZR_JULIA_CUBE,
  /* hypercomplex only: */
  ZR_JULIA_RECIPROCAL,
  ZR_JULIA_EXP,
  ZR_JULIA_LN,
  ZR_JULIA_SIN,
  ZR_JULIA_ASIN,
  ZR_JULIA_COS,
  ZR_JULIA_ACOS,
  ZR_JULIA_TAN,
  ZR_JULIA_ATAN,
  ZR_JULIA_SINH,
  ZR_JULIA_ASINH,
  ZR_JULIA_COSH,
  ZR_JULIA_ACOSH,
  ZR_JULIA_TANH,
  ZR_JULIA_ATANH,
  ZR_JULIA_PWR /* pwr(X, Y): z^(X + i Y) */
} zr_julia_function;

struct zr_julia {
  double c[4];     /* the julia parameter */
  zr_julia_algebra algebra;
  zr_julia_function function;
  double exponent[2]; /* pwr's */
  int max_iteration; /* default 20 */
  double precision;  /* default 20, at least 1 */
  /* slice <n>, d: the hyperplane n . h = d (n a unit vector) that 3-D
     space is mapped onto (lib/trace/obj_julia.c). */
  double slice[4], distance;
  double escape; /* the escape radius: |h| beyond it escapes; the
                    bounding sphere about the origin too */
};

#endif /* ZR_SCENE_SHAPES_H */
