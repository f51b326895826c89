# lib/radiosity/local.mk - hierarchical radiosity on exact surfaces:
# Gauss rules, exact form factors, NURBS and parametric surfaces.
lib_libzrcube_la_SOURCES += \
	lib/radiosity/formfactor.c lib/radiosity/formfactor.h \
	lib/radiosity/nurbs.c lib/radiosity/nurbs.h \
	lib/radiosity/quadrature.c lib/radiosity/quadrature.h \
	lib/radiosity/surface.c lib/radiosity/surface.h

check_PROGRAMS += tests/test_formfactor tests/test_nurbs
TESTS += tests/test_formfactor tests/test_nurbs
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
