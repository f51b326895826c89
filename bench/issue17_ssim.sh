#!/bin/sh
# SSIM of zRcube against POV-Ray 3.7 on the stock scenes that use what
# issue 17 rewrote in warp.c, obj_julia.c and shade.c (metallic): every
# stock example that writes `warp`, `julia_fractal` or `metallic`.
#
# Usage: bench/issue17_ssim.sh [ZRCUBE] [OUTDIR]
#
# Each scene is rendered at 160x120, no antialiasing, one thread, from
# its own folder, by POV-Ray (kept in OUTDIR/ref and reused; set
# SSIM_POVRAY_AGAIN=1 to render them again) and by zRcube (OUTDIR/zr);
# SSIM is computed on 8-bit RGB after a 2x2 box filter with skimage,
# as ../shared/corpus/compare.py does.  Prints one line per scene:
#   scene  ssim-or-reason  zrcube-seconds
# Each render may take SSIM_TIMEOUT seconds (default 120).
set -u
zr=${1:-build/bin/zrcube}
case $zr in /*) ;; *) zr=$(pwd)/$zr ;; esac
out=${2:-bench/out/issue17}
case $out in /*) ;; *) out=$(pwd)/$out ;; esac
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
limit=${SSIM_TIMEOUT:-120}
if [ ! -d "$ex" ] || ! command -v povray >/dev/null 2>&1; then
    echo "issue17_ssim.sh: needs povray and povray-examples" >&2
    exit 77
fi
mkdir -p "$out/ref" "$out/zr"
scenes=$( cd "$ex" && grep -rlw -e warp -e julia_fractal -e metallic \
    --include='*.pov' . | sed 's|^\./||' | sort )
ssim() {
    /usr/bin/python3 - "$1" "$2" <<'EOF'
import sys
import numpy as np
from skimage import io
from skimage.metrics import structural_similarity
def rgb8(path):
    a = np.asarray(io.imread(path))
    if a.dtype == np.uint16:
        a = (a / 257.0).round()
    if a.ndim == 2:
        a = np.stack([a] * 3, axis=-1)
    return a[..., :3].astype(np.float64)
def box2(a):
    h, w = a.shape[0] // 2 * 2, a.shape[1] // 2 * 2
    a = a[:h, :w]
    return (a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4
x, y = rgb8(sys.argv[1]), rgb8(sys.argv[2])
if x.shape != y.shape:
    print('size')
else:
    print('%.4f' % structural_similarity(box2(x), box2(y), channel_axis=2,
                                         data_range=255.0))
EOF
}
printf '# scene\tssim\tzrcube_s\n'
for rel in $scenes; do
    dir=$ex/$(dirname "$rel")
    name=$(echo "$rel" | sed 's|/|_|g; s|\.pov$||')
    ref=$out/ref/$name.png
    img=$out/zr/$name.png
    if [ ! -s "$ref" ] || [ "${SSIM_POVRAY_AGAIN:-0}" = 1 ]; then
        ( cd "$dir" && timeout "$limit" povray +I"$ex/$rel" +O"$ref" \
            +W160 +H120 -D -A +WT1 -GA +L"$inc" +L"$dir" \
            >/dev/null 2>&1 ) || rm -f "$ref"
    fi
    if [ ! -s "$ref" ]; then
        printf '%s\tno-povray-image\t-\n' "$rel"
        continue
    fi
    rm -f "$img"
    t0=$(date +%s.%N)
    ( cd "$dir" && timeout "$limit" "$zr" +I"$ex/$rel" +O"$img" \
        +W160 +H120 -D +WT1 +L"$inc" +L"$dir" >/dev/null 2>&1 )
    rc=$?
    t1=$(date +%s.%N)
    secs=$(awk "BEGIN { printf \"%.1f\", $t1 - $t0 }")
    if [ $rc -ne 0 ] || [ ! -s "$img" ]; then
        printf '%s\texit-%s\t%s\n' "$rel" "$rc" "$secs"
        continue
    fi
    printf '%s\t%s\t%s\n' "$rel" "$(ssim "$img" "$ref")" "$secs"
done
