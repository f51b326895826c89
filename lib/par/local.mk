# lib/par/local.mk - MPI and threads.  Not part of libzrcube, which must
# not depend on MPI: a convenience library linked into bin/zrcube only.
noinst_LTLIBRARIES += lib/par/libzrpar.la
lib_par_libzrpar_la_SOURCES = \
	lib/par/bundle.c lib/par/bundle.h \
	lib/par/par.c lib/par/par.h \
	lib/par/pool.c lib/par/pool.h \
	lib/par/rows.c lib/par/rows.h
lib_par_libzrpar_la_CPPFLAGS = $(AM_CPPFLAGS) $(MPI_CFLAGS)
lib_par_libzrpar_la_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS)
lib_par_libzrpar_la_LIBADD = $(MPI_LIBS) $(PTHREAD_LIBS)

check_PROGRAMS += tests/test_par
TESTS += tests/test_par
tests_test_par_SOURCES = tests/test_par.c
tests_test_par_CPPFLAGS = $(TEST_CPPFLAGS) $(MPI_CFLAGS)
tests_test_par_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS)
tests_test_par_LDADD = lib/par/libzrpar.la $(TEST_LDADD) $(MPI_LIBS) \
	$(PTHREAD_LIBS)
