#!/bin/sh
# test_object_mods.sh - an object's pigment { }, normal { } and finish { }
# after its texture modify that texture's (its top layer's), as the same
# blocks do inside a texture block (grammar/pov.y object_body and
# union_body; tests/object_mods.pov).  The tree before this test started
# them from the built-in defaults, so sphere { texture { T } finish {
# ambient 0.4 } } lost T's diffuse 0 (the corpus' glasstestreal.pov,
# texture { Glass } finish { ambient ... phong ... }: a glass blob too
# bright by ~30 levels, SSIM 0.927).  povray 3.7.0.10's pixels (16x12,
# -A +WT1 -GA) at rows,columns 6,8 4,6 8,10 3,9, and what the tree
# before this test gave:
#   1 texture's finish, object's finish: 170,124,89 everywhere (before
#     208,152,111 245,180,131 170,124,89 219,161,117: diffuse 0.6)
#   2 the same through object { S finish { } }: as 1 (before as 1's)
#   3 the finish on a union whose child has a texture: black (unchanged)
#   4 a union's texture, then its finish: as 1 (before as 1's)
#   5 a checker texture, then pigment { scale 5 }: 255,188,137 and the
#     second colour at 3,9 (before black: the default pigment)
#   6 a bumps normal scaled 0.3, then normal { scale 3 }: 78 226 0 204
#     (before 167 237 0 190)
#   7 the same, then normal { bumps 1 scale 0.9 }: 198 139 0 193
#     (before 78 226 0 204)
#   8 no texture, pigment and finish: the defaults (unchanged)
#   9 an object moved after its pigment, then pigment { checker ... }: the
#     checker moves with it; at 6,0 6,2 6,4 6,8: 255 124 255 124 (before
#     124 255 124 124: the checker where it was declared)
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="170,124,89 170,124,89 170,124,89 170,124,89"
recorded_2="170,124,89 170,124,89 170,124,89 170,124,89"
recorded_3="0,0,0 0,0,0 0,0,0 0,0,0"
recorded_4="170,124,89 170,124,89 170,124,89 170,124,89"
recorded_5="255,188,137 255,188,137 255,188,137 188,188,188"
recorded_6="78,78,78 226,226,226 0,0,0 204,204,204"
recorded_7="198,198,198 139,139,139 0,0,0 193,193,193"
recorded_8="208,152,111 245,180,131 170,124,89 219,161,117"
recorded_9="255,255,255 124,124,124 255,255,255 124,124,124"
fail=0
pixel_cases "$srcdir/tests/object_mods.pov" Case "1 2 3 4 5 6 7 8" \
  "6,8 4,6 8,10 3,9" || fail=1
pixel_cases "$srcdir/tests/object_mods.pov" Case "9" "6,0 6,2 6,4 6,8" ||
  fail=1
exit $fail
