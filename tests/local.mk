# tests/local.mk - image tests, the image comparison tool and the golden
# scene suite.

check_PROGRAMS += tests/test_image
TESTS += tests/test_image
tests_test_image_SOURCES = tests/test_image.c
tests_test_image_CPPFLAGS = $(TEST_CPPFLAGS) $(PNG_CFLAGS)
tests_test_image_LDADD = $(TEST_LDADD) $(PNG_LIBS) $(JPEG_LIBS)
# The test calls zr__ functions, which the shared library hides
# (-fvisibility=hidden): link the static archive, where they resolve.
tests_test_image_LDFLAGS = -static

# The numeric assertions the test programs share (header only).
EXTRA_DIST += tests/test_util.h

# imgcmp compares two renders (SSIM or relative RMSE); golden.sh uses it.
check_PROGRAMS += tests/imgcmp
tests_imgcmp_SOURCES = tests/imgcmp.c
tests_imgcmp_CPPFLAGS = $(AM_CPPFLAGS)
tests_imgcmp_LDADD = lib/libzrcube.la -lm

TESTS += tests/golden.sh
EXTRA_DIST += tests/golden.sh tests/ref/README.md tests/ref/make-refs.sh \
	tests/ref/blob.png \
	tests/ref/default_maps.png \
	tests/ref/fade_shadow.png \
	tests/ref/flat_box.png \
	tests/ref/image_gamma.png \
	tests/ref/legacy_gamma.png \
	tests/ref/negative_light.png \
	tests/ref/normal_tilt.png \
	tests/ref/ortho_id.png \
	tests/ref/spirals.png \
	tests/ref/waves_quilted.png \
	tests/ref/camera_sky.png \
	tests/ref/transmit_over.png \
	tests/ref/texture_modify.png \
	tests/ref/bicubic.png \
	tests/ref/julia.png \
	tests/ref/warps.png \
	tests/ref/warp_image.png \
	tests/ref/sphere_sweep.png \
	tests/ref/camera.png \
	tests/ref/lights.png \
	tests/ref/atmosphere.png \
	tests/ref/media.png \
	tests/ref/media2.png \
	tests/ref/fisheye.png \
	tests/ref/ortho.png \
	tests/ref/csg_difference.png \
	tests/ref/csg_clip.png \
	tests/ref/csg_union.png \
	tests/ref/default.png \
	tests/ref/expressions.png \
	tests/ref/gamma.png \
	tests/ref/height_field.png \
	tests/ref/isosurface.png \
	tests/ref/fractals.png \
	tests/ref/lathe.png \
	tests/ref/layered.png \
	tests/ref/maps.png \
	tests/ref/mesh.png \
	tests/ref/metallic.png \
	tests/ref/ovus.png \
	tests/ref/parametric.png \
	tests/ref/patterns.png \
	tests/ref/phong.png \
	tests/ref/polygon.png \
	tests/ref/primitives.png \
	tests/ref/quadric.png \
	tests/ref/prism.png \
	tests/ref/reflection.png \
	tests/ref/refraction.png \
	tests/ref/shadows.png \
	tests/ref/sor.png \
	tests/ref/specular.png \
	tests/ref/superellipsoid.png \
	tests/ref/text.png \
	tests/ref/tir.png \
	tests/ref/torus.png \
	tests/ref/transforms.png \
	tests/ref/zfor.png

# The benchmark against POV-Ray (run by `make bench` in the top Makefile).
EXTRA_DIST += bench/run.sh bench/README.md bench/conformance.sh \
	bench/results/stock-2026-12-02-before.tsv \
	bench/results/stock-2026-12-02-after.tsv \
	bench/results/corpus-2026-12-02-before.tsv \
	bench/results/corpus-2026-12-02-after.tsv \
	bench/conformance.py

# The radiosity benchmark's footing: imgcmp reads POV-Ray's Radiance HDR
# output, and the Cornell box ground truth and scene are what they claim.
TESTS += tests/test_cornell_truth.sh
EXTRA_DIST += tests/test_cornell_truth.sh

# Old syntax against POV-Ray's pictures (skipped without povray).
TESTS += tests/test_legacy_povray.sh
EXTRA_DIST += tests/test_legacy_povray.sh tests/legacy/camera_angle0.pov \
	tests/legacy/camera_angle0p.pov tests/legacy/declare.pov \
	tests/legacy/srgb.pov tests/legacy/texture_ids.pov \
	tests/legacy/finish_ior.pov tests/legacy/no_bump_scale.pov \
	tests/legacy/blocks.pov tests/legacy/clip_id.pov \
	tests/legacy/include_semicolon.inc \
	tests/legacy/hash_keyword.pov tests/legacy/bare_object_csg.pov \
	tests/legacy/bare_light.pov

# Media against POV-Ray's pictures (skipped without povray).
TESTS += tests/test_media_povray.sh
EXTRA_DIST += tests/test_media_povray.sh tests/media_check.pov
TESTS += tests/test_media_shadow_povray.sh tests/test_fog_povray.sh \
	tests/test_image_gamma_povray.sh
EXTRA_DIST += tests/test_fog_povray.sh tests/fog/solid_fog.pov \
	tests/test_image_gamma_povray.sh
EXTRA_DIST += tests/test_media_shadow_povray.sh bench/media_shadow.py bench/conform/png16.py \
	bench/media_warp_ssim.sh bench/media_more_samples.py \
	bench/results/media-warp-ssim-2026-12-02.tsv \
	bench/results/media-shadow-2026-12-02.txt

# The radiosity benchmark (bench/radiosity.sh; not run by `make check`).
EXTRA_DIST += bench/radiosity.sh bench/build_args.sh bench/radiosity/charts.gp \
	bench/radiosity/cornell.pov bench/radiosity/check_truth.py \
	bench/radiosity/summary.awk bench/radiosity/error-time.png
# Hierarchical radiosity as scenes grow (bench/radiosity_scale.sh).
EXTRA_DIST += bench/radiosity_scale.sh bench/radiosity/scale_scene.py \
	bench/radiosity/scale.gp bench/radiosity/scale.png

# GIF, POT and TGA files (lib/image/gif.c, tga.c, heights.c).
check_PROGRAMS += tests/test_image_formats
TESTS += tests/test_image_formats
tests_test_image_formats_SOURCES = tests/test_image_formats.c
tests_test_image_formats_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_image_formats_LDADD = $(TEST_LDADD) $(PNG_LIBS) $(JPEG_LIBS)
tests_test_image_formats_LDFLAGS = -static

# The I/O restrictions (issue 10): the path rules of lib/core/iopolicy.c,
# and end to end the output name, devices, links, the checks before
# parsing and every file a scene opens.
check_PROGRAMS += tests/test_iopolicy
TESTS += tests/test_iopolicy tests/test_iopolicy.sh
tests_test_iopolicy_SOURCES = tests/test_iopolicy.c
tests_test_iopolicy_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_iopolicy_LDADD = $(TEST_LDADD)
tests_test_iopolicy_LDFLAGS = -static
EXTRA_DIST += tests/test_iopolicy.sh
# Hostile input and faults (issue 10): budgets, escaped and bounded
# messages, non-finite values, signals, a killed rank, a full disk, too
# little memory, corrupt files, 10^6 objects.
TESTS += tests/test_faults.sh
EXTRA_DIST += tests/test_faults.sh
# mkhfpng writes test_faults.sh's 11000 x 11000 height field picture.
check_PROGRAMS += tests/mkhfpng
tests_mkhfpng_SOURCES = tests/mkhfpng.c
tests_mkhfpng_CPPFLAGS = $(AM_CPPFLAGS) $(PNG_CFLAGS)
tests_mkhfpng_LDADD = $(PNG_LIBS) -lm

# Issue 12's writers and readers (JPEG, TGA, HDR, OpenEXR, alpha, BMP,
# TIFF) and encoding to memory and to a stream.
check_PROGRAMS += tests/test_image_io
TESTS += tests/test_image_io
tests_test_image_io_SOURCES = tests/test_image_io.c
tests_test_image_io_CPPFLAGS = $(TEST_CPPFLAGS) $(TIFF_CFLAGS)
tests_test_image_io_LDADD = $(TEST_LDADD) $(TIFF_LIBS)
tests_test_image_io_LDFLAGS = -static

# Writing and reading each format against POV-Ray's (skipped without povray).
TESTS += tests/test_formats_povray.sh
EXTRA_DIST += tests/test_formats_povray.sh

# A newcomer's set-up (issue 12): the MPI wrapper as root and with more
# ranks than cores; install, pkg-config (shared and --static), uninstall.
TESTS += tests/test_mpirun_wrapper.sh tests/test_install.sh
EXTRA_DIST += tests/test_mpirun_wrapper.sh tests/test_install.sh
# The lib/ folders include one another only downward (issue 14;
# bench/layering.sh, README "Layering").
TESTS += tests/test_layering.sh
EXTRA_DIST += tests/test_layering.sh bench/layering.sh

# Simulated caustics against povray's measured law and picture.
TESTS += tests/test_caustics.sh
EXTRA_DIST += tests/test_caustics.sh tests/caustics_check.pov \
	tests/caustics_bumps.pov

# Photon mapping: the power law, lights without photons, povray's picture.
TESTS += tests/test_photons.sh
EXTRA_DIST += tests/test_photons.sh tests/photons_check.pov

# Photons in media: beams of media photons against povray's region
# means, thread and rank byte-identity, bad 'media' values.
TESTS += tests/test_media_photons.sh
EXTRA_DIST += tests/test_media_photons.sh tests/media_photons.pov \
	tests/region_mean.py

# +AM2, the recursive antialiasing method, against povray's.
TESTS += tests/test_aa_method.sh
EXTRA_DIST += tests/test_aa_method.sh tests/am2_check.pov

# A mesh's texture_list moves with the object.
TESTS += tests/test_mesh_textures.sh
EXTRA_DIST += tests/test_mesh_textures.sh tests/mesh_texture_list.pov

# The public API's contracts (issue 14): threads in zr_render_image,
# progress and cancel in every phase, parameter sizes, diagnostic spans;
# linked with the shared library, so it sees exported symbols only.
check_PROGRAMS += tests/test_api
TESTS += tests/test_api
tests_test_api_SOURCES = tests/test_api.c
tests_test_api_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_api_LDADD = $(TEST_LDADD)
# zr_scene_preview (lib/radiosity/preview.c), through the public API.
check_PROGRAMS += tests/test_preview
TESTS += tests/test_preview
tests_test_preview_SOURCES = tests/test_preview.c
tests_test_preview_CPPFLAGS = $(TEST_CPPFLAGS)
tests_test_preview_LDADD = $(TEST_LDADD)
# The exported symbols are lib/libzrcube.sym's list and zrcube.h's, and
# every public function is named in a section-3 page (issue 14).
TESTS += tests/test_symbols.sh tests/test_manpages.sh
EXTRA_DIST += tests/test_symbols.sh tests/test_manpages.sh \
	tests/public_names.sh lib/libzrcube.sym

# One-value reflection forms (fresnel from none up to R), povray's picture.
TESTS += tests/test_reflection_forms.sh
EXTRA_DIST += tests/test_reflection_forms.sh

# Subsurface light transport against povray's measured slab, plane and edge.
TESTS += tests/test_subsurface.sh
EXTRA_DIST += tests/test_subsurface.sh tests/subsurface_check.pov \
	bench/conform/sslt_probe.py

# Total internal reflection under a layered texture: one mirrored ray.
TESTS += tests/test_layer_tir.sh
EXTRA_DIST += tests/test_layer_tir.sh tests/layer_tir.pov

# A tilted normal that mirrors a grazing ray into the surface.
TESTS += tests/test_grazing_normal.sh
EXTRA_DIST += tests/test_grazing_normal.sh tests/grazing_normal.pov

# The common start of the picture-comparing test scripts (sourced).
EXTRA_DIST += tests/render_env.sh

# The Embree backend's pictures against the built-in hierarchy's (skips
# in a build without Embree).
TESTS += tests/embree.sh
EXTRA_DIST += tests/embree.sh tests/embree_scene.pov

# A camera's normal { } at the screen point (u, v, 0), povray's values.
TESTS += tests/test_camera_normal.sh
EXTRA_DIST += tests/test_camera_normal.sh tests/camera_normal.pov \
	tests/pixel_check.py

# sky_sphere layers: filter passes untinted, povray's values.
TESTS += tests/test_sky_layers.sh
EXTRA_DIST += tests/test_sky_layers.sh tests/sky_layers.pov

# Ripples and waves normals: the sine of each wave's phase, povray's values.
TESTS += tests/test_waves_normal.sh
EXTRA_DIST += tests/test_waves_normal.sh bench/conform/waves_normal_fit.py

# A negative transmit is traced: (1 - t) C + t B, povray's values.
TESTS += tests/test_negative_transmit.sh
EXTRA_DIST += tests/test_negative_transmit.sh tests/negative_transmit.pov

# Quilted normals: the cube offset times quilted's Bezier, povray's values.
TESTS += tests/test_quilted_normal.sh
EXTRA_DIST += tests/test_quilted_normal.sh tests/quilted_normal.pov \
	bench/conform/quilted_normal_probe.py

# A normal pattern's bump size when none is written: #default's, an
# identifier's, else 0.5; povray's values.
TESTS += tests/test_default_normal.sh
EXTRA_DIST += tests/test_default_normal.sh tests/default_normal.pov

# A no_shadow object's media and fading shadow nothing, povray's values.
TESTS += tests/test_no_shadow_interior.sh
EXTRA_DIST += tests/test_no_shadow_interior.sh tests/no_shadow_interior.pov

TESTS += tests/test_csg_area_shadow.sh
EXTRA_DIST += tests/test_csg_area_shadow.sh tests/csg_area_shadow.pov

# Interiors of CSG parts and fading where a ray leaves, povray's values.
TESTS += tests/test_merge_interior.sh
EXTRA_DIST += tests/test_merge_interior.sh tests/merge_interior.pov

# A pattern normal's samples: a tetrahedron around the point, povray's
# values.
TESTS += tests/test_normal_stencil.sh
EXTRA_DIST += tests/test_normal_stencil.sh tests/normal_stencil.pov \
	bench/conform/normal_stencil_probe.sh \
	bench/conform/normal_stencil_probe.pov

# A quartic's small leading term kept where it matters, povray's values.
TESTS += tests/test_poly_degree.sh
EXTRA_DIST += tests/test_poly_degree.sh tests/poly_degree.pov

# Thick media as bright as POV-Ray's method 3 cells make them (the
# scattering box of issue 16), povray's values.
TESTS += tests/test_media_cells.sh
EXTRA_DIST += tests/test_media_cells.sh tests/media_cells.pov \
	bench/media_quadrature.py \
	bench/results/media-quadrature-2026-12-02.txt

# Fog turbulence thins constant and ground fog, povray's values.
TESTS += tests/test_fog_turbulence.sh
EXTRA_DIST += tests/test_fog_turbulence.sh tests/fog_turbulence.pov \
	bench/conform/fog_turbulence_probe.py

# irid's turbulence: the scalar turbulence sum, povray's values.
TESTS += tests/test_irid_turbulence.sh
EXTRA_DIST += tests/test_irid_turbulence.sh tests/irid_turbulence.pov \
	bench/conform/irid_turbulence_probe.py

# Pattern normals sampled around the point moved once by the warps and
# turbulence, povray's values.
TESTS += tests/test_normal_warped.sh
EXTRA_DIST += tests/test_normal_warped.sh tests/normal_warped.pov

# Which photons a target's lattice brings: overlapping targets, the
# photon trace level, shadowless lights; povray's counts and pixels.
TESTS += tests/test_photon_targets.sh
EXTRA_DIST += tests/test_photon_targets.sh tests/photon_targets.pov \
	bench/photon_targets.sh

# A ray's way into or out of an object follows its path's objects, not
# the surface's side (an upside-down clear height field), povray's pixels.
TESTS += tests/test_hf_inside.sh
EXTRA_DIST += tests/test_hf_inside.sh tests/hf_inside.pov

# A union of triangles with an interior refracts as a solid, povray's
# pixels.
TESTS += tests/test_flat_interior.sh
EXTRA_DIST += tests/test_flat_interior.sh tests/flat_interior.pov
TESTS += tests/test_dispersion.sh
TESTS += tests/test_exit_fade.sh
EXTRA_DIST += tests/test_exit_fade.sh tests/exit_fade.pov
TESTS += tests/test_mandel_map.sh
EXTRA_DIST += tests/test_mandel_map.sh tests/mandel_map.pov
EXTRA_DIST += tests/test_dispersion.sh tests/dispersion.pov \
	bench/conform/dispersion_probe.pov bench/conform/dispersion_probe.py

# corpus (session 7): shared CSG faces, polygons off their plane, the
# noise far out.
EXTRA_DIST += tests/legacy/csg_shared_face.pov \
	tests/legacy/polygon_offplane.pov bench/noise/probe_far.pov
TESTS += tests/test_no_bump_scale.sh
EXTRA_DIST += tests/test_no_bump_scale.sh tests/no_bump_scale.pov
EXTRA_DIST += tests/legacy/macro_arg_colour.pov

TESTS += tests/test_isosurface_nan.sh
EXTRA_DIST += tests/test_isosurface_nan.sh tests/isosurface_nan.pov
# When a photon branch is dropped (povray's measured bailout rule) and
# photons shot from a far light at a curved target: povray's counts.
TESTS += tests/test_photon_bailout.sh
EXTRA_DIST += tests/test_photon_bailout.sh bench/photon_bailout.pov \
	bench/photon_bailout.sh
TESTS += tests/test_interior_path.sh
EXTRA_DIST += tests/test_interior_path.sh tests/interior_path.pov
TESTS += tests/test_sky_transform.sh
EXTRA_DIST += tests/test_sky_transform.sh tests/sky_transform.pov
EXTRA_DIST += tests/noise/cells.txt bench/noise/probe_cells.py
# Gamma correction off in legacy scenes (no assumed_gamma, no #version
# 3.7), File_Gamma, image_map codes and the antialiasing threshold,
# povray's codes (bench/conform/legacy_gamma_probe.py prints the table).
TESTS += tests/test_legacy_gamma_povray.sh
EXTRA_DIST += tests/test_legacy_gamma_povray.sh \
	bench/conform/legacy_gamma_probe.py
TESTS += tests/test_exit_fresnel.sh
EXTRA_DIST += tests/test_exit_fresnel.sh tests/exit_fresnel.pov
TESTS += tests/test_gradient_wrap.sh
EXTRA_DIST += tests/test_gradient_wrap.sh bench/conform/gradient_wrap_probe.sh bench/conform/gradient_wrap_probe.pov
TESTS += tests/test_media_curvature.sh
EXTRA_DIST += tests/test_media_curvature.sh tests/media_curvature.pov bench/conform/media_curvature_probe.py
# Focal blur's lens radius, aperture / 4 (povray's measured spread).
TESTS += tests/test_focal_blur.sh
EXTRA_DIST += tests/test_focal_blur.sh bench/conform/focal_blur_probe.py
TESTS += tests/test_fade_colour.sh
EXTRA_DIST += tests/test_fade_colour.sh tests/fade_colour.pov
# libtiff opened with dlopen, not linked (issue 13's start-up cost).
TESTS += tests/test_tiff_dlopen.sh
EXTRA_DIST += tests/test_tiff_dlopen.sh
# Shadows through fading interiors and through merges of several parts
# (povray's rule measured by bench/conform/shadow_fade_probe.sh).
TESTS += tests/test_shadow_fade.sh
EXTRA_DIST += tests/test_shadow_fade.sh tests/shadow_fade.pov \
	bench/conform/shadow_fade_probe.sh bench/conform/shadow_fade_probe.pov
EXTRA_DIST += bench/conform/fade_power_probe.sh bench/conform/probe_value.sh
# Media in a CSG shell moved after its interior was given, and media lit
# by a shadowless light (benchmark.pov's clouds).
TESTS += tests/test_media_shell.sh
EXTRA_DIST += tests/test_media_shell.sh tests/media_shell.pov
# An object's pigment, normal and finish after its texture modify the
# texture's (grammar/pov.y object_body; the corpus' glasstestreal.pov).
TESTS += tests/test_object_mods.sh
EXTRA_DIST += tests/test_object_mods.sh tests/object_mods.pov
# A parametric whose max_gradient understates its slopes (the corpus'
# GSprites_Terrain_demo.pov's water): drawn whole, as povray draws it.
TESTS += tests/test_parametric_gradient.sh
EXTRA_DIST += tests/test_parametric_gradient.sh tests/parametric_gradient.pov
# Radiosity with normal off under a normal { } that tilts past 90 degrees
# (the corpus' pneumaticBoat.pov sand): the surface's own hemisphere.
TESTS += tests/test_gi_normal_off.sh
EXTRA_DIST += tests/test_gi_normal_off.sh tests/gi_normal_off.pov
# bounded_by on a poly, cubic or quartic: rays that miss the bounding
# object itself skip the shape (objects/quartic/hyptorus.pov's corners).
TESTS += tests/test_bounded_poly.sh
EXTRA_DIST += tests/test_bounded_poly.sh tests/bounded_poly.pov
# An object's own bounded_by whose box is smaller than the object's: rays
# that miss that box skip the object.
TESTS += tests/test_bounded_box.sh
EXTRA_DIST += tests/test_bounded_box.sh tests/bounded_box.pov
TESTS += tests/test_pigment_keep.sh
EXTRA_DIST += tests/test_pigment_keep.sh tests/pigment_keep.pov
# A clip whose inside reaches beyond its box bounds the object by that box.
TESTS += tests/test_clip_box.sh
EXTRA_DIST += tests/test_clip_box.sh tests/clip_box.pov
# CSG with a disc or a height field, whose inside reaches beyond its box
# (stock advanced/desk/desk.pov's paperweight).
TESTS += tests/test_csg_inside.sh
EXTRA_DIST += tests/test_csg_inside.sh tests/csg_inside.pov
# Rays leaving an upside-down smooth glass height field (glasschess's board).
TESTS += tests/test_hf_glass.sh
EXTRA_DIST += tests/test_hf_glass.sh tests/hf_glass.pov
# Smooth height field normals as POV-Ray makes them (stock
# advanced/glasschess.pov's board).
TESTS += tests/test_hf_smooth.sh
EXTRA_DIST += tests/test_hf_smooth.sh tests/hf_smooth.pov
TESTS += tests/test_mesh_runs.sh
EXTRA_DIST += tests/test_mesh_runs.sh tests/mesh_runs.pov tests/mesh_runs.inc
# A light's negative fade_distance, as povray takes it (the manual's
# formula as it is: bench/conform/light_fade_negative.sh).
TESTS += tests/test_light_fade.sh
EXTRA_DIST += tests/test_light_fade.sh tests/light_fade.pov \
	bench/conform/light_fade_negative.sh
# An interior's negative fade_distance, likewise
# (bench/conform/interior_fade_negative.sh).
TESTS += tests/test_interior_fade.sh
EXTRA_DIST += tests/test_interior_fade.sh tests/interior_fade.pov \
	bench/conform/interior_fade_negative.sh

# image_pattern { } against povray's pixels (lib/scene/bitmap.c).
TESTS += tests/test_image_pattern.sh
EXTRA_DIST += tests/test_image_pattern.sh tests/image_pattern.pov

# An image_map's alpha channel and tRNS as transmit (lib/image/png.c).
TESTS += tests/test_image_alpha.sh
EXTRA_DIST += tests/test_image_alpha.sh tests/image_alpha.pov
# gamma G / gamma srgb on JPEG, BMP, PPM and TIFF image maps; TIFF
# samples in the working space (session 22).
TESTS += tests/test_image_gamma_formats.sh
EXTRA_DIST += tests/test_image_gamma_formats.sh \
	tests/image_gamma_formats.pov tests/image_gamma.jpg

# Scenes POV-Ray 3.7 refuses, reduced from the corpus (bench/refused.py):
# zrcube refuses them too, with the place and the problem.
TESTS += tests/test_refused.sh
EXTRA_DIST += tests/test_refused.sh tests/refused/semicolon.pov \
	tests/refused/semicolon_local.pov tests/refused/semicolon_v31.pov \
	tests/refused/version_38.pov tests/refused/version_3705.pov \
	tests/refused/version_37049.pov tests/refused/array_of_arrays.pov \
	tests/refused/colour_short_vector.pov tests/refused/object_light.pov \
	tests/refused/bad_char_later.pov tests/refused/bad_char_reached.pov \
	tests/refused/bad_char_skipped.pov tests/refused/seed_number.pov \
	tests/refused/seed_semicolon.pov
