#!/bin/sh
# test_aa_method.sh - +AM2, POV-Ray's adaptive recursive antialiasing
# (lib/trace/render.c): with povray installed, tests/am2_check.pov at
# +A0.3 +AM2 +R3 -J matches povray's picture (SSIM >= 0.99, where +AM1
# against povray's +AM2 scores 0.93); without it, +AM2 must still
# differ from +AM1 and +AM3 must be refused with a message.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/am2_check.pov" . || exit 99
fail=0
aa="+W160 +H120 -D +A0.3 -J +R3 +WT1"
for m in 1 2; do
  timeout 120 "$zrcube" +Iam2_check.pov +Oz$m.png $aa +AM$m >z$m.log 2>&1 ||
    { echo "zrcube +AM$m failed:" >&2; cat z$m.log >&2; exit 1; }
done
if cmp -s z1.png z2.png; then
  echo "FAIL: +AM2 renders the same bytes as +AM1"
  fail=1
else
  echo "ok: +AM2 differs from +AM1"
fi
if "$zrcube" +Iam2_check.pov +Oz3.png $aa +AM3 >z3.log 2>&1; then
  echo "FAIL: +AM3 was accepted"
  fail=1
elif grep -q "sampling method must be 1 or 2" z3.log; then
  echo "ok: +AM3 refused: $(head -1 z3.log)"
else
  echo "FAIL: +AM3: $(head -1 z3.log)"
  fail=1
fi
if command -v povray >/dev/null 2>&1; then
  timeout 120 povray +Iam2_check.pov +Opov.png $aa +AM2 -GA \
    </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
  if out=$("$imgcmp" z2.png pov.png --ssim-min 0.99); then
    echo "ok: +AM2 against povray's +AM2: $out"
  else
    echo "FAIL: +AM2 against povray's +AM2: $out"
    fail=1
  fi
else
  echo "no povray: the picture comparison is skipped"
fi
exit $fail
