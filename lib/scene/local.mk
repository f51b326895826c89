lib_libzrcube_la_SOURCES += \
	lib/scene/scene.c lib/scene/scene.h

# Patterns, noise, colour maps, image maps and normals.
lib_libzrcube_la_SOURCES += \
	lib/scene/pattern.c lib/scene/pattern.h \
	lib/scene/texture.c lib/scene/texture.h

check_PROGRAMS += tests/test_pattern
TESTS += tests/test_pattern
tests_test_pattern_SOURCES = tests/test_pattern.c
tests_test_pattern_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_pattern_LDADD = $(TEST_LDADD)
tests_test_pattern_LDFLAGS = -static
