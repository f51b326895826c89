#!/bin/sh
# test_media_cells.sh - the brightness of thick media against POV-Ray
# 3.7's: tests/media_cells.pov's four cases (the issue's scattering box,
# an emitting slab with samples 3, a density rising as z^2, Henyey-
# Greenstein scattering with intervals 3) at 16x12, pixels recorded
# from povray (each channel within 2 levels; with povray installed, the
# whole picture against its render too).  Before method 3 summed cells
# as POV-Ray does (lib/trace/media.c, gather_cell();
# bench/media_quadrature.py) case 1 was up to 41 levels darker.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
scene=$srcdir/tests/media_cells.pov
fail=0
pixel_case "$scene" 1 Case=1 3,8=158,158,158 6,8=53,53,54 9,8=13,14,14 \
  1,1=89,124,149 || fail=1
pixel_case "$scene" 2 Case=2 3,8=199,158,132 6,8=199,158,132 \
  9,8=199,158,132 1,1=89,124,149 || fail=1
pixel_case "$scene" 3 Case=3 3,8=179,193,206 6,8=179,193,206 \
  9,8=179,193,206 1,1=89,124,149 || fail=1
pixel_case "$scene" 4 Case=4 3,8=149,157,149 6,8=61,95,112 9,8=21,59,88 \
  1,1=89,124,149 || fail=1
exit $fail
