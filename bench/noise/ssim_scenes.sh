#!/bin/sh
# ssim_scenes.sh - renders the stock scenes the noise work touches with
# POV-Ray and with two zRcube builds (before and after a change) at
# 160x120, no antialiasing, one thread, and prints the SSIM of each
# against POV-Ray (8-bit RGB after a 2x2 box filter, as
# ../shared/corpus/compare.py computes it).
# Usage: bench/noise/ssim_scenes.sh BEFORE_ZRCUBE AFTER_ZRCUBE [SCENE...]
# (scene paths relative to the stock examples folder; by default the
# woods, stones, skies, landscape and a sample using noise patterns).
set -u
before=$1 after=$2
shift 2
EX=${EXAMPLES:-/usr/share/doc/povray/examples}
INC=${POVRAY_INCLUDE:-/usr/share/povray-3.7/include}
OUT=${OUT:-/tmp/zr-noise-ssim}
mkdir -p "$OUT"
if [ $# -eq 0 ]; then
  set -- $(cd "$EX" && ls incdemo/woods/*.pov incdemo/stones/*.pov \
    textures/pigments/skies/s_cloud*.pov advanced/landscape.pov \
    textures/patterns/agate.pov textures/patterns/bozo.pov \
    textures/patterns/granite.pov textures/patterns/crackle*.pov \
    textures/patterns/spotted.pov textures/patterns/bumps.pov \
    textures/patterns/dents.pov textures/patterns/wrinkles.pov \
    textures/noise_generator.pov textures/pigments/crack1.pov \
    objects/csg/granite.pov templates/Basic_Scenes/Sea_blue_sky.pov \
    templates/Basic_Scenes/Rainy_S_Cloud4.pov interior/skysph2.pov \
    textures/pigments/pigment.pov 2>/dev/null)
fi
ssim() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
import numpy as np
from skimage.io import imread
from skimage.metrics import structural_similarity
def load(p):
    a = imread(p)
    if a.ndim == 2:
        a = np.stack([a] * 3, 2)
    a = a[..., :3].astype(np.float64)
    if a.max() > 255:
        a = a / 257.0
    h, w = a.shape[0] // 2 * 2, a.shape[1] // 2 * 2
    a = a[:h, :w]
    return (a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4
try:
    print("%.4f" % structural_similarity(load(sys.argv[1]), load(sys.argv[2]),
                                         channel_axis=2, data_range=255.0))
except Exception:
    print("-")
PY
}
printf '# scene\tbefore\tafter\n'
for s in "$@"; do
  name=$(echo "$s" | tr / _ | sed 's/\.pov$//')
  dir=$EX/$(dirname "$s") base=$(basename "$s")
  ref=$OUT/$name.ref.png
  [ -f "$ref" ] || (cd "$dir" && timeout 60 povray +I"$base" +O"$ref" \
    +W160 +H120 -D -A +WT1 -GA +L"$INC" >/dev/null 2>&1)
  (cd "$dir" && timeout 60 "$before" +I"$base" +O"$OUT/$name.before.png" \
    +W160 +H120 -D +WT1 +L"$INC" >/dev/null 2>&1)
  (cd "$dir" && timeout 60 "$after" +I"$base" +O"$OUT/$name.after.png" \
    +W160 +H120 -D +WT1 +L"$INC" >/dev/null 2>&1)
  b=- a=-
  [ -f "$ref" ] && [ -f "$OUT/$name.before.png" ] && \
    b=$(ssim "$OUT/$name.before.png" "$ref")
  [ -f "$ref" ] && [ -f "$OUT/$name.after.png" ] && \
    a=$(ssim "$OUT/$name.after.png" "$ref")
  printf '%s\t%s\t%s\n' "$s" "$b" "$a"
done
