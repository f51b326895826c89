#!/bin/sh
# test_default_normal.sh - a normal pattern written without a bump size
# takes the one its block starts from: the #default normal's (also in a
# normal_map's entries) or an identifier's, and 0.5 when neither gives
# one (lib/sdl/build.c zr__sdl_normal_new, zr__sdl_normal_pattern).
# tests/default_normal.pov, cases 1 to 5; eight pixels of each are
# povray's, recorded below (povray 3.7.0.10, 16x12, -A +WT1 -GA), each
# channel within 2 levels.  Before, every pattern keyword set 0.5: cases
# 1 to 4 were 6 to 41 levels off and textures/normals/normmap.pov scored
# SSIM 0.90 (0.98 now).  With povray installed the whole pictures are
# compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
px="2,3 2,12 6,8 9,3 9,12 3,4 8,11 5,6"
recorded_1="102,102,102 176,176,176 104,104,104 102,102,102 176,176,176 176,176,176 104,104,104 103,103,103"
recorded_2="141,141,141 156,156,156 141,141,141 141,141,141 156,156,156 156,156,156 141,141,141 141,141,141"
recorded_3="102,102,102 176,176,176 166,166,166 142,142,142 155,155,155 176,176,176 110,110,110 103,103,103"
recorded_4="$recorded_2"
recorded_5="135,135,135 161,161,161 136,136,136 135,135,135 160,160,160 160,160,160 136,136,136 136,136,136"
pixel_cases "$srcdir/tests/default_normal.pov" Case "1 2 3 4 5" "$px"
