#!/bin/sh
# bench/write_rows.sh - how long rank 0's PNG write takes a pixel: the
# estimate (WRITE_PIXEL_SECONDS in bin/zrcube.c) by which zr__par_render
# sizes the last bands the other ranks render while rank 0 encodes.
# One rank, no mpirun: +V prints "Write Time" (the encode and the file
# of zr_image_save at the default PNG level); best of REPEAT (3) runs of
# scenes/default.pov and bench/peers.sh's flake, at 2048x1536 and
# 2048x2048, without antialiasing (the write does not depend on it).
#   bench/write_rows.sh [build-dir]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
top=$(dirname "$here")
build=$(cd "${1:-$top/build}" && pwd)
REPEAT=${REPEAT:-3}
. "$here/zrexe.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$here/peers_gen.py" "$tmp" >/dev/null
echo "load: $(cat /proc/loadavg)"
for case in "$top/scenes/default.pov 2048 1536" "$tmp/flake.pov 2048 2048"; do
  set -- $case
  best=
  for rep in $(seq 1 "$REPEAT"); do
    t=$(cd "$(dirname "$1")" && $zrcube "+I$(basename "$1")" "+W$2" "+H$3" \
          -A +WT1 -D +V "+O$tmp/out.png" 2>&1 |
        sed -n 's/.*Write Time:.*(\([0-9.]*\) seconds).*/\1/p')
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc)" = 1 ]; then best=$t; fi
  done
  echo "$(basename "$1") $2x$3: write $best s, $(echo "scale=1; $best * 1000000000 / ($2 * $3)" | bc) ns a pixel"
done
