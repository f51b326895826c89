#!/bin/sh
# test_alpha.sh - +UA (Output_Alpha) from the command line, without
# povray: the same bytes with 1 and 3 threads and with 1 and 2 ranks
# under mpirun, antialiasing on (alpha travels through the gather and is
# averaged over supersamples); PNG is RGBA (colour type 6), Targa and
# BMP are 32 bits a pixel; the background of a scene without #version
# is clear; a format without alpha (PPM) is written without it, with a
# warning, and so is Output_Alpha=off; OpenEXR colours are
# premultiplied.  tests/test_alpha_povray.sh
# compares the alpha with povray's.
set -u
TEST_NAME=test_alpha
. "$(dirname "$0")/cli_env.sh"
cd "$work" || exit 99

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

cat >scene.pov <<'POV'
camera { location <0, 0, -4> look_at 0 }
light_source { <5, 5, -5> rgb 1 }
background { rgb <0.2, 0.4, 0.8> }
sphere { <-0.6, 0, 0>, 0.8 pigment { rgbt <1, 0.5, 0.2, 0.5> } }
sphere { <1.2, 0, 0>, 0.6 pigment { rgbf <0.2, 0.5, 1, 0.7> }
  interior { ior 1.3 } }
plane { y, -1 pigment { checker rgb 1 rgb 0.2 } finish { reflection 0.3 } }
POV
zr() { timeout 120 "$ZRCUBE" scene.pov +W48 +H36 -D +A0.1 "$@"; }

zr +WT1 +UA +Oone.png 2>one.err || fail "+UA +WT1: $(tail -1 one.err)"
zr +WT3 +UA +Othree.png 2>three.err || fail "+UA +WT3: $(tail -1 three.err)"
cmp -s one.png three.png || fail "+UA: 1 and 3 threads differ"
ASAN_OPTIONS="$MPI_ASAN" timeout 300 "$MPIRUN" -n 2 "$ZRCUBE" scene.pov \
  +W48 +H36 -D +A0.1 +WT1 +UA +Otwo.png 2>two.err ||
  fail "+UA under mpirun -n 2: $(tail -1 two.err)"
cmp -s one.png two.png || fail "+UA: 1 and 2 ranks differ"
# PNG colour type (byte 25): 6 is RGBA, 2 RGB.
[ "$(od -A n -t u1 -j 25 -N 1 one.png | tr -d ' ')" = 6 ] ||
  fail "+UA: the PNG is not RGBA"
# Alpha of the top-left pixel (background only): 0.  Read with zrcube's
# own writer: +FT stores it as the 4th byte of the first pixel.
zr +WT1 +UA +FT +Oone.tga 2>tga.err || fail "+UA +FT: $(tail -1 tga.err)"
[ "$(od -A n -t u1 -j 16 -N 2 one.tga | tr -s ' ')" = " 32 40" ] ||
  fail "+UA +FT: not a 32-bit Targa with 8 alpha bits"
[ "$(od -A n -t u1 -j 21 -N 1 one.tga | tr -d ' ')" = 0 ] ||
  fail "+UA: the background is not clear"
zr +WT1 +UA +FB +Oone.bmp 2>bmp.err || fail "+UA +FB: $(tail -1 bmp.err)"
[ "$(od -A n -t u1 -j 28 -N 1 one.bmp | tr -d ' ')" = 32 ] ||
  fail "+UA +FB: not a 32-bit BMP"
# Without alpha: RGB, and the background's colour.
zr +WT1 Output_Alpha=off +Oplain.png 2>plain.err ||
  fail "-UA: $(tail -1 plain.err)"
[ "$(od -A n -t u1 -j 25 -N 1 plain.png | tr -d ' ')" = 2 ] ||
  fail "Output_Alpha=off: the PNG is not RGB"
zr +WT1 +UA +FP +Oplain.ppm 2>ppm.err || fail "+UA +FP: $(tail -1 ppm.err)"
grep -q "warning: +UA: this output format holds no alpha channel" ppm.err ||
  fail "+UA +FP: no warning"
zr +WT1 +FP +Oplain2.ppm 2>/dev/null || fail "+FP"
cmp -s plain.ppm plain2.ppm || fail "+UA +FP differs from +FP"

# OpenEXR keeps colours premultiplied (as povray's +UA +FE): in this
# scene of no #version, black behind, the colours equal those of the
# render without +UA.
imgcmp="${ZR_BUILDDIR:-$(pwd)}/tests/imgcmp"
if "$ZRCUBE" +I/dev/null +FE 2>&1 | grep -q "built without OpenEXR"; then
  echo "no OpenEXR in this build: +FE skipped"
elif [ -x "$imgcmp" ]; then
  sed '/^background/d' scene.pov >black.pov
  timeout 120 "$ZRCUBE" black.pov +W48 +H36 -D +WT1 +UA +FE +Oa.exr \
    2>/dev/null || fail "+UA +FE"
  timeout 120 "$ZRCUBE" black.pov +W48 +H36 -D +WT1 +FE +Ob.exr \
    2>/dev/null || fail "+FE"
  "$imgcmp" a.exr b.exr --ssim-min 1 --delta-max 0 >/dev/null ||
    fail "+UA +FE: the colours are not premultiplied"
fi

[ "$failures" -eq 0 ] || exit 1
echo "test_alpha: ok"
exit 0
