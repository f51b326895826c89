#!/bin/sh
# test_poly_degree.sh - a quartic's ray polynomial keeps a small
# leading term where it matters out to the roots' bound
# (lib/trace/obj_poly.c lowered_degree).  tests/poly_degree.pov looks
# at the Piriform nearly across its x axis; the middle rows' rays have
# an x^4 term of 1e-11, which, dropped, left a cubic with a root at
# 1e7: a line of false hits at eye height across the picture (pixels
# 70 where povray has the background's 39; objects/quartic/teardrop.pov
# scored SSIM 0.945).  Pixels recorded from povray 3.7.0.10 (16x12, -A
# +WT1 -GA), each channel within 2 levels; with povray installed the
# whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
bg=39,39,39
pixel_case "$srcdir/tests/poly_degree.pov" q Unused=0 4,0=$bg 4,3=$bg \
  5,2=$bg 5,12=$bg 4,15=$bg 5,7=135,185,210 6,6=69,97,111
