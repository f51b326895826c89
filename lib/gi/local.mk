# lib/gi/local.mk - global illumination other than hierarchical
# radiosity: the irradiance cache (POV-Ray's radiosity block), the sky
# as light, and the choice of model per scene.
lib_libzrcube_la_SOURCES += \
	lib/gi/gi.h lib/gi/cache.c lib/gi/cachefile.c lib/gi/choose.c \
	lib/gi/path.c

check_PROGRAMS += tests/test_gi
TESTS += tests/test_gi
tests_test_gi_SOURCES = tests/test_gi.c \
	tests/parse_fixture.c tests/parse_fixture.h bin/options.c bin/options.h
tests_test_gi_CPPFLAGS = $(TEST_CPPFLAGS) -I$(top_srcdir)/bin
tests_test_gi_LDADD = $(TEST_LDADD)
tests_test_gi_LDFLAGS = -static
$(tests_test_gi_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# The irradiance cache end to end: threads, ranks, save and load, the
# model options (bin/zrcube).
TESTS += tests/test_gi_cli.sh
EXTRA_DIST += bench/gi_error.sh bench/gi_error.awk bench/gi_error.gp \
	bench/gi_convergence.gp bench/radiosity/with_block.awk \
	bench/gi/gi-error-cbox.png bench/gi/gi-error-cornell.png \
	bench/gi/gi-error-sky.png bench/gi/path-convergence.png
EXTRA_DIST += tests/test_gi_cli.sh bench/gi.sh scenes/sky_outdoor.pov \
	tests/ref/sky_outdoor.png

# The cache's sample directions and its blend at a record's own point,
# against povray's measured pillars and walls (a hall probe).
TESTS += tests/test_gi_pattern.sh
EXTRA_DIST += tests/test_gi_pattern.sh tests/gi_pattern.pov bench/gi_radset.py \
	bench/gi_pattern_probe.sh bench/gi_cpu_ab.sh
# Sample rays and fog, against povray's recorded pixels.
TESTS += tests/test_gi_fog.sh
EXTRA_DIST += tests/test_gi_fog.sh tests/gi_fog.pov
# Fog and media between the surfaces of a closed room, and an emitting
# dome around the camera (the automatic choice and the path-traced
# reference), against povray's measured means.
TESTS += tests/test_gi_room.sh
EXTRA_DIST += tests/test_gi_room.sh tests/gi_room.pov tests/gi_dome.pov
# A flat emitter lights the room whichever way its normal points, as
# povray's do (the hierarchical solver, against the path-traced
# reference's recorded means).
TESTS += tests/test_gi_flat.sh
EXTRA_DIST += tests/test_gi_flat.sh tests/gi_flat.pov
# The solver's picture follows the radiosity block's recursion_limit
# (1, 2, 3, 5 and none) against povray's measured means, and every
# bounce with --bounces=all against the path-traced reference's.
TESTS += tests/test_gi_bounce.sh
EXTRA_DIST += tests/test_gi_bounce.sh tests/gi_bounce.pov

# The path-traced reference: exact furnaces, samples in pieces, and the
# Cornell box against ../shared/reference's ground truth.
check_PROGRAMS += tests/test_path
TESTS += tests/test_path
tests_test_path_SOURCES = tests/test_path.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_path_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_path_LDADD = $(TEST_LDADD)
tests_test_path_LDFLAGS = -static
$(tests_test_path_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
