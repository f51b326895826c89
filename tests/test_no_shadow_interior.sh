#!/bin/sh
# test_no_shadow_interior.sh - a no_shadow object's interior shadows
# nothing (tests/no_shadow_interior.pov): povray 3.7 lets the light
# through the absorbing media (K=1) and the fade_distance filter (K=2)
# of a no_shadow sphere onto the plane below, and only without
# no_shadow (NS=0) do they shadow it.  Before, zRcube skipped only the
# surface of a no_shadow object on shadow rays and still applied its
# media and fading: the cloud of the corpus scene p2_100386336 (a
# no_shadow media sphere) shaded itself through 30 x 30 media samples
# per ray, and rendered darker and 5x slower.  Pixels (row,column) below
# the sphere are povray's, recorded below (povray 3.7.0.10, 16x12, -A
# +WT1 -GA), each channel within 2 levels; with povray installed the
# whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_10="7,7=6,6,6 8,7=90,90,90 9,7=95,95,95 8,5=95,95,95"
recorded_11="7,7=29,29,29 8,7=218,218,218 9,7=218,218,218 8,5=218,218,218"
recorded_20="7,7=66,22,71 8,7=132,102,137 9,7=136,103,137 8,5=136,103,137"
recorded_21="7,7=113,57,116 8,7=218,218,218 9,7=218,218,218 8,5=218,218,218"
pixel_cases "$srcdir/tests/no_shadow_interior.pov" C "10 11 20 21"
