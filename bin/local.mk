# bin/local.mk - the zrcube command and its tests.
bin_PROGRAMS += bin/zrcube
bin_zrcube_SOURCES = bin/zrcube.c bin/options.c bin/options.h \
	bin/state.c bin/state.h
bin_zrcube_CPPFLAGS = $(AM_CPPFLAGS) -I$(top_srcdir)/bin
bin_zrcube_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS)
bin_zrcube_LDADD = lib/par/libzrpar.la lib/libzrcube.la $(MPI_LIBS) \
	$(PTHREAD_LIBS) -lm
# zrcube under mpirun as root and with more ranks than cores (issue 12).
bin_SCRIPTS = bin/zrcube-mpirun
EXTRA_DIST += bin/zrcube-mpirun.in

check_PROGRAMS += tests/test_cli_options
TESTS += tests/test_cli_options
tests_test_cli_options_SOURCES = tests/test_cli_options.c bin/options.c \
	bin/options.h
tests_test_cli_options_CPPFLAGS = $(TEST_CPPFLAGS) -I$(top_srcdir)/bin
tests_test_cli_options_LDADD = $(TEST_LDADD)

# End-to-end: mpirun with 1 to 3 ranks, bad input, option handling.
TESTS += tests/test_cli.sh
EXTRA_DIST += tests/test_cli.sh tests/cli_env.sh
# Every POV-Ray 3.7 include file parses (skipped without povray-includes).
TESTS += tests/test_includes.sh
EXTRA_DIST += tests/test_includes.sh

# Radiosity end to end: the Cornell box with --radiosity, 1 and 2 ranks,
# save and load, radiosity-only, one-sided emission, option errors.
TESTS += tests/test_rad_cli.sh
EXTRA_DIST += tests/test_rad_cli.sh

# Animation, partial renders, +O-, Declare=, streams, stock INI files
# (issue 12); +C after kill -9.
TESTS += tests/test_anim.sh tests/test_continue.sh tests/test_quality.sh
# +UA (issue 12): tests/test_alpha.sh alone, and against povray.
TESTS += tests/test_alpha.sh tests/test_alpha_povray.sh
EXTRA_DIST += tests/test_alpha.sh tests/test_alpha_povray.sh
EXTRA_DIST += tests/test_anim.sh tests/test_continue.sh \
	tests/test_quality.sh tests/quality/quality.pov tests/quality/quick.pov
