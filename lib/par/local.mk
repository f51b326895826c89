# lib/par/local.mk - MPI and threads.  Not part of libzrcube, which must
# not depend on MPI: a convenience library linked into bin/zrcube only.
noinst_LTLIBRARIES += lib/par/libzrpar.la
lib_par_libzrpar_la_SOURCES = \
	lib/par/bundle.c lib/par/bundle.h \
	lib/par/par.c lib/par/par.h \
	lib/par/pool.c lib/par/pool.h \
	lib/par/rows.c lib/par/rows.h \
	lib/par/writer.c lib/par/writer.h
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

if ZR_MPI
# libzrcube_mpi: the MPI driver above on a caller's communicator
# (include/zrcube_mpi.h), for programs that run MPI themselves.
lib_LTLIBRARIES += lib/par/libzrcube_mpi.la
include_HEADERS += include/zrcube_mpi.h
lib_par_libzrcube_mpi_la_SOURCES = lib/par/mpi_api.c
lib_par_libzrcube_mpi_la_CPPFLAGS = $(AM_CPPFLAGS) $(MPI_CFLAGS) \
	-DZR_BUILDING_MPI_LIBRARY
lib_par_libzrcube_mpi_la_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS)
lib_par_libzrcube_mpi_la_LIBADD = lib/par/libzrpar.la lib/libzrcube.la \
	$(MPI_LIBS) $(PTHREAD_LIBS)
lib_par_libzrcube_mpi_la_LDFLAGS = -version-info 0:0:0 -no-undefined

# Its example, run under mpirun with 1 to 3 ranks by make check.
check_PROGRAMS += examples/mpi_render
examples_mpi_render_SOURCES = examples/mpi_render.c
examples_mpi_render_CPPFLAGS = $(AM_CPPFLAGS) $(MPI_CFLAGS)
examples_mpi_render_LDADD = lib/par/libzrcube_mpi.la lib/libzrcube.la \
	$(MPI_LIBS)
TESTS += tests/test_mpi_example.sh
EXTRA_DIST += tests/test_mpi_example.sh

# Waiting ranks sleep; one host skips the network probe (par.c).
check_PROGRAMS += tests/mpi_wait
tests_mpi_wait_SOURCES = tests/mpi_wait.c
tests_mpi_wait_CPPFLAGS = $(AM_CPPFLAGS) $(MPI_CFLAGS)
tests_mpi_wait_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS)
tests_mpi_wait_LDADD = lib/par/libzrpar.la lib/libzrcube.la $(MPI_LIBS) \
	$(PTHREAD_LIBS)
TESTS += tests/test_mpi_wait.sh
EXTRA_DIST += tests/test_mpi_wait.sh
# ZRCUBE_TIMELINE's steps (zr__par_mark), which bench/timeline.sh reads.
TESTS += tests/test_timeline.sh
EXTRA_DIST += tests/test_timeline.sh
endif
