# gui/local.mk - zrcube-gtk, the GTK 4 front end (configure --with-gtk).
# Built only when configure found GTK 4 and libepoxy (or was told
# --with-gtk=yes); tests/test_gtk.sh skips when it was not built.
if ZR_GTK
bin_PROGRAMS += gui/zrcube-gtk
gui_zrcube_gtk_SOURCES = gui/zrcube-gtk.c
# GTK's deprecations after 4.8 (Debian 12's) do not warn, so -Werror
# builds stay green on newer GTK; the code uses nothing deprecated in
# 4.8.
gui_zrcube_gtk_CPPFLAGS = $(AM_CPPFLAGS) $(GTK_CFLAGS) \
	-DGDK_VERSION_MIN_REQUIRED=GDK_VERSION_4_8
gui_zrcube_gtk_LDADD = lib/libzrcube.la $(GTK_LIBS) -lm
dist_man_MANS += man/zrcube-gtk.1
endif
TESTS += tests/test_gtk.sh
EXTRA_DIST += tests/test_gtk.sh tests/gtk_scene.pov
