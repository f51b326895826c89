# lib/trace/local.mk - the tracer: bounds, BVH, intersections, shading,
# camera rays and antialiasing.
lib_libzrcube_la_SOURCES += \
	lib/scene/bounds.c \
	lib/trace/bvh.c lib/trace/bvh.h \
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
