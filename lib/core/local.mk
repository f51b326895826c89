lib_libzrcube_la_SOURCES += \
	lib/core/arena.c lib/core/arena.h \
	lib/core/budget.c lib/core/budget.h \
	lib/core/context.c lib/core/context.h \
	lib/core/hugepage.h \
	lib/core/iopolicy.c lib/core/iopolicy.h \
	lib/core/noise.c lib/core/noise.h \
	lib/core/parallel.c lib/core/parallel.h \
	lib/core/strbuf.c lib/core/strbuf.h \
	lib/core/team.c lib/core/team.h \
	lib/core/transform.c lib/core/transform.h \
	lib/core/vec.h

check_PROGRAMS += tests/test_core
TESTS += tests/test_core
tests_test_core_SOURCES = tests/test_core.c
tests_test_core_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_core_LDADD = $(TEST_LDADD)
tests_test_core_LDFLAGS = -static

# Teams: the exchange protocol, and a radiosity solve, a cache pretrace
# and a parse (its meshes' hierarchies) shared by members (threads here)
# against one alone, with members that part (other bytes, a failure).
check_PROGRAMS += tests/test_team
TESTS += tests/test_team
tests_test_team_SOURCES = tests/test_team.c
tests_test_team_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_team_CFLAGS = $(AM_CFLAGS) $(PTHREAD_CFLAGS)
tests_test_team_LDADD = $(TEST_LDADD) $(PTHREAD_LIBS)
tests_test_team_LDFLAGS = -static
