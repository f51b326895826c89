#!/bin/sh
# test_normal_warped.sh - pattern normals with turbulence or warps
# (tests/normal_warped.pov): povray 3.7 moves the point by the pattern's
# warps and turbulence once and samples the height around the moved
# point (lib/scene/texture.c, slope_tilt); marble and wood, whose
# turbulence is their own, excepted.  The pixels below are povray's
# (povray 3.7.0.10, 16x12, -A +WT1 -GA); each channel must be within 2
# levels.  Before, each sample was moved by the turbulence at its own
# place, which breaks a crackle's cells into speckle: case 1's first
# pixel was 110,89,234 for povray's 234,194,233, and the chrome water of
# templates/Basic_Scenes/Sea_*.pov glittered where povray's is calm.
# With povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_0="221,216,206 212,223,231 204,231,213 221,217,216"
recorded_1="234,194,233 208,226,203 228,202,192 179,242,206"
recorded_2="254,92,188 230,204,228 141,241,148 159,248,209"
recorded_3="0,222,185 226,114,43 234,193,196 195,234,232"
pixel_cases "$srcdir/tests/normal_warped.pov" Case "0 1 2 3" \
  "2,2 6,8 9,13 10,5"
