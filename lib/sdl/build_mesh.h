/*
 * build_mesh.h - building mesh, mesh2, smooth_triangle and text objects
 * from the grammar's actions (lib/sdl/build_mesh.c).
 */
#ifndef ZR_SDL_BUILD_MESH_H
#define ZR_SDL_BUILD_MESH_H

#include "sdl/sdl.h"

/* The lists of a mesh2, in the order the manual gives them. */
typedef enum zr_sdl_mesh2_list {
  ZR_SDL_M2_VERTICES = 0,
  ZR_SDL_M2_NORMALS,
  ZR_SDL_M2_UVS,
  ZR_SDL_M2_FACES,
  ZR_SDL_M2_NORMAL_INDICES,
  ZR_SDL_M2_UV_INDICES,
  ZR_SDL_M2_TEXTURES
} zr_sdl_mesh2_list;

/* mesh { M ... }: a copy of the declared mesh M (an error when M is
   another kind of object). */
zr_object *zr__sdl_mesh_copy(zr_sdl_parser *p, const zr_object *o,
                             const zr_sdl_loc *loc);
/* An empty mesh (mesh2 set for mesh2's messages). */
zr_object *zr__sdl_mesh_new(zr_sdl_parser *p, bool mesh2,
                            const zr_sdl_loc *loc);
/* mesh { triangle { v0, v1, v2 [uv_vectors a, b, c] [texture] } }, or a
   smooth_triangle when normals (three) is not NULL; uvs (three, or
   NULL) are the uv_vectors.  texture may be NULL. */
bool zr__sdl_mesh_triangle(zr_sdl_parser *p, zr_object *o,
                           const zr_sdl_expr vertices[3],
                           const zr_sdl_loc vertex_locs[3],
                           const zr_sdl_expr *normals,
                           const zr_sdl_loc *normal_locs,
                           const zr_sdl_expr *uvs, const zr_sdl_loc *uv_locs,
                           const zr_texture *texture);
/* The corners of a T_TRIANGLE_RUN token (corners: its nine values,
   tokens.c; loc is the token's), for a triangle object or, with the
   _mesh_ form, as a face of mesh o with no texture of its own. */
void zr__sdl_triangle_run(const double *corners, zr_vec3 out[3]);
bool zr__sdl_mesh_triangle_run(zr_sdl_parser *p, zr_object *o,
                               const double *corners,
                               const zr_sdl_loc *loc);
/* The same for a T_SMOOTH_TRIANGLE_RUN token (run: its corners and
   normals, tokens.c), as a smooth_triangle object (a mesh of one face)
   or a face of mesh o. */
zr_object *zr__sdl_smooth_triangle_run(zr_sdl_parser *p,
                                       const zr_sdl_smooth_run *run,
                                       const zr_sdl_loc *loc);
bool zr__sdl_mesh_smooth_triangle_run(zr_sdl_parser *p, zr_object *o,
                                      const zr_sdl_smooth_run *run,
                                      const zr_sdl_loc *loc);
bool zr__sdl_mesh_inside_vector(zr_sdl_parser *p, zr_object *o,
                                const zr_sdl_expr *e, const zr_sdl_loc *loc);
/* Checks the indices and builds the mesh's BVH; after the last item. */
bool zr__sdl_mesh_done(zr_sdl_parser *p, zr_object *o,
                       const zr_sdl_loc *loc);

/*
 * mesh2's lists.  open starts one (at loc, its keyword); when fast is
 * true the grammar has read nothing past its '{' and the plain numbers
 * and vectors that follow are read straight from the token array, up to
 * the first token that needs the grammar.  item takes one value the
 * grammar parsed (the count first), close checks the count at '}'.
 */
bool zr__sdl_mesh2_open(zr_sdl_parser *p, zr_object *o,
                        zr_sdl_mesh2_list list, const zr_sdl_loc *loc,
                        bool fast);
bool zr__sdl_mesh2_item(zr_sdl_parser *p, zr_object *o,
                        const zr_sdl_expr *e, const zr_sdl_loc *loc);
bool zr__sdl_mesh2_texture(zr_sdl_parser *p, zr_object *o,
                           const zr_texture *t, const zr_sdl_loc *loc);
bool zr__sdl_mesh2_close(zr_sdl_parser *p, zr_object *o,
                         const zr_sdl_loc *loc);

/* smooth_triangle { v0, n0, v1, n1, v2, n2 }: a mesh of one face. */
zr_object *zr__sdl_smooth_triangle(zr_sdl_parser *p, const zr_sdl_loc *loc,
                                   const zr_sdl_expr e[6],
                                   const zr_sdl_loc locs[6]);

/* text { ttf "font" "string" thickness, offset }: font is the file name,
   or NULL with internal_font the number after 'internal'. */
zr_object *zr__sdl_text(zr_sdl_parser *p, const zr_sdl_loc *loc,
                        const char *font, double internal_font,
                        const zr_sdl_loc *font_loc, const char *string,
                        const zr_sdl_expr *thickness,
                        const zr_sdl_loc *thickness_loc,
                        const zr_sdl_expr *offset,
                        const zr_sdl_loc *offset_loc);

#endif /* ZR_SDL_BUILD_MESH_H */
