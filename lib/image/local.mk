# lib/image/local.mk - PNG, JPEG, GIF, TGA, PPM and PFM files, gamma.
lib_libzrcube_la_SOURCES += \
	lib/image/image.c lib/image/image.h \
	lib/image/png.c \
	lib/image/jpeg.c \
	lib/image/pnm.c \
	lib/image/gif.c \
	lib/image/tga.c \
	lib/image/heights.c
