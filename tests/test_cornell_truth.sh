#!/bin/sh
# test_cornell_truth.sh - what the radiosity benchmark's scores rest on.
#
# bench/radiosity.sh scores POV-Ray's radiosity, which 3.7 can only write
# as a Radiance HDR file (+FH), against the path-traced ground truth
# cbox_emissive-256.pfm with `imgcmp --rmse`.  So this test checks:
#  - imgcmp reads RGBE pictures: the adaptive run-length encoding (runs
#    and literals), flat pixels with the old run-length repeat code, the
#    mantissa decoding (m + 0.5) * 2^(e - 136) and the row order, against
#    a PFM holding the expected values (stored bottom row first, so a row
#    flip shows); the figures --info prints are exact here because every
#    value is a short binary fraction;
#  - bad pictures end with status 2 and the exact message;
#  - the ground truth (when ../shared/reference is there, else those
#    checks are skipped): 256x256, its brightest samples are the
#    emitter's radiance (30, the red of emission <30, 20.1, 6.3>, stored
#    exactly), it scores 0 against itself and the renderer's scene copy
#    scenes/cornell.pov (or bench/radiosity/cornell.pov) is the
#    reference scene byte for byte after its "// golden: skip" line.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
srcdir=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
imgcmp=${ZR_BUILDDIR:-$(pwd)}/tests/imgcmp
if [ ! -x "$imgcmp" ]; then
  echo "test_cornell_truth.sh: no imgcmp at $imgcmp" >&2
  exit 99
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_cornell_truth.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 99

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# expect NAME STATUS STDOUT STDERR COMMAND...: the command's exact
# status, standard output and standard error.
expect() {
  name=$1 status=$2 want_out=$3 want_err=$4
  shift 4
  "$@" >"$name.out" 2>"$name.err"
  got=$?
  [ "$got" -eq "$status" ] || fail "$name: status $got, want $status"
  [ "$(cat "$name.out")" = "$want_out" ] ||
    fail "$name: stdout '$(cat "$name.out")', want '$want_out'"
  [ "$(cat "$name.err")" = "$want_err" ] ||
    fail "$name: stderr '$(cat "$name.err")', want '$want_err'"
}

header='#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n'
# Pixel A = (128, 64, 32) with exponent 129: (m + 0.5) / 128 =
# 1.00390625, 0.50390625, 0.25390625.  The top two rows are A, the bottom
# two black (imgcmp's 2x2 box filter would average a flip of a 2-row
# picture away).

# 8x4, adaptive encoding: the A rows as four runs of 8 (code 128 + 8),
# the black rows as four literals of 8 zeros.
runs='\2\2\0\10\210\200\210\100\210\040\210\201'
zeros='\010\0\0\0\0\0\0\0\0'
literals='\2\2\0\10'"$zeros$zeros$zeros$zeros"
printf "$header"'-Y 4 +X 8\n'"$runs$runs$literals$literals" >rle.hdr

# 4x4, flat pixels (too narrow for the adaptive encoding): pixel A and
# the old repeat code 1, 1, 1, 3; then A four times; then black.
black4='\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0'
printf "$header"'-Y 4 +X 4\n\200\100\040\201\1\1\1\3' >flat.hdr
printf '\200\100\040\201\200\100\040\201\200\100\040\201\200\100\040\201' \
  >>flat.hdr
printf "$black4$black4" >>flat.hdr

# The same pictures as PFM: little-endian floats, bottom row first.
a='\0\200\200\77\0\0\1\77\0\0\202\76'
black='\0\0\0\0\0\0\0\0\0\0\0\0'
pfm() { # width, file, the pixel of the bottom rows, of the top rows
  printf 'PF\n%d 4\n-1.0\n' "$1" >"$2"
  for pixel in "$3" "$4"; do
    i=0
    while [ $i -lt $((2 * $1)) ]; do
      printf "$pixel" >>"$2"
      i=$((i + 1))
    done
  done
}
pfm 8 rle.pfm "$black" "$a"
pfm 4 flat.pfm "$black" "$a"
pfm 4 flip.pfm "$a" "$black"

# Means over the samples, half of them A's.
info='mean=0.293620 clipped_mean=0.292969 max=1.003906'
expect rle-info 0 "width=8 height=4 $info" '' "$imgcmp" --info rle.hdr
expect flat-info 0 "width=4 height=4 $info" '' "$imgcmp" --info flat.hdr
expect pfm-info 0 "width=8 height=4 $info" '' "$imgcmp" --info rle.pfm
expect rle-rmse 0 'rmse=0.0000' '' "$imgcmp" rle.hdr rle.pfm --rmse
expect flat-rmse 0 'rmse=0.0000' '' "$imgcmp" flat.hdr flat.pfm --rmse
# Upside down, the error is large: the comparison sees the rows.  With
# clipped A = (1, 0.50390625, 0.25390625): sqrt(mean of A^2 over the
# channels) / (mean of A / 2) = 2.2628.
expect flip-rmse 1 'rmse=2.2628' '' "$imgcmp" flat.hdr flip.pfm \
  --rmse-max 0.01

# Bad pictures.
head -c 100 rle.hdr >short.hdr
expect short 2 '' 'imgcmp: short.hdr: malformed or truncated pixel data' \
  "$imgcmp" --info short.hdr
printf "$header"'+Y 2 +X 4\n' >upside.hdr
expect upside 2 '' \
  'imgcmp: upside.hdr: only the resolution line "-Y H +X W" is supported' \
  "$imgcmp" --info upside.hdr
printf '#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\0\0\0\0' >xyz.hdr
expect xyz 2 '' 'imgcmp: xyz.hdr: only FORMAT=32-bit_rle_rgbe is supported' \
  "$imgcmp" --info xyz.hdr
# A run that overflows the scanline (code 128 + 9 in a row of 8).
printf "$header"'-Y 1 +X 8\n\2\2\0\10\211\0' >long.hdr
expect long 2 '' 'imgcmp: long.hdr: malformed or truncated pixel data' \
  "$imgcmp" --info long.hdr
# Old repeat codes of length 0, one after another: their shift grows by
# 8 bits each time, which must stop before it overflows.
repeat0='\1\1\1\0\1\1\1\0\1\1\1\0\1\1\1\0'
printf "$header"'-Y 1 +X 4\n\200\100\040\201'"$repeat0$repeat0$repeat0" \
  >zeros.hdr
expect zeros 2 '' 'imgcmp: zeros.hdr: malformed or truncated pixel data' \
  "$imgcmp" --info zeros.hdr
expect usage 2 '' "$("$imgcmp" --help 2>&1)" "$imgcmp" --info a b

# The ground truth and the scene, when the reference directory exists.
ref=$srcdir/../shared/reference
if [ -f "$ref/cbox_emissive-256.pfm" ]; then
  truth=$ref/cbox_emissive-256.pfm
  "$imgcmp" --info "$truth" >truth.out 2>&1 || fail "truth: unreadable"
  grep -q '^width=256 height=256 .* max=30.000000$' truth.out ||
    fail "truth: $(cat truth.out), want 256x256 and max 30 (the emitter)"
  expect truth-self 0 'rmse=0.0000' '' "$imgcmp" "$truth" "$truth" --rmse
  scene=$srcdir/scenes/cornell.pov
  [ -f "$scene" ] || scene=$srcdir/bench/radiosity/cornell.pov
  # scenes/cornell.pov adds a first line, "// golden: skip WHY", which
  # keeps it out of the golden suite (tests/golden.sh).
  sed '1{/^\/\/ golden: skip/d;}' "$scene" |
    cmp -s - "$ref/cbox_emissive.pov" ||
    fail "$scene differs from $ref/cbox_emissive.pov"
else
  echo "test_cornell_truth.sh: no $ref, ground truth checks skipped"
fi

[ $failures -eq 0 ] && echo "test_cornell_truth.sh: all checks passed"
[ $failures -eq 0 ]
