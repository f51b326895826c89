# scenes/local.mk - sample scenes, installed under $(pkgdatadir)/scenes.
# NAME.ref.pov is NAME.pov for POV-Ray when NAME.pov uses a zRcube
# extension (see tests/ref/README.md).
scenesdir = $(pkgdatadir)/scenes
EXTRA_DIST += scenes/README.md
dist_scenes_DATA = \
	scenes/camera.pov \
	scenes/csg_union.pov \
	scenes/default.pov \
	scenes/default.ref.pov \
	scenes/expressions.pov \
	scenes/gamma.pov \
	scenes/metallic.pov \
	scenes/phong.pov \
	scenes/patterns.pov \
	scenes/primitives.pov \
	scenes/reflection.pov \
	scenes/refraction.pov \
	scenes/shadows.pov \
	scenes/specular.pov \
	scenes/tir.pov \
	scenes/transforms.pov \
	scenes/zfor.pov \
	scenes/zfor.ref.pov
