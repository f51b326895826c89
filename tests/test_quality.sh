#!/bin/sh
# test_quality.sh - +Q0..11 as POV-Ray 3.7 renders them (reference
# 3.2.8.3), measured: tests/quality/quality.pov (an area light, a
# reflective plane, a glass and a mirror sphere) rendered by povray and
# zrcube at each quality, 160x120, no antialiasing, one thread, compared
# with SSIM after a 2x2 box filter (as /work/shared/corpus/compare.py).
# Prints each SSIM, and the SSIM of zrcube's +Q9 picture against
# povray's picture at the lower quality, to show the quality changed
# the picture the way povray's did.  Then tests/quality/quick.pov at
# +Q0, +Q1, +Q2, +Q5 and +Q6: quick_color up to +Q5, and +Q0/+Q1's
# unlit colours (SSIM 0.99 at least; 1.0000 measured).  Skipped (77)
# without povray or python3 with numpy and skimage.
set -u
TEST_NAME=test_quality
. "$(dirname "$0")/cli_env.sh"
POVRAY=${POVRAY:-povray}
command -v "$POVRAY" >/dev/null 2>&1 || { echo "no povray: skipped"; exit 77; }
PY=/usr/bin/python3
"$PY" -c 'import numpy, skimage' 2>/dev/null || { echo "no skimage: skipped"; exit 77; }
cp "${ZR_SRCDIR:-$(dirname "$0")/..}/tests/quality/quality.pov" \
  "${ZR_SRCDIR:-$(dirname "$0")/..}/tests/quality/quick.pov" "$work/" || exit 99
cd "$work" || exit 99
failures=0
for q in 3 4 5 7 8 9; do
  timeout 120 "$POVRAY" +Iquality.pov "+Opov$q.png" +W160 +H120 -D -A +WT1 \
    -GA "+Q$q" >/dev/null 2>&1 || { echo "povray +Q$q failed" >&2; exit 99; }
  timeout 120 "$ZRCUBE" quality.pov "+Ozr$q.png" +W160 +H120 -D +WT1 \
    "+Q$q" 2>"zr$q.err" || { echo "FAIL: zrcube +Q$q" >&2; failures=$((failures + 1)); }
done
for q in 0 1 2 5 6; do
  timeout 120 "$POVRAY" +Iquick.pov "+Opovq$q.png" +W160 +H120 -D -A +WT1 \
    -GA "+Q$q" >/dev/null 2>&1 || { echo "povray quick +Q$q failed" >&2; exit 99; }
  timeout 120 "$ZRCUBE" quick.pov "+Ozrq$q.png" +W160 +H120 -D +WT1 \
    "+Q$q" 2>"zrq$q.err" || { echo "FAIL: zrcube quick +Q$q" >&2; failures=$((failures + 1)); }
done
"$PY" - <<'PY' || failures=$((failures + 1))
import numpy as np
from skimage import io
from skimage.metrics import structural_similarity
def load(p):
    a = io.imread(p)[:, :, :3].astype(np.float64)
    h, w = a.shape[0] // 2 * 2, a.shape[1] // 2 * 2
    a = a[:h, :w]
    return (a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4
def ssim(a, b):
    return structural_similarity(load(a), load(b), channel_axis=2,
                                 data_range=255.0)
bad = 0
for q in (3, 4, 5, 7, 8):
    same = ssim('zr%d.png' % q, 'pov%d.png' % q)
    full = ssim('zr9.png', 'pov%d.png' % q)
    print('Q%d: ssim %.4f (zrcube +Q9 against povray +Q%d: %.4f)' % (q, same, q, full))
    # The lower quality must be at least as close to povray's as the
    # full one (strictly closer where povray's picture changed).
    if not (same >= full and same > 0.9):
        print('FAIL: +Q%d does not follow povray' % q)
        bad += 1
print('Q9: ssim %.4f' % ssim('zr9.png', 'pov9.png'))
for q in (0, 1, 2, 5, 6):
    same = ssim('zrq%d.png' % q, 'povq%d.png' % q)
    print('quick.pov Q%d: ssim %.4f' % (q, same))
    if not same >= 0.99:
        print('FAIL: quick.pov +Q%d does not follow povray' % q)
        bad += 1
raise SystemExit(1 if bad else 0)
PY
[ "$failures" -eq 0 ] || exit 1
exit 0
