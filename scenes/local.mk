# scenes/local.mk - sample scenes, installed under $(pkgdatadir)/scenes.
# NAME.ref.pov is NAME.pov for POV-Ray when NAME.pov uses a zRcube
# extension (see tests/ref/README.md).
scenesdir = $(pkgdatadir)/scenes
EXTRA_DIST += scenes/README.md
dist_scenes_DATA = \
	scenes/blob.pov \
	scenes/bicubic.pov \
	scenes/julia.pov \
	scenes/warps.pov \
	scenes/warp_image.pov \
	scenes/sphere_sweep.pov \
	scenes/camera.pov \
	scenes/cornell.pov \
	scenes/csg_difference.pov \
	scenes/csg_clip.pov \
	scenes/csg_union.pov \
	scenes/default.pov \
	scenes/default.ref.pov \
	scenes/default_maps.pov \
	scenes/expressions.pov \
	scenes/fade_shadow.pov \
	scenes/flat_box.pov \
	scenes/image_gamma.pov \
	scenes/legacy_gamma.pov \
	scenes/negative_light.pov \
	scenes/normal_tilt.pov \
	scenes/ortho_id.pov \
	scenes/spirals.pov \
	scenes/waves_quilted.pov \
	scenes/camera_sky.pov \
	scenes/transmit_over.pov \
	scenes/texture_modify.pov \
	scenes/gamma.pov \
	scenes/height_field.pov \
	scenes/isosurface.pov \
	scenes/fractals.pov \
	scenes/lathe.pov \
	scenes/layered.pov \
	scenes/maps.pov \
	scenes/mesh.pov \
	scenes/metallic.pov \
	scenes/ovus.pov \
	scenes/parametric.pov \
	scenes/phong.pov \
	scenes/polygon.pov \
	scenes/patterns.pov \
	scenes/primitives.pov \
	scenes/quadric.pov \
	scenes/prism.pov \
	scenes/reflection.pov \
	scenes/refraction.pov \
	scenes/shadows.pov \
	scenes/sor.pov \
	scenes/specular.pov \
	scenes/superellipsoid.pov \
	scenes/text.pov \
	scenes/tir.pov \
	scenes/torus.pov \
	scenes/transforms.pov \
	scenes/zfor.pov \
	scenes/lights.pov \
	scenes/atmosphere.pov \
	scenes/media.pov \
	scenes/media2.pov \
	scenes/fisheye.pov \
	scenes/ortho.pov \
	scenes/zfor.ref.pov
