/*
 * prepare.h - the scene made ready for tracing (lib/trace/prepare.c).
 */
#ifndef ZR_TRACE_PREPARE_H
#define ZR_TRACE_PREPARE_H

#include "core/context.h"
#include "scene/scene.h"

/*
 * Ends construction: flattens unions into scene->primitives, resolves
 * default textures, then builds the tracer's BVH.  Called once by the
 * parser after the last statement.
 */
zr_status zr__scene_finish(zr_scene *scene, zr_context *ctx);

/* Makes *prim's per-texture copies when it is a mesh with a texture
   list (lib/trace/obj_mesh.c); *prim then points to a new copy.  A no-op
   for other objects. */
zr_status zr__mesh_instance(zr_arena *arena, const zr_object **prim);

#endif /* ZR_TRACE_PREPARE_H */
