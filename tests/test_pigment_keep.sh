#!/bin/sh
# test_pigment_keep.sh - pigment { COLOUR ... } given to an object that
# has a pigment modifies that pigment (the manual, "Textures": "If it
# has a texture then the pigment, normal or finish will modify the
# existing texture"): POV-Ray 3.7 draws the colour, but keeps the old
# pigment's transform, colour_map and warps for a pattern named later
# (tests/pigment_keep.pov), and a pattern named in a block that
# modifies a pigment keeps that pigment's turbulence, warps, frequency,
# phase and wave type (lib/scene/pattern.c zr__pattern_set_kind); so
# does a pattern named in a normal block that modifies a normal.  The tree before this test started such a
# pigment afresh, so corpus church-window.pov's red border took the
# crackle at 0.9 instead of 0.324 (SSIM 0.934 -> 0.981).
# povray 3.7.0.10's pixels (16x12, -A +WT1 -GA, row 6 from the top) and
# what the tree before gave:
#   1 pigment identifier after the colour: replaces all, period 1: 64 191
#     64 191 (both)
#   2 gradient x without colour_map after the colour: B's blue-green map
#     at B's period 2: 0,32,223 0,96,159 ... (before grey 64 191 64 191)
#   3 colour, scale 0.5, then a gradient: 2 x 0.5, period 1: 64 191
#     (before 128 128 128 128: period 0.5)
#   4 a union's pigment, colour, object scaled 0.5, then a gradient:
#     period 1 (before 128 128 128 128)
#   5 the colour alone: red (both)
#   6-10 B's pigment given octaves 1 turbulence 0.5, frequency 2, phase
#     0.5, warp { turbulence 0.5 }, triangle_wave, then a gradient x
#     with a grey map: 85 134 176 231; 64 191 64 191; 159 223 32 96;
#     21 127 186 236; 64 191 191 64 (before, each 32 96 159 223: the
#     modifier lost)
#   11-15 N's normal (a sine-wave gradient x of bump size 1, period 2)
#     given frequency 2, phase 0.5, scallop_wave, octaves 1 turbulence
#     0.5, warp { turbulence 0.5 }, then normal { gradient x 1 }: the
#     modifier kept, as in pigments (before, each 234 234 234 234: a
#     plain ramp, the sine wave lost); 16 N alone
# With povray installed its whole picture is compared too (within 2).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/pigment_keep.pov
recorded_1="6,0=64,64,64 6,1=191,191,191 6,2=64,64,64 6,3=191,191,191"
recorded_2="6,0=0,32,223 6,1=0,96,159 6,2=0,159,96 6,3=0,223,32"
recorded_3="6,0=64,64,64 6,1=191,191,191 6,2=64,64,64 6,3=191,191,191"
recorded_4="6,4=64,64,64 6,5=191,191,191 6,6=64,64,64 6,7=191,191,191"
recorded_5="6,0=255,0,0 6,1=255,0,0 6,2=255,0,0 6,3=255,0,0"
recorded_6="6,0=85,85,85 6,1=134,134,134 6,2=176,176,176 6,3=231,231,231"
recorded_7="6,0=64,64,64 6,1=191,191,191 6,2=64,64,64 6,3=191,191,191"
recorded_8="6,0=159,159,159 6,1=223,223,223 6,2=32,32,32 6,3=96,96,96"
recorded_9="6,0=21,21,21 6,1=127,127,127 6,2=186,186,186 6,3=236,236,236"
recorded_10="6,0=64,64,64 6,1=191,191,191 6,2=191,191,191 6,3=64,64,64"
recorded_11="6,0=212,212,212 6,1=225,225,225 6,2=212,212,212 6,3=225,225,225"
recorded_12="6,0=174,174,174 6,1=247,247,247 6,2=246,246,246 6,3=171,171,171"
recorded_13="6,0=251,251,251 6,1=236,236,236 6,2=194,194,194 6,3=156,156,156"
recorded_14="6,0=185,185,185 6,1=152,152,152 6,2=198,198,198 6,3=250,250,250"
recorded_15="6,0=250,250,250 6,1=151,151,151 6,2=213,213,213 6,3=251,251,251"
recorded_16="6,0=246,246,246 6,1=171,171,171 6,2=174,174,174 6,3=247,247,247"
pixel_cases "$scene" K "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16"
