# lib/trace/local.mk - the tracer: bounds, BVH, intersections, shading,
# camera rays and antialiasing.
lib_libzrcube_la_SOURCES += \
	lib/scene/bounds.c \
	lib/trace/bvh.c lib/trace/bvh.h \
	lib/trace/intersect.c lib/trace/intersect.h \
	lib/trace/render.c lib/trace/render.h \
	lib/trace/shade.c lib/trace/shade.h
