#!/bin/sh
# SSIM of zRcube against POV-Ray 3.7 on every scene that uses media: the
# stock examples that mention `media` and the project's scenes/ that do.
# Each scene is rendered at 160x120, no antialiasing, one thread, from
# its own folder (as /work/shared/corpus/compare.py does), and SSIM is
# taken after a 2x2 box filter (skimage, 8-bit RGB).  POV-Ray also
# renders a copy of the scene with 4 times the media samples
# (bench/media_more_samples.py): the SSIM between its two pictures says
# whether POV-Ray's own image is converged.
#
# Usage: bench/media_ssim.sh [ZRCUBE] [OUTDIR]
# Prints one line per scene:
#   scene  zr_vs_povray  povray_vs_povray4x  zr_vs_povray4x  zr_seconds
# POV-Ray's pictures are kept in OUTDIR/ref and reused by later runs
# (MEDIA_POVRAY_AGAIN=1 renders them again); zRcube's go to OUTDIR/zr, or
# OUTDIR/$MEDIA_LABEL to keep runs of two builds apart.  A scene counts
# when the word `media` stands alone in it (hollow1.pov has only
# media_attenuation).  Exits 77 without povray.
set -u
zr=${1:-build/bin/zrcube}
case $zr in /*) ;; *) zr=$(pwd)/$zr ;; esac
out=${2:-bench/out/media}
case $out in /*) ;; *) out=$(pwd)/$out ;; esac
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
tmo=${MEDIA_TIMEOUT:-600}
command -v povray >/dev/null 2>&1 || { echo "media_ssim.sh: no povray" >&2; exit 77; }
zdir=$out/${MEDIA_LABEL:-zr}
mkdir -p "$out/ref" "$zdir"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_media.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT

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

{
    grep -l '\bmedia\b' $(find "$ex" -name '*.pov') 2>/dev/null
    grep -l '\bmedia\b' "$root"/scenes/*.pov 2>/dev/null
} | sort -u > "$tmp/list"

printf '# scene\tzr_vs_povray\tpovray_vs_povray4x\tzr_vs_povray4x\tzr_seconds\n'
while read -r f; do
    dir=$(dirname "$f")
    base=$(basename "$f" .pov)
    case $f in "$ex"/*) name=$(echo "${f#$ex/}" | sed 's|/|_|g; s|\.pov$||') ;;
               *) name=scenes_$base ;; esac
    ref=$out/ref/$name.png
    ref4=$out/ref/$name.4x.png
    if [ ! -s "$ref" ] || [ "${MEDIA_POVRAY_AGAIN:-0}" = 1 ]; then
        (cd "$dir" && timeout "$tmo" povray +I"$f" +O"$ref" +W160 +H120 -D -A \
            +WT1 -GA +L"$inc" </dev/null >/dev/null 2>&1)
    fi
    if [ ! -s "$ref4" ] || [ "${MEDIA_POVRAY_AGAIN:-0}" = 1 ]; then
        # The copy lives in tmp; +L"$dir" finds the scene's own includes.
        /usr/bin/python3 "$here/media_more_samples.py" "$f" "$tmp/s.pov" 4 \
            >/dev/null
        s4=$tmp/s.pov
        (cd "$dir" && timeout "$tmo" povray +I"$s4" +O"$ref4" +W160 +H120 -D -A \
            +WT1 -GA +L"$inc" +L"$dir" </dev/null >/dev/null 2>&1)
    fi
    zout=$zdir/$name.png
    rm -f "$zout"
    t0=$(date +%s.%N)
    (cd "$dir" && timeout "$tmo" "$zr" +I"$f" +O"$zout" +W160 +H120 -D +WT1 \
        </dev/null >/dev/null 2>"$zdir/$name.log")
    t1=$(date +%s.%N)
    printf '%s\t%s\t%s\t%s\t%.1f\n' "${f#$ex/}" "$(ssim "$zout" "$ref")" \
        "$(ssim "$ref4" "$ref")" "$(ssim "$zout" "$ref4")" \
        "$(echo "$t1 - $t0" | bc)"
done < "$tmp/list"
