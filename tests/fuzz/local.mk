# tests/fuzz/local.mk - the libFuzzer target for the parser.
#
# Built only by `configure --enable-fuzz CC=clang` (without --enable-werror:
# clang warns on flex's output): the target compiles the library's sources
# itself with -fsanitize=fuzzer,address,undefined (undefined behaviour
# stops the run, as a crash would), so coverage reaches every parser file
# while the ordinary library stays uninstrumented.
#   make tests/fuzz/fuzz_parse
#   tests/fuzz/fuzz_parse -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
#     -dict=$(srcdir)/tests/fuzz/pov.dict \
#     CORPUS_DIR $(srcdir)/scenes $(srcdir)/tests/fuzz/regress
# Inputs that once crashed, leaked or hung are kept in tests/fuzz/regress/
# and replayed through the same entry point, without libFuzzer, by
# tests/fuzz/replay in every `make check`.
EXTRA_DIST += tests/fuzz/regress tests/fuzz/pov.dict
check_PROGRAMS += tests/fuzz/replay
TESTS += tests/fuzz/replay
tests_fuzz_replay_SOURCES = tests/fuzz/replay.c tests/fuzz/fuzz_parse.c
tests_fuzz_replay_CPPFLAGS = $(TEST_CPPFLAGS)
tests_fuzz_replay_LDADD = $(TEST_LDADD)

if ZR_FUZZ
noinst_PROGRAMS += tests/fuzz/fuzz_parse
tests_fuzz_fuzz_parse_SOURCES = tests/fuzz/fuzz_parse.c \
	$(lib_libzrcube_la_SOURCES)
nodist_tests_fuzz_fuzz_parse_SOURCES = $(GRAMMAR_GENERATED)
tests_fuzz_fuzz_parse_CPPFLAGS = $(AM_CPPFLAGS) -DZR_BUILDING_LIBRARY \
	$(PNG_CFLAGS) $(PTHREAD_CFLAGS) $(TIFF_CFLAGS) $(EXR_CFLAGS)
tests_fuzz_fuzz_parse_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS) \
	-fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
	-fno-omit-frame-pointer
tests_fuzz_fuzz_parse_LDFLAGS = -fsanitize=fuzzer,address,undefined
tests_fuzz_fuzz_parse_LDADD = $(PNG_LIBS) $(JPEG_LIBS) $(TIFF_LIBS) \
	$(EXR_LIBS) $(EMBREE_LIBS) $(PTHREAD_LIBS) -lm
$(tests_fuzz_fuzz_parse_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
endif

# The image decoders' target (fuzz_image.c): the same flags, the seeds in
# tests/fuzz/image-seeds (tests/fuzz/make-image-seeds.sh), its saved
# inputs in tests/fuzz/regress-image, replayed by tests/fuzz/replay_image
# in every `make check`.
#   make tests/fuzz/fuzz_image
#   tests/fuzz/fuzz_image -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
#     CORPUS_DIR $(srcdir)/tests/fuzz/image-seeds \
#     $(srcdir)/tests/fuzz/regress-image
EXTRA_DIST += tests/fuzz/regress-image tests/fuzz/image-seeds \
	tests/fuzz/make-image-seeds.sh
check_PROGRAMS += tests/fuzz/replay_image
TESTS += tests/fuzz/replay_image
tests_fuzz_replay_image_SOURCES = tests/fuzz/replay.c tests/fuzz/fuzz_image.c
tests_fuzz_replay_image_CPPFLAGS = $(TEST_CPPFLAGS) \
	-DZR_REPLAY_DIR='"tests/fuzz/regress-image"'
tests_fuzz_replay_image_LDADD = $(TEST_LDADD) $(PNG_LIBS) $(JPEG_LIBS)
# zr__ functions are hidden in the shared library: link the archive.
tests_fuzz_replay_image_LDFLAGS = -static

if ZR_FUZZ
noinst_PROGRAMS += tests/fuzz/fuzz_image
tests_fuzz_fuzz_image_SOURCES = tests/fuzz/fuzz_image.c \
	$(lib_libzrcube_la_SOURCES)
nodist_tests_fuzz_fuzz_image_SOURCES = $(GRAMMAR_GENERATED)
tests_fuzz_fuzz_image_CPPFLAGS = $(tests_fuzz_fuzz_parse_CPPFLAGS)
tests_fuzz_fuzz_image_CFLAGS = $(tests_fuzz_fuzz_parse_CFLAGS)
tests_fuzz_fuzz_image_LDFLAGS = $(tests_fuzz_fuzz_parse_LDFLAGS)
tests_fuzz_fuzz_image_LDADD = $(tests_fuzz_fuzz_parse_LDADD)
$(tests_fuzz_fuzz_image_OBJECTS): grammar/pov-parse.h grammar/pov-scan.h
endif
