#!/bin/sh
# test_no_bump_scale.sh - no_bump_scale (tests/no_bump_scale.pov): a
# scaled normal keeps its size but not its depth, on a normal and on a
# texture's normal (mjhorvath's GSprites terrain textures).  Pixels of
# each strip are povray's, recorded below (povray 3.7.0.10, 16x12, -A
# +WT1 -GA); each channel must be within 2 levels.  Before, the keyword
# was ignored: 169 and 173 for 158 and 156 in the top strip.  With
# povray installed the whole picture is compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
# ROW,COL=R,G,B
pixel_case "$srcdir/tests/no_bump_scale.pov" 0 Unused=1 \
  1,3=158,158,158 1,12=156,156,156 4,3=156,156,156 4,12=154,154,154 \
  7,3=171,171,171 7,12=173,173,173 10,3=151,151,151 10,12=148,148,148
