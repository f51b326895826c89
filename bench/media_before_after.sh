#!/bin/sh
# SSIM against POV-Ray 3.7's default renders of the stock media scenes,
# for two zrcube binaries (before and after a change), 160x120, no AA,
# one thread, SSIM after a 2x2 box filter (as ../shared/corpus/compare.py).
#
# Usage: bench/media_before_after.sh BEFORE AFTER [OUTDIR]
#   BEFORE, AFTER: zrcube commands (words split on blanks, so "env
#   LD_LIBRARY_PATH=/tmp/old /tmp/old/zrcube" works; absolute paths).
# POV-Ray's pictures are kept in OUTDIR/ref (default bench/out/media_ba)
# and reused.  Prints "scene before after" a line
# (bench/results/media-ssim-2026-12-02-fin.tsv).
set -u
before=$1
after=$2
out=${3:-bench/out/media_ba}
mkdir -p "$out/ref" "$out/before" "$out/after"
out=$(cd "$out" && pwd)
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
command -v povray >/dev/null 2>&1 || { echo "no povray" >&2; exit 77; }
scenes=$(cd "$ex" && grep -rlw media --include='*.pov' . | sed 's|^\./||' |
         grep -v allpatterns | sort)
ssim() {
    /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
import numpy as np
from skimage import io
from skimage.metrics import structural_similarity
def load(p):
    a = np.asarray(io.imread(p))
    if a.dtype == np.uint16:
        a = (a / 257.0).round()
    a = a.astype(np.float64)
    if a.ndim == 2:
        a = np.stack([a] * 3, axis=-1)
    return a[..., :3]
def box2(a):
    h, w = a.shape[0] // 2 * 2, a.shape[1] // 2 * 2
    a = a[:h, :w]
    return (a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4
try:
    a, b = load(sys.argv[1]), load(sys.argv[2])
    print('%.4f' % structural_similarity(box2(a), box2(b), channel_axis=2,
                                         data_range=255.0))
except Exception:
    print('-')
PY
}
printf '# scene\tbefore\tafter\n'
for rel in $scenes; do
    dir=$ex/$(dirname "$rel")
    name=$(echo "$rel" | sed 's|/|_|g; s|\.pov$||')
    [ -s "$out/ref/$name.png" ] ||
        (cd "$dir" && timeout 600 povray +I"$ex/$rel" +O"$out/ref/$name.png" \
            +W160 +H120 -D -A +WT1 -GA +L"$inc" </dev/null >/dev/null 2>&1)
    for which in before after; do
        eval "bin=\$$which"
        (cd "$dir" && timeout 600 $bin +I"$ex/$rel" \
            +O"$out/$which/$name.png" +W160 +H120 -D +WT1 -q \
            </dev/null >/dev/null 2>&1)
    done
    printf '%s\t%s\t%s\n' "$rel" \
        "$(ssim "$out/ref/$name.png" "$out/before/$name.png")" \
        "$(ssim "$out/ref/$name.png" "$out/after/$name.png")"
done
