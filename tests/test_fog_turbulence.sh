#!/bin/sh
# test_fog_turbulence.sh - fog turbulence (tests/fog_turbulence.pov): in
# povray 3.7 a turbulent fog, constant or ground, is thinned by
# 1 - min(1, turb_depth s) exp(-d / distance), s the scalar turbulence
# sum at the turbulence times the middle of the ray
# (bench/conform/fog_turbulence_probe.py, lib/trace/atmosphere.c).  The
# pixels below are povray's (povray 3.7.0.10, 16x12, -A +WT1 -GA); each
# channel must be within 2 levels.  Before, turbulence moved a ground
# fog's height and left a constant fog alone: the middle pixel of case 1
# was 139 for povray's 79, and the skies of the Basic_Scenes templates
# with a turbulent ground fog (Grass_small_clouds, Sea_small_clouds_in_sky,
# Sea_moon_partly_cloudy) were speckled where povray's are smooth.  With
# povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_0="138,138,138 133,133,133 142,142,142 130,130,130"
recorded_1="71,71,71 79,79,79 114,114,114 91,91,91"
recorded_2="140,140,140 249,249,249 251,251,251 251,251,251"
recorded_3="141,141,141 124,124,124 141,141,141 126,126,126"
pixel_cases "$srcdir/tests/fog_turbulence.pov" Case "0 1 2 3" \
  "2,2 6,8 9,13 10,5"
