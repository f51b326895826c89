# lib/trace/local.mk - the tracer: bounds, BVH, intersections, shading,
# camera rays and antialiasing.
lib_libzrcube_la_SOURCES += \
	lib/trace/bounds.c \
	lib/trace/bounds_csg.c \
	lib/trace/prepare.c lib/trace/prepare.h \
	lib/trace/bvh.c lib/trace/bvh.h lib/trace/bvh_wide.h \
	lib/trace/csg.c \
	lib/trace/obj_quadric.c lib/trace/obj_quadric.h \
	lib/trace/obj_poly.c lib/trace/obj_poly.h \
	lib/trace/intersect.c lib/trace/intersect.h \
	lib/trace/shape.c lib/trace/shape.h \
	lib/trace/obj_sphere.c lib/trace/obj_box.c lib/trace/obj_plane.c \
	lib/trace/obj_triangle.c lib/trace/obj_cone.c lib/trace/obj_disc.c \
	lib/trace/render.c lib/trace/render.h \
	lib/trace/shade.c lib/trace/shade.h \
	lib/trace/dispersion.c lib/trace/dispersion.h \
	lib/trace/photons.c lib/trace/photons.h \
	lib/trace/subsurface.c

# The Embree backend for meshes (configure --with-embree).
if ZR_EMBREE
lib_libzrcube_la_SOURCES += lib/trace/embree.c
endif
EXTRA_DIST += lib/trace/embree.c
lib_libzrcube_la_SOURCES += lib/trace/embree.h

# The tracer's tests call zr__ functions, which the shared library hides
# (-fvisibility=hidden): they link the static archive.
check_PROGRAMS += tests/test_intersect
TESTS += tests/test_intersect
tests_test_intersect_SOURCES = tests/test_intersect.c
tests_test_intersect_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_intersect_LDADD = $(TEST_LDADD)
tests_test_intersect_LDFLAGS = -static

check_PROGRAMS += tests/test_bvh
TESTS += tests/test_bvh
tests_test_bvh_SOURCES = tests/test_bvh.c
tests_test_bvh_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_bvh_LDADD = $(TEST_LDADD)
tests_test_bvh_LDFLAGS = -static

check_PROGRAMS += tests/test_shade
TESTS += tests/test_shade
tests_test_shade_SOURCES = tests/test_shade.c
tests_test_shade_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_shade_LDADD = $(TEST_LDADD)
tests_test_shade_LDFLAGS = -static

check_PROGRAMS += tests/test_render
TESTS += tests/test_render
tests_test_render_SOURCES = tests/test_render.c
tests_test_render_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_render_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS)
tests_test_render_LDADD = $(TEST_LDADD) $(PTHREAD_LIBS)
tests_test_render_LDFLAGS = -static

# Meshes (mesh, mesh2, smooth_triangle) and text, each with its own
# inner bounding and exact tests (issue 3).
lib_libzrcube_la_SOURCES += \
	lib/trace/obj_mesh.c lib/trace/obj_mesh.h \
	lib/trace/obj_text.c lib/trace/obj_text.h
check_PROGRAMS += tests/test_mesh tests/test_text
TESTS += tests/test_mesh tests/test_text
tests_test_mesh_SOURCES = tests/test_mesh.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_mesh_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_mesh_LDADD = $(TEST_LDADD)
tests_test_mesh_LDFLAGS = -static
tests_test_text_SOURCES = tests/test_text.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_text_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_text_LDADD = $(TEST_LDADD)
tests_test_text_LDFLAGS = -static
$(tests_test_mesh_OBJECTS) $(tests_test_text_OBJECTS): \
	grammar/pov-parse.h grammar/pov-scan.h

# CSG, quadrics and clipping (issue 3): parsed scenes to crossings.
check_PROGRAMS += tests/test_csg
TESTS += tests/test_csg
tests_test_csg_SOURCES = tests/test_csg.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_csg_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_csg_LDADD = $(TEST_LDADD)
tests_test_csg_LDFLAGS = -static
$(tests_test_csg_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Camera projections, light source kinds, fog, sky_sphere and rainbows
# (issue 3), and their tests.
lib_libzrcube_la_SOURCES += \
	lib/trace/camera.c \
	lib/trace/camera_mesh.c \
	lib/trace/lights.c lib/trace/lights.h \
	lib/trace/atmosphere.c lib/trace/atmosphere.h
check_PROGRAMS += tests/test_camlight
TESTS += tests/test_camlight
tests_test_camlight_SOURCES = tests/test_camlight.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_camlight_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_camlight_LDADD = $(TEST_LDADD)
tests_test_camlight_LDFLAGS = -static
$(tests_test_camlight_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
# mesh_camera, omnimax and transform functions (lib/trace/camera_mesh.c,
# lib/sdl/build_meshcam.c).
check_PROGRAMS += tests/test_meshcam
TESTS += tests/test_meshcam
tests_test_meshcam_SOURCES = tests/test_meshcam.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_meshcam_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_meshcam_LDADD = $(TEST_LDADD)
tests_test_meshcam_LDFLAGS = -static
$(tests_test_meshcam_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Torus, polygon, superellipsoid, prism, lathe, blob and sor, and the
# polynomial root finder they and later shapes share (issue 3).
lib_libzrcube_la_SOURCES += \
	lib/trace/roots.c lib/trace/roots.h \
	lib/trace/obj_shapes.h \
	lib/trace/obj_torus.c \
	lib/trace/obj_polygon.c \
	lib/trace/obj_superellipsoid.c \
	lib/trace/obj_prism.c \
	lib/trace/obj_lathe.c \
	lib/trace/obj_blob.c \
	lib/trace/obj_sor.c

# The sphere sweep and the julia fractal (lib/trace/obj_sweep.h).
lib_libzrcube_la_SOURCES += \
	lib/trace/obj_sweep.c lib/trace/obj_sweep.h \
	lib/trace/obj_julia.c

# The isosurface, the height field and the ovus
# (lib/trace/obj_isosurface.h), and their tests.
lib_libzrcube_la_SOURCES += \
	lib/trace/obj_isosurface.c lib/trace/obj_isosurface.h \
	lib/trace/obj_height_field.c \
	lib/trace/obj_ovus.c \
	lib/trace/obj_parametric.c
check_PROGRAMS += tests/test_isosurface
TESTS += tests/test_isosurface
tests_test_isosurface_SOURCES = tests/test_isosurface.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_isosurface_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_isosurface_LDADD = $(TEST_LDADD)
tests_test_isosurface_LDFLAGS = -static
$(tests_test_isosurface_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
check_PROGRAMS += tests/test_height_field
TESTS += tests/test_height_field
tests_test_height_field_SOURCES = tests/test_height_field.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_height_field_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_height_field_LDADD = $(TEST_LDADD)
tests_test_height_field_LDFLAGS = -static
$(tests_test_height_field_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
check_PROGRAMS += tests/test_ovus
TESTS += tests/test_ovus
tests_test_ovus_SOURCES = tests/test_ovus.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_ovus_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_ovus_LDADD = $(TEST_LDADD)
tests_test_ovus_LDFLAGS = -static
$(tests_test_ovus_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
check_PROGRAMS += tests/test_parametric
TESTS += tests/test_parametric
tests_test_parametric_SOURCES = tests/test_parametric.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_parametric_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_parametric_LDADD = $(TEST_LDADD)
tests_test_parametric_LDFLAGS = -static
$(tests_test_parametric_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
check_PROGRAMS += tests/test_shapes
TESTS += tests/test_shapes
tests_test_shapes_SOURCES = tests/test_shapes.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_shapes_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_shapes_LDADD = $(TEST_LDADD)
tests_test_shapes_LDFLAGS = -static
$(tests_test_shapes_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
# light_group and blob components' own textures, rendered.
check_PROGRAMS += tests/test_lightgroup
TESTS += tests/test_lightgroup
tests_test_lightgroup_SOURCES = tests/test_lightgroup.c \
	tests/parse_fixture.c tests/parse_fixture.h tests/test_util.h
tests_test_lightgroup_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_lightgroup_LDADD = $(TEST_LDADD)
tests_test_lightgroup_LDFLAGS = -static
$(tests_test_lightgroup_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# bicubic_patch, sphere_sweep and julia_fractal, parsed and traced.
check_PROGRAMS += tests/test_surfaces
TESTS += tests/test_surfaces
tests_test_surfaces_SOURCES = tests/test_surfaces.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_surfaces_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_surfaces_LDADD = $(TEST_LDADD)
tests_test_surfaces_LDFLAGS = -static
$(tests_test_surfaces_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Participating media: interior and atmospheric media (lib/trace/media.c).
lib_libzrcube_la_SOURCES += lib/trace/media.c lib/trace/media.h
check_PROGRAMS += tests/test_media
TESTS += tests/test_media
tests_test_media_SOURCES = tests/test_media.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_media_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_media_LDADD = $(TEST_LDADD)
tests_test_media_LDFLAGS = -static
$(tests_test_media_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# julia_fractal's escape rule against POV-Ray (skipped without it).
TESTS += tests/test_julia_probe.sh
EXTRA_DIST += tests/test_julia_probe.sh bench/julia_probe.sh

# The metallic tint against POV-Ray (skipped without it); the fit.
TESTS += tests/test_metallic_probe.sh
EXTRA_DIST += tests/test_metallic_probe.sh bench/metallic_probe.sh \
	bench/metallic_fit.py

# The Embree backend against the built-in hierarchy (issue 13); in a
# build without Embree it checks zr_context_set_accel's refusal alone.
check_PROGRAMS += tests/test_embree
TESTS += tests/test_embree
tests_test_embree_SOURCES = tests/test_embree.c
tests_test_embree_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_embree_LDADD = $(TEST_LDADD)
tests_test_embree_LDFLAGS = -static

# Shadow shafts of area lights (one test for a light's rays).
lib_libzrcube_la_SOURCES += lib/trace/shaft.c lib/trace/shaft.h
check_PROGRAMS += tests/test_shaft
TESTS += tests/test_shaft
tests_test_shaft_SOURCES = tests/test_shaft.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_shaft_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_shaft_LDADD = $(TEST_LDADD)
tests_test_shaft_LDFLAGS = -static
$(tests_test_shaft_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
