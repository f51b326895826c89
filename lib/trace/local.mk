# lib/trace/local.mk - the tracer: bounds, BVH, intersections, shading,
# camera rays and antialiasing.
lib_libzrcube_la_SOURCES += \
	lib/scene/bounds.c \
	lib/trace/bvh.c lib/trace/bvh.h \
	lib/trace/csg.c \
	lib/trace/obj_quadric.c lib/trace/obj_quadric.h \
	lib/trace/obj_poly.c lib/trace/obj_poly.h \
	lib/trace/intersect.c lib/trace/intersect.h \
	lib/trace/render.c lib/trace/render.h \
	lib/trace/shade.c lib/trace/shade.h

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
check_PROGRAMS += tests/test_shapes
TESTS += tests/test_shapes
tests_test_shapes_SOURCES = tests/test_shapes.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_shapes_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_shapes_LDADD = $(TEST_LDADD)
tests_test_shapes_LDFLAGS = -static
$(tests_test_shapes_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
