# lib/image/local.mk - PNG, JPEG, GIF, TGA, BMP, TIFF, PPM, PFM, HDR and
# OpenEXR files, gamma.
lib_libzrcube_la_SOURCES += \
	lib/image/image.c lib/image/image.h \
	lib/image/png.c \
	lib/image/jpeg.c \
	lib/image/pnm.c \
	lib/image/gif.c \
	lib/image/tga.c \
	lib/image/tga_write.c \
	lib/image/bmp_write.c \
	lib/image/jpeg_write.c \
	lib/image/hdr.c \
	lib/image/exr.c \
	lib/image/bmp.c \
	lib/image/tiff.c \
	lib/image/heights.c
