#!/bin/sh
# test_media_curvature.sh - when povray 3.7's media method 3 halves a
# cell and what a halved cell gives (lib/trace/media.c, cell_means()):
# a cell is halved when its middle sample's coefficients differ from the
# mean of its ends' (a density that changes linearly along the ray is
# never halved; a step or a curve is), and a halved cell adds its light
# once, with the mean of its halves' coefficients, dimmed only by the
# cells before it.  tests/media_curvature.pov's three cases at 16x12,
# pixels recorded from povray 3.7.0.10 (each channel within 2 levels;
# with povray installed, its whole render too); the probe values behind
# the rule are bench/conform/media_curvature_probe.py's.  Before (cells
# halved on any difference between neighbouring samples, halves summed
# one after the other) case 1 was 25 levels dark in the middle, cases 2
# and 3 18 and 10.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
scene=$srcdir/tests/media_curvature.pov
fail=0
pixel_case "$scene" 1 Case=1 6,8=239,203,188 6,9=218,185,188 \
  6,10=141,153,188 5,7=239,203,188 4,6=186,167,188 1,1=124,149,188 || fail=1
pixel_case "$scene" 2 Case=2 6,5=136,99,70 6,8=136,99,70 3,10=136,99,70 \
  6,13=0,0,0 || fail=1
pixel_case "$scene" 3 Case=3 6,5=104,74,52 6,8=104,74,52 3,10=104,74,52 \
  6,13=0,0,0 || fail=1
exit $fail
