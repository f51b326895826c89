lib_libzrcube_la_SOURCES += \
	lib/scene/scene.c lib/scene/scene.h lib/scene/shapes.h

# Patterns, noise, colour maps, image maps and normals.
lib_libzrcube_la_SOURCES += \
	lib/scene/pattern.c lib/scene/pattern.h lib/scene/pattern_more.c \
	lib/scene/pattern_tiling.c \
	lib/scene/warp.c lib/scene/warp.h \
	lib/scene/texture.c lib/scene/texture.h \
	lib/scene/bitmap.c lib/scene/bitmap.h

check_PROGRAMS += tests/test_pattern
TESTS += tests/test_pattern
tests_test_pattern_SOURCES = tests/test_pattern.c
tests_test_pattern_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_pattern_LDADD = $(TEST_LDADD)
tests_test_pattern_LDFLAGS = -static

# TrueType fonts for the text object.
lib_libzrcube_la_SOURCES += lib/scene/ttf.c lib/scene/ttf.h

# Maps, layered and patterned textures, materials (with lib/sdl/build_texture.c).
check_PROGRAMS += tests/test_texture
TESTS += tests/test_texture
tests_test_texture_SOURCES = tests/test_texture.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_texture_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_texture_LDADD = $(TEST_LDADD)
tests_test_texture_LDFLAGS = -static
$(tests_test_texture_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# Bump maps, material maps and map types (lib/scene/bitmap.c).
check_PROGRAMS += tests/test_bitmap
TESTS += tests/test_bitmap
tests_test_bitmap_SOURCES = tests/test_bitmap.c \
	tests/parse_fixture.c tests/parse_fixture.h
tests_test_bitmap_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_bitmap_LDADD = $(TEST_LDADD)
tests_test_bitmap_LDFLAGS = -static
$(tests_test_bitmap_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h

# The density_file pattern's df3 voxel files (media densities).
lib_libzrcube_la_SOURCES += lib/scene/df3.c lib/scene/df3.h

# The warps against POV-Ray's measured values (bench/warp_probe.sh).
check_PROGRAMS += tests/test_warp
TESTS += tests/test_warp
tests_test_warp_SOURCES = tests/test_warp.c
tests_test_warp_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_warp_LDADD = $(TEST_LDADD)
tests_test_warp_LDFLAGS = -static
# The same probes read back by zrcube and by POV-Ray (skipped without it).
TESTS += tests/test_warp_probe.sh
EXTRA_DIST += tests/test_warp_probe.sh bench/warp_probe.sh \
	bench/issue17_ssim.sh

# rand() and noise against values recorded from POV-Ray by the probe
# scripts in bench/noise/ (data in tests/noise/).
check_PROGRAMS += tests/test_noise
TESTS += tests/test_noise
tests_test_noise_SOURCES = tests/test_noise.c
tests_test_noise_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_noise_LDADD = $(TEST_LDADD)
tests_test_noise_LDFLAGS = -static
EXTRA_DIST += tests/noise/rand.txt bench/noise/probe_rand.sh \
	bench/noise/probe_noise.py bench/noise/povprobe.py \
	bench/noise/noise_tables.h bench/noise/probe_patterns.py \
	tests/noise/patterns.txt bench/noise/probe_crackle.py \
	bench/noise/crackle_tables.h bench/noise/README.md \
	bench/noise/ssim_scenes.sh bench/noise/ssim-160x120.tsv \
	bench/noise/probe_gen3.py bench/noise/gen3_tables.h \
	lib/scene/waves_tables.h bench/conform/waves_probe.py \
	bench/conform/quilted_probe.py \
	bench/noise/lanes.py bench/noise/noise_lanes.h
