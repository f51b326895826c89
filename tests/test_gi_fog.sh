#!/bin/sh
# test_gi_fog.sh - the irradiance cache's sample rays pass through fog
# unchanged, as povray 3.7's radiosity rays do (lib/gi/cache.c gather
# sets the tracer's no_fog; lib/trace/shade.c fogged()).  A white floor
# seen from 0.1 above, lit only by a green sky through a red fog
# (tests/gi_fog.pov): povray 3.7.0.10 (-A +WT1 -GA, 16x12) renders the
# floor green with the camera ray's own tenth of fog, 97,241,0 at the
# corners and 87,244,0 in the middle for a fog of distance 1, and
# 34,253,0 / 29,254,0 for a ground fog; the tree before fogged the
# sample rays too, 255,0,0 and 161,210,0 all over.  With povray
# installed the whole picture is compared too (it was identical).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="97,241,0 87,244,0 97,241,0"
recorded_2="34,253,0 29,254,0 33,253,0"
pixel_cases "$srcdir/tests/gi_fog.pov" Fog "1 2" "0,0 6,8 11,15"
