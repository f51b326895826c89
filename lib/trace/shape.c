/*
 * shape.c - the table of shape operations, one entry per object kind
 * (lib/trace/shape.h); each entry is defined in the primitive's own
 * file.  A new primitive is a new zr_object_kind, a new file with its
 * zr_shape_ops, and a line here.
 */
#include "trace/shape.h"

const zr_shape_ops *const zr__shapes[] = {
    [ZR_OBJ_SPHERE] = &zr__shape_sphere,
    [ZR_OBJ_BOX] = &zr__shape_box,
    [ZR_OBJ_PLANE] = &zr__shape_plane,
    [ZR_OBJ_TRIANGLE] = &zr__shape_triangle,
    [ZR_OBJ_CYLINDER] = &zr__shape_cylinder,
    [ZR_OBJ_CONE] = &zr__shape_cone,
    [ZR_OBJ_DISC] = &zr__shape_disc,
    [ZR_OBJ_UNION] = &zr__shape_union,
    [ZR_OBJ_MESH] = &zr__shape_mesh,
    [ZR_OBJ_TEXT] = &zr__shape_text,
    [ZR_OBJ_INTERSECTION] = &zr__shape_intersection,
    [ZR_OBJ_MERGE] = &zr__shape_merge,
    [ZR_OBJ_QUADRIC] = &zr__shape_quadric,
    [ZR_OBJ_TORUS] = &zr__shape_torus,
    [ZR_OBJ_POLYGON] = &zr__shape_polygon,
    [ZR_OBJ_SUPERELLIPSOID] = &zr__shape_superellipsoid,
    [ZR_OBJ_PRISM] = &zr__shape_prism,
    [ZR_OBJ_LATHE] = &zr__shape_lathe,
    [ZR_OBJ_BLOB] = &zr__shape_blob,
    [ZR_OBJ_POLY] = &zr__shape_poly,
    [ZR_OBJ_SOR] = &zr__shape_sor,
    [ZR_OBJ_SPHERE_SWEEP] = &zr__shape_sphere_sweep,
    [ZR_OBJ_JULIA] = &zr__shape_julia,
    [ZR_OBJ_ISOSURFACE] = &zr__shape_isosurface,
    [ZR_OBJ_HEIGHT_FIELD] = &zr__shape_height_field,
    [ZR_OBJ_OVUS] = &zr__shape_ovus,
    [ZR_OBJ_PARAMETRIC] = &zr__shape_parametric,
};

/* Every kind has its entry: the enum's last member is the table's last
   row, and a missing row in between is caught by tests/test_intersect.c
   (every entry named). */
_Static_assert(sizeof zr__shapes / sizeof zr__shapes[0] ==
                   ZR_OBJ_PARAMETRIC + 1,
               "one table entry per zr_object_kind");
