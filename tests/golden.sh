#!/bin/sh
# golden.sh - the golden-scene suite: every scenes/NAME.pov rendered by
# zRcube must look like POV-Ray 3.7's rendering of it, tests/ref/NAME.png.
#
# "Look like" is SSIM >= 0.98 (tests/imgcmp: 2x2 box filter, 11x11
# Gaussian window, sRGB space, mean over R, G, B) and a worst 8x8 block
# colour difference delta <= 0.05.  SSIM alone forgives wrong brightness
# over smooth areas (a scene without its ambient term scores 0.981);
# delta catches that, while the single silhouette pixels in which two
# correct ray tracers differ are diluted in it (POV-Ray with and without
# antialiasing: delta <= 0.038).  Byte equality is never asked for.
#
# Environment (set by AM_TESTS_ENVIRONMENT under `make check`):
#   ZR_SRCDIR, ZR_BUILDDIR  source and build trees (default: this script's
#                           tree and its build/)
#   GOLDEN_SCENES           names to run instead of all ("phong tir")
#   (a scene whose first line is "// golden: skip WHY" is left out of
#   "all": it has a test of its own)
#   GOLDEN_KEEP             a directory to keep zRcube's renders in
#   GOLDEN_SSIM_MIN         threshold (default 0.98)
#   GOLDEN_DELTA_MAX        threshold (default 0.05)
# The references are 160x120, no antialiasing (tests/ref/make-refs.sh).
set -u
here=$(cd "$(dirname "$0")" && pwd)
srcdir=${ZR_SRCDIR:-$(cd "$here/.." && pwd)}
builddir=${ZR_BUILDDIR:-$srcdir/build}
zrcube=$builddir/bin/zrcube
imgcmp=$builddir/tests/imgcmp
ssim_min=${GOLDEN_SSIM_MIN:-0.98}
delta_max=${GOLDEN_DELTA_MAX:-0.05}
width=160
height=120

for tool in "$zrcube" "$imgcmp"; do
  if [ ! -x "$tool" ]; then
    echo "golden: $tool is not built" >&2
    exit 99 # a hard error for the automake test driver
  fi
done

# The comparator must tell pictures apart before its verdicts count: a
# reference against itself scores exactly 1, two different scenes fail.
check_ref_a=$srcdir/tests/ref/phong.png
check_ref_b=$srcdir/tests/ref/specular.png
same=$("$imgcmp" "$check_ref_a" "$check_ref_a" --ssim-min "$ssim_min" \
       --delta-max "$delta_max")
if [ $? -ne 0 ] || [ "$same" != "ssim=1.0000 delta=0.0000" ]; then
  echo "golden: imgcmp scores an image against itself as '$same'" >&2
  exit 99
fi
if "$imgcmp" "$check_ref_a" "$check_ref_b" --ssim-min "$ssim_min" \
     >/dev/null; then
  echo "golden: imgcmp does not tell phong.png and specular.png apart" >&2
  exit 99
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/zr-golden.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT INT TERM
out_dir=${GOLDEN_KEEP:-$work}
mkdir -p "$out_dir" || exit 99

if [ -n "${GOLDEN_SCENES:-}" ]; then
  names=$GOLDEN_SCENES
else
  # A scene whose first line is "// golden: skip WHY" has its own test
  # (scenes/cornell.pov: tests/test_cornell_truth.sh).
  names=$(cd "$srcdir/scenes" && ls *.pov | grep -v '\.ref\.pov$' |
          while read -r f; do
            head -n 1 "$f" | grep -q '^// golden: skip' ||
              echo "${f%.pov}"
          done)
  # A reference without its scene is a leftover that tests nothing.
  for ref in "$srcdir"/tests/ref/*.png; do
    name=$(basename "$ref" .png)
    [ -f "$srcdir/scenes/$name.pov" ] ||
      echo "golden: warning: $ref has no scene" >&2
  done
fi

# Runs a command with a time limit when timeout(1) exists.
limited() {
  if command -v timeout >/dev/null 2>&1; then
    timeout 300 "$@"
  else
    "$@"
  fi
}

passed=0
failed=0
for name in $names; do
  scene=$srcdir/scenes/$name.pov
  ref=$srcdir/tests/ref/$name.png
  out=$out_dir/$name.png
  if [ ! -f "$scene" ]; then
    echo "$name: FAIL (no scene $scene)"
    failed=$((failed + 1))
    continue
  fi
  if [ ! -f "$ref" ]; then
    echo "$name: FAIL (no reference; run tests/ref/make-refs.sh $name)"
    failed=$((failed + 1))
    continue
  fi
  rm -f "$out"
  if ! limited "$zrcube" "$scene" +W$width +H$height -A +O"$out" \
       +L"$srcdir/scenes" >"$work/$name.log" 2>&1; then
    echo "$name: FAIL (zrcube failed)"
    sed 's/^/    /' "$work/$name.log" | head -20
    failed=$((failed + 1))
    continue
  fi
  result=$("$imgcmp" "$out" "$ref" --ssim-min "$ssim_min" \
           --delta-max "$delta_max" 2>&1)
  status=$?
  if [ $status -eq 0 ]; then
    echo "$name: $result ok"
    passed=$((passed + 1))
  else
    echo "$name: $result FAIL (need ssim >= $ssim_min, delta <= $delta_max)"
    failed=$((failed + 1))
  fi
done

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
