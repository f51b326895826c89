# grammar/local.mk - the scanner (flex) and parser (bison) of the scene
# language.  Both are generated into the build directory and not
# distributed: configure insists on flex and bison >= 3.6, so every build,
# including `make distcheck`, regenerates them from pov.l and pov.y.

GRAMMAR_GENERATED = grammar/pov-parse.c grammar/pov-parse.h \
	grammar/pov-scan.c grammar/pov-scan.h
BUILT_SOURCES += $(GRAMMAR_GENERATED)
CLEANFILES += $(GRAMMAR_GENERATED)
EXTRA_DIST += grammar/pov.l grammar/pov.y

nodist_lib_libzrcube_la_SOURCES = $(GRAMMAR_GENERATED)

# Bison -Wall -Werror: a new conflict in the grammar fails the build.
grammar/pov-parse.c: $(srcdir)/grammar/pov.y
	$(AM_V_GEN)$(MKDIR_P) grammar && \
	$(BISON) -Wall -Werror -o grammar/pov-parse.c \
	  --header=grammar/pov-parse.h $(srcdir)/grammar/pov.y
grammar/pov-parse.h: grammar/pov-parse.c
	@test -f $@ || { rm -f grammar/pov-parse.c; \
	  $(MAKE) $(AM_MAKEFLAGS) grammar/pov-parse.c; }

grammar/pov-scan.c: $(srcdir)/grammar/pov.l
	$(AM_V_GEN)$(MKDIR_P) grammar && \
	$(FLEX) -o grammar/pov-scan.c --header-file=grammar/pov-scan.h \
	  $(srcdir)/grammar/pov.l
grammar/pov-scan.h: grammar/pov-scan.c
	@test -f $@ || { rm -f grammar/pov-scan.c; \
	  $(MAKE) $(AM_MAKEFLAGS) grammar/pov-scan.c; }
