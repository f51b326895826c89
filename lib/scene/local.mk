lib_libzrcube_la_SOURCES += \
	lib/scene/scene.c lib/scene/scene.h
