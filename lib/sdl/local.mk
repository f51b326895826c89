# lib/sdl/local.mk - the scene language at run time: token arrays,
# keywords, the directive engine, values and symbol tables, and the
# helpers that build the scene model (the grammar is in grammar/).
lib_libzrcube_la_SOURCES += \
	lib/sdl/sdl.h \
	lib/sdl/build.c \
	lib/sdl/build_object.c \
	lib/sdl/build_warp.c \
	lib/sdl/builtins.c \
	lib/sdl/control.c \
	lib/sdl/directive.c \
	lib/sdl/fastexpr.c \
	lib/sdl/fileio.c \
	lib/sdl/keywords.c \
	lib/sdl/numlist.c \
	lib/sdl/spline.h \
	lib/sdl/spline.c \
	lib/sdl/symtab.c \
	lib/sdl/tokens.c \
	lib/sdl/values.c

# The tests call zr__ functions, which the shared library hides
# (-fvisibility=hidden): they link the static archive.
check_PROGRAMS += tests/test_lexer tests/test_parser
TESTS += tests/test_lexer tests/test_parser
tests_test_lexer_SOURCES = tests/test_lexer.c
tests_test_lexer_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_lexer_LDADD = $(TEST_LDADD)
tests_test_lexer_LDFLAGS = -static
tests_test_parser_SOURCES = tests/test_parser.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_parser_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_parser_LDADD = $(TEST_LDADD)
tests_test_parser_LDFLAGS = -static

# These sources include the generated grammar headers: make them first
# even when a single target is asked for (BUILT_SOURCES only covers
# `make`, `make check` and `make install`).
$(lib_libzrcube_la_OBJECTS) $(tests_test_lexer_OBJECTS) \
	$(tests_test_parser_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# The directive language and values (issue 3).
check_PROGRAMS += tests/test_directives
TESTS += tests/test_directives
tests_test_directives_SOURCES = tests/test_directives.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_directives_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_directives_LDADD = $(TEST_LDADD)
tests_test_directives_LDFLAGS = -static
$(tests_test_directives_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Runs of plain mesh2 items read from the bytes (lib/sdl/numlist.c).
check_PROGRAMS += tests/test_numlist
TESTS += tests/test_numlist
tests_test_numlist_SOURCES = tests/test_numlist.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_numlist_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_numlist_LDADD = $(TEST_LDADD)
tests_test_numlist_LDFLAGS = -static
$(tests_test_numlist_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# User-defined functions: the compiler (lib/sdl/function.c; the machine
# is lib/fn) and their tests.
lib_libzrcube_la_SOURCES += lib/sdl/function.h lib/sdl/function.c
check_PROGRAMS += tests/test_function
TESTS += tests/test_function
tests_test_function_SOURCES = tests/test_function.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_function_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_function_LDADD = $(TEST_LDADD)
tests_test_function_LDFLAGS = -static
$(tests_test_function_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Splines (lib/sdl/spline.c, listed with the sources above).
check_PROGRAMS += tests/test_spline
TESTS += tests/test_spline
tests_test_spline_SOURCES = tests/test_spline.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_spline_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_spline_LDADD = $(TEST_LDADD)
tests_test_spline_LDFLAGS = -static
$(tests_test_spline_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Building meshes, mesh2 and text from the grammar.
lib_libzrcube_la_SOURCES += lib/sdl/build_mesh.c lib/sdl/build_mesh.h
lib_libzrcube_la_SOURCES += lib/sdl/build_texture.c
# Transform blocks, fractal and function patterns (lib/sdl/build_pattern.c).
lib_libzrcube_la_SOURCES += lib/sdl/build_pattern.c lib/sdl/build_pattern.h
check_PROGRAMS += tests/test_pattern_more
TESTS += tests/test_pattern_more
tests_test_pattern_more_SOURCES = tests/test_pattern_more.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_pattern_more_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_pattern_more_LDADD = $(TEST_LDADD)
tests_test_pattern_more_LDFLAGS = -static
$(tests_test_pattern_more_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Cameras, lights and atmospheric effects (issue 3).
lib_libzrcube_la_SOURCES += lib/sdl/build_camlight.c lib/sdl/build_camlight.h
lib_libzrcube_la_SOURCES += lib/sdl/build_meshcam.c

# Building tori, polygons and superellipsoids from the grammar.
lib_libzrcube_la_SOURCES += lib/sdl/build_shape.c lib/sdl/build_shape.h

# Building bicubic patches, sphere sweeps and julia fractals.
lib_libzrcube_la_SOURCES += lib/sdl/build_surface.c lib/sdl/build_surface.h

# Building isosurfaces and height fields from the grammar.
lib_libzrcube_la_SOURCES += lib/sdl/build_iso.c lib/sdl/build_iso.h \
	lib/sdl/build_hf.c

# Radiosity settings: global_settings { radiosity { } }, an object's
# radiosity keywords and finish { energy } (issue 4).
lib_libzrcube_la_SOURCES += lib/sdl/build_radiosity.c
check_PROGRAMS += tests/test_rad_settings
TESTS += tests/test_rad_settings
tests_test_rad_settings_SOURCES = tests/test_rad_settings.c \
	tests/parse_fixture.c tests/parse_fixture.h bin/options.c bin/options.h
tests_test_rad_settings_CPPFLAGS = $(TEST_CPPFLAGS) -I$(top_srcdir)/bin
tests_test_rad_settings_LDADD = $(TEST_LDADD)
tests_test_rad_settings_LDFLAGS = -static
$(tests_test_rad_settings_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
# Radiosity where the method is known to fail (issue 4), coarse settings.
check_PROGRAMS += tests/test_rad_stability
TESTS += tests/test_rad_stability
tests_test_rad_stability_SOURCES = tests/test_rad_stability.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_rad_stability_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_rad_stability_LDADD = $(TEST_LDADD)
tests_test_rad_stability_LDFLAGS = -static
$(tests_test_rad_stability_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Participating media, interior_texture and photons blocks.
lib_libzrcube_la_SOURCES += lib/sdl/build_media.c lib/sdl/build_media.h
