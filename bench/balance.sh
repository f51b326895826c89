#!/bin/sh
# bench/balance.sh - how evenly interleaved rows share a render whose
# cost is concentrated (issue 15): a glass sphere in one corner of the
# image (bench/scale/glass_corner.pov).  For 1, 2, 4 and 8 ranks (more
# ranks than cores is fine: the figure is CPU seconds, the work each
# rank did, which the machine's load does not change), prints each
# rank's render CPU, the imbalance (busiest over mean) and the
# efficiency it caps (mean over busiest).
#   bench/balance.sh [build-dir] [size]     (size default 1600x1200)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$(dirname "$here")/build}
size=${2:-1600x1200}
w=${size%x*} h=${size#*x}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$here/scale"
echo "glass_corner.pov ${w}x$h, antialiasing +A0.3, 1 thread a rank; load $(cut -d' ' -f1 /proc/loadavg)"
for n in 1 2 4 8; do
  timeout 600 mpirun --bind-to none -n $n "$build/bin/zrcube" \
    glass_corner.pov +W"$w" +H"$h" +A0.3 +WT1 -v +O"$tmp/g$n.png" 2>"$tmp/err"
  [ $n = 1 ] || cmp -s "$tmp/g1.png" "$tmp/g$n.png" ||
    { echo "balance.sh: $n ranks: other bytes" >&2; exit 1; }
  sed -n 's/^zrcube: rank \([0-9]*\): .*cpu s: .* render \([0-9.]*\) exchange.*/\1 \2/p' \
    "$tmp/err" | sort -n | awk -v n=$n '
      { c[$1] = $2; s += $2; if ($2 > m) m = $2 }
      END { printf "%d ranks: render CPU", n
            for (r = 0; r < n; r++) printf " %.3f", c[r]
            printf "; busiest/mean %.3f, efficiency cap %.1f%%\n",
                   m / (s / n), 100 * (s / n) / m }'
done
