#!/bin/sh
# test_refused.sh - scenes POV-Ray 3.7 refuses, reduced from the corpus
# scenes it refused (bench/refused.py, bench/results/refused-*.tsv): each
# tests/refused/*.pov names in "// expect-error: TEXT" lines what
# zRcube's error output must contain (file:line:col and the problem), and
# zrcube must exit 1 without writing a picture.  A scene with no
# expect-error line is one POV-Ray 3.7 renders (perhaps with a warning,
# "// expect: TEXT" lines): zrcube must render it too, and print each
# "// expect-debug: TEXT" (#debug output).  With povray installed, povray
# must agree (refuse or render, and the #debug lines) on every scene, so
# the snippets stay true to the yardstick, and a scene both render must
# score SSIM >= 0.95 (tests/imgcmp, 2x2 box filter, 64x48 pixels).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp -r "$srcdir"/tests/refused/* . || exit 99
pass=0 fail=0
for scene in *.pov; do
  name=${scene%.pov}
  refuse=no
  grep -q '^// expect-error: ' "$scene" && refuse=yes
  ok=yes why=""
  if command -v povray >/dev/null 2>&1; then
    prc=0
    timeout 60 povray +I"$scene" +O"$name.pov.png" +W64 +H48 -D -A +WT1 \
      +L/usr/share/povray-3.7/include </dev/null >"$name.pov.log" 2>&1 ||
      prc=$?
    if { [ $refuse = yes ] && [ $prc -eq 0 ]; } ||
       { [ $refuse = no ] && [ $prc -ne 0 ]; }; then
      ok=no why="$why; povray exit $prc (the snippet is wrong)"
    fi
    missing=$(sed -n 's|^// expect-debug: ||p' "$scene" |
      while IFS= read -r w; do grep -qF -- "$w" "$name.pov.log" || echo "$w"
      done)
    [ -n "$missing" ] && ok=no why="$why; povray did not print: $missing"
  fi
  rm -f "$name.zr.png"
  zrc=0
  timeout 60 "$zrcube" +I"$scene" +O"$name.zr.png" +W64 +H48 -D +WT1 \
    </dev/null >"$name.zr.log" 2>&1 || zrc=$?
  if [ $refuse = yes ]; then
    [ $zrc -eq 1 ] || { ok=no why="$why; zrcube exit $zrc, not 1"; }
    [ -e "$name.zr.png" ] && { ok=no why="$why; zrcube wrote a picture"; }
    expects=$(sed -n 's|^// expect-error: ||p' "$scene")
  else
    [ $zrc -eq 0 ] || { ok=no why="$why; zrcube exit $zrc"; }
    if [ $zrc -eq 0 ] && [ -e "$name.pov.png" ]; then
      "$imgcmp" "$name.zr.png" "$name.pov.png" --ssim-min 0.95 \
        >"$name.cmp" 2>&1 || { ok=no why="$why; $(cat "$name.cmp")"; }
    fi
    expects=$(sed -n 's|^// expect\(-debug\)\{0,1\}: ||p' "$scene")
  fi
  missing=$(printf '%s\n' "$expects" | while IFS= read -r w; do
    [ -z "$w" ] || grep -qF -- "$w" "$name.zr.log" || echo "$w"
  done)
  [ -n "$missing" ] && { ok=no why="$why; missing: $missing"; }
  if [ $ok = yes ]; then
    echo "$name: ok"
    pass=$((pass + 1))
  else
    echo "$name: FAIL$why"
    sed -n '1,6p' "$name.zr.log"
    fail=$((fail + 1))
  fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
