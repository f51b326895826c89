#!/bin/sh
# normal_stencil_probe.sh [ZRCUBE] - where POV-Ray 3.7 samples a
# pattern around a point to tilt the normal (lib/scene/texture.c,
# slope_corner).  A gradient normal's height jumps from 1 to 0 at a
# plane; a point's normal is disturbed where one of its samples lies
# across the jump.  Scanning across the jump along x, y and z (1210
# pixels over 6 accuracy units) prints, in units of accuracy, where each
# band of equal colour begins: the band around the jump runs from minus
# the largest offset of the samples along the axis to minus the
# smallest.  POV-Ray 3.7.0.10 prints (x: cfg 1 and 4, y: 2 and 5, z: 3
# and 6; some views are mirrored):
#   cfg 1: -3.0225 -0.9425 0.0025 0.4725    x: +0.9428, -0.4714
#   cfg 2: -3.0225 -0.9975 0.3375           y: +1, -1/3
#   cfg 3: -3.0225 -0.8125 0.0025 0.8175    z: +-0.8165
# the corners of a regular tetrahedron with one corner on +y.  With
# ZRCUBE given, its bands are printed below POV-Ray's.
set -u
here=$(cd "$(dirname "$0")" && pwd)
zr=${1:-}
command -v povray >/dev/null || { echo "no povray" >&2; exit 77; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_stencil.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
bands='
import sys
from skimage import io
a = io.imread(sys.argv[1])[1, :, :3].astype(int)
out, prev = [], None
for i in range(a.shape[0]):
    c = tuple(a[i])
    if c != prev:
        out.append("%.4f:%s" % ((-0.0605 + (i + 0.5) * 0.0001) / 0.02,
                                ",".join(map(str, c))))
        prev = c
print(" ".join(out))'
for cfg in 1 2 3 4 5 6; do
  povray +I"$here/normal_stencil_probe.pov" +O"$tmp/p.png" +W1210 +H2 -D -A \
    +WT1 -GA Declare=Cfg=$cfg >/dev/null 2>&1 || exit 1
  echo "cfg $cfg povray: $(/usr/bin/python3 -c "$bands" "$tmp/p.png")"
  if [ -n "$zr" ]; then
    "$zr" +I"$here/normal_stencil_probe.pov" +O"$tmp/z.png" +W1210 +H2 -D \
      +WT1 Declare=Cfg=$cfg >/dev/null 2>&1 || exit 1
    echo "cfg $cfg zrcube: $(/usr/bin/python3 -c "$bands" "$tmp/z.png")"
  fi
done
