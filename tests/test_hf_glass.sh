#!/bin/sh
# test_hf_glass.sh - rays reflected or refracted at an upside-down smooth
# height field of glass (stock advanced/glasschess.pov's board) leave the
# surface where they met it (lib/trace/shade.c ray_start;
# tests/hf_glass.pov).  The tree before this test moved their start off
# the surface along the smooth normal, nearly vertical on the steps'
# walls, which left it on the side the ray came from: the ray met the
# same wall again and the steps showed black or mirrored lines
# (glasschess SSIM 0.908, now 0.972).
# povray 3.7.0.10's pixels (80x60, -A +WT1 -GA; rows from the top) and
# what the tree before gave:
#   1 filter 1: 35,37 36,24 36,49 the box's white square through the
#     glass, 108,111,108 (before black); 29,46 the sky 231,187,188 (both)
#   2 reflection 1: 35,37 the box's blue 0,0,89 (before the sky
#     226,185,194); 36,15 36,29 the sky (before the box's blue)
# With povray installed its whole picture is compared too (within 2).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/hf_glass.pov
recorded_1="35,37=108,111,108 36,24=108,111,108 36,49=108,111,108 29,46=231,187,188"
recorded_2="35,37=0,0,89 36,15=225,185,195 36,29=225,184,195 28,77=230,187,189"
pixel_w=80 pixel_h=60
pixel_cases "$scene" K "1 2"
