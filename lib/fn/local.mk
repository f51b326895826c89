# lib/fn/local.mk - user functions at run time: the bytecode machine
# and the internal functions of functions.inc (the compiler is
# lib/sdl/function.c).
lib_libzrcube_la_SOURCES += \
	lib/fn/fn.h lib/fn/code.h \
	lib/fn/vm.c \
	lib/fn/internal.c
