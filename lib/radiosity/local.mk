# lib/radiosity/local.mk - hierarchical radiosity on exact surfaces:
# Gauss rules, exact form factors, NURBS and parametric surfaces.
lib_libzrcube_la_SOURCES += \
	lib/radiosity/formfactor.c lib/radiosity/formfactor.h \
	lib/radiosity/nurbs.c lib/radiosity/nurbs.h \
	lib/radiosity/quadrature.c lib/radiosity/quadrature.h \
	lib/radiosity/surface.c lib/radiosity/surface.h \
	lib/radiosity/radiosity.h lib/radiosity/radiosity.c \
	lib/radiosity/mesh.c lib/radiosity/quadtree.c \
	lib/radiosity/refine.c lib/radiosity/solve.c lib/radiosity/io.c \
	lib/radiosity/workers.c lib/radiosity/workers.h lib/radiosity/trim.c \
	lib/radiosity/direct.c lib/radiosity/meshimage.c \
	lib/radiosity/cluster.c lib/radiosity/volume.c \
	lib/radiosity/preview.c

check_PROGRAMS += tests/test_formfactor tests/test_nurbs \
	tests/test_quadtree tests/test_radiosity tests/test_rad_mesh \
	tests/test_rad_torus
TESTS += tests/test_formfactor tests/test_nurbs tests/test_quadtree \
	tests/test_radiosity tests/test_rad_mesh tests/test_rad_torus
tests_test_rad_torus_SOURCES = tests/test_rad_torus.c
tests_test_rad_torus_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_rad_torus_LDADD = $(TEST_LDADD)
tests_test_rad_torus_LDFLAGS = -static
tests_test_rad_mesh_SOURCES = tests/test_rad_mesh.c
tests_test_rad_mesh_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_rad_mesh_LDADD = $(TEST_LDADD)
tests_test_rad_mesh_LDFLAGS = -static
tests_test_quadtree_SOURCES = tests/test_quadtree.c
tests_test_quadtree_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_quadtree_LDADD = $(TEST_LDADD)
tests_test_quadtree_LDFLAGS = -static
tests_test_radiosity_SOURCES = tests/test_radiosity.c
tests_test_radiosity_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_radiosity_LDADD = $(TEST_LDADD)
tests_test_radiosity_LDFLAGS = -static
tests_test_formfactor_SOURCES = tests/test_formfactor.c
tests_test_formfactor_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_formfactor_LDADD = $(TEST_LDADD)
tests_test_nurbs_SOURCES = tests/test_nurbs.c
tests_test_nurbs_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_nurbs_LDADD = $(TEST_LDADD)
# The library hides zr__ symbols (-fvisibility=hidden), so unit tests of
# internal functions link its static archive, where hidden symbols still
# resolve.
tests_test_formfactor_LDFLAGS = -static
tests_test_nurbs_LDFLAGS = -static
