#!/bin/sh
# test_legacy_povray.sh - old and lenient syntax that POV-Ray 3.7 accepts
# from 3.0-3.6 scenes, picture to picture: every tests/legacy/*.pov is
# rendered by povray and by zRcube (160x120, no antialiasing, one
# thread) and must score SSIM >= 0.95 (tests/imgcmp, 2x2 box filter).
# A scene may name the zRcube warnings it expects in "// expect: TEXT"
# lines; each must appear in zRcube's output.  srgb.pov also runs with
# assumed_gamma 2.2.  Skips (77) when povray is not installed.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
ZR_NEEDS_POVRAY=1
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir"/tests/legacy/*.pov "$srcdir"/tests/legacy/*.inc . || exit 99
sed 's/^#ifndef (Gamma).*/#declare Gamma = 2.2;/' srgb.pov >srgb_gamma22.pov
pass=0 fail=0
for scene in *.pov; do
  name=${scene%.pov}
  if ! timeout 60 povray +I"$scene" +O"$name.pov.png" +W160 +H120 -D -A \
      +WT1 -GA +L/usr/share/povray-3.7/include </dev/null \
      >"$name.pov.log" 2>&1; then
    echo "$name: povray failed" >&2
    tail -3 "$name.pov.log" >&2
    exit 99
  fi
  if ! timeout 60 "$zrcube" +I"$scene" +O"$name.zr.png" +W160 +H120 -D \
      +WT1 </dev/null >"$name.zr.log" 2>&1; then
    echo "$name: zrcube failed FAIL"
    tail -3 "$name.zr.log"
    fail=$((fail + 1))
    continue
  fi
  ok=yes
  result=$("$imgcmp" "$name.zr.png" "$name.pov.png" --ssim-min 0.95) || ok=no
  missing=$(sed -n 's|^// expect: ||p' "$scene" | while IFS= read -r w; do
    grep -qF -- "$w" "$name.zr.log" || echo "$w"
  done)
  if [ -n "$missing" ]; then
    ok=no
    result="$result; warning missing: $missing"
  fi
  if [ $ok = yes ]; then
    echo "$name: $result ok"
    pass=$((pass + 1))
  else
    echo "$name: $result FAIL"
    fail=$((fail + 1))
  fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
