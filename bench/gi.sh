#!/bin/sh
# bench/gi.sh - the stock POV-Ray scenes with a radiosity block (and
# scenes/sky_outdoor.pov), rendered by povray and zrcube at 160x120, no
# antialiasing, one thread, in the same run: wall seconds of each, their
# ratio, and the SSIM of zrcube's picture against povray's (after a 2x2
# box filter, as ../shared/corpus/compare.py computes it).  Times are
# CPU seconds (user + system, /usr/bin/time), which a machine shared
# with other jobs changes less than wall seconds; the wall seconds of
# both are printed too.  Issue 11's
# target: SSIM >= 0.90 at <= 1.5x POV-Ray's time.
#
#   bench/gi.sh [ZRCUBE [OUTDIR [TIMEOUT]]]
#
# ZRCUBE defaults to build/bin/zrcube; TIMEOUT (seconds per render) to
# 120.  Needs povray and /usr/bin/python3 with numpy and skimage.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
zr=$(cd "$(dirname "${1:-$here/build/bin/zrcube}")" && pwd)/$(basename "${1:-zrcube}")
out=${2:-/tmp/zrcube-gi-bench}
limit=${3:-120}
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
command -v povray >/dev/null || { echo "bench/gi.sh: no povray" >&2; exit 77; }
mkdir -p "$out"
ssim() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
import numpy as np
from skimage import io as skio
from skimage.metrics import structural_similarity
def load(p):
    a = skio.imread(p)
    if a.ndim == 2:
        a = np.stack([a] * 3, -1)
    a = a[..., :3].astype(np.float64)
    if a.max() > 255:
        a = a / 257.0
    h, w = a.shape[0] // 2 * 2, a.shape[1] // 2 * 2
    a = a[:h, :w]
    return a.reshape(h // 2, 2, w // 2, 2, 3).mean(axis=(1, 3))
a, b = load(sys.argv[1]), load(sys.argv[2])
print('%.4f' % structural_similarity(a, b, channel_axis=2, data_range=255))
PY
}
now() { date +%s.%N; }
# /usr/bin/time puts "Command exited with non-zero status N" first when
# the render fails or times out: the times are the last line.
cpu() { tail -n 1 "$1" | awk '{ printf "%.2f", $1 + $2 }'; }
printf 'scene\tpovray_cpu\tzrcube_cpu\tratio\tssim\tmodel\tpovray_wall\tzrcube_wall\n'
scenes=${GI_SCENES:-"radiosity/cornell.pov radiosity/patio-radio_36.pov
radiosity/patio-radio_37.pov radiosity/radiosity_36.pov
radiosity/radiosity_37.pov radiosity/radiosity2.pov radiosity/radiosity3.pov
radiosity/rad_def_test_36.pov radiosity/rad_def_test_37.pov
advanced/blocks/stackerday.pov advanced/blocks/stackernight.pov
advanced/object_pattern.pov advanced/diffuse_back.pov
advanced/balcony/balcony.pov advanced/benchmark/benchmark.pov
gamma/gamma_showcase.pov camera/mesh_camera/baking_demo.pov
animations/raddem/raddem.pov @sky_outdoor.pov"}
for s in $scenes; do
  case $s in
  @*) dir=$here/scenes; file=${s#@} ;;
  *) dir=$ex/$(dirname "$s"); file=$(basename "$s") ;;
  esac
  name=$(echo "$s" | tr '/@' '__' | sed 's/\.pov$//')
  cd "$dir" || continue
  t0=$(now)
  /usr/bin/time -f '%U %S' -o "$out/$name.pov.time" \
    timeout "$limit" povray +I"$file" +O"$out/$name.pov.png" +W160 +H120 -D \
    -A +WT1 -GA +L"$inc" >/dev/null 2>&1
  prc=$?
  t1=$(now)
  /usr/bin/time -f '%U %S' -o "$out/$name.zr.time" \
    timeout "$limit" "$zr" +I"$file" +O"$out/$name.zr.png" +W160 +H120 -D \
    +WT1 +V >"$out/$name.log" 2>&1
  zrc=$?
  t2=$(now)
  model=$(sed -n 's/^zrcube: global illumination: \([a-z]*\).*/\1/p' \
    "$out/$name.log")
  pw=$(echo "$t1 - $t0" | bc); zw=$(echo "$t2 - $t1" | bc)
  ps=$(cpu "$out/$name.pov.time"); zs=$(cpu "$out/$name.zr.time")
  ratio=$(echo "scale=2; $zs / $ps" | bc)
  if [ $prc -eq 0 ] && [ $zrc -eq 0 ]; then
    q=$(ssim "$out/$name.pov.png" "$out/$name.zr.png")
  else
    q="- (povray $prc, zrcube $zrc)"
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%.2f\t%.2f\n' "$s" "$ps" "$zs" \
    "$ratio" "$q" "${model:-?}" "$pw" "$zw"
done
