#!/bin/sh
# gi_pattern_probe.sh [BUILD...] - radiosity_36.pov without its fog, with
# its radiosity block at count 50, 100, 200 and a converged one (count
# 600, error_bound 0.15, pretrace_end 0.01, nearest_count 10), rendered at
# 160x120 by povray 3.7 (-A +WT1 -GA) and each zRcube build (+WT1);
# prints the mean 8-bit colour of four regions: the back wall
# (columns 28-41, rows 35-59), the middle shadowed pillar (95-109,
# 20-89), the shadowed corridor floor (60-139, 100-117) and the right
# wall (120-134, 40-59).  Used for bench/results/gi-2026-12-04-s19.md.
set -u
ex=/usr/share/doc/povray/examples/radiosity/radiosity_36.pov
[ -f "$ex" ] || { echo "gi_pattern_probe: $ex missing" >&2; exit 77; }
builds=""
for b in "${@:-build}"; do builds="$builds $(cd "$b" && pwd)"; done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gi_pattern.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
mk() { # mk NAME RADIOSITY-ITEMS
  /usr/bin/python3 - "$ex" "$tmp/$1.pov" "$2" <<'PY'
import sys
s = open(sys.argv[1]).read()
i = s.index('fog {'); j = s.index('}', i)
s = s[:i] + s[j + 1:]
i = s.index('radiosity {'); j = s.index('}', i)
open(sys.argv[2], 'w').write(s[:i] + 'radiosity { ' + sys.argv[3] + ' }' + s[j + 1:])
PY
}
base="pretrace_start 0.08 pretrace_end 0.02 error_bound 0.5 recursion_limit 1"
mk c50 "$base count 50"
mk c100 "$base count 100"
mk c200 "$base count 200"
mk hq "pretrace_start 0.08 pretrace_end 0.01 count 600 error_bound 0.15 recursion_limit 1 nearest_count 10"
for v in c50 c100 c200 hq; do
  povray +I"$tmp/$v.pov" +O"$tmp/$v-povray.png" +W160 +H120 -D -A +WT1 -GA \
    >/dev/null 2>&1
  k=0
  for b in $builds; do
    k=$((k + 1))
    LD_LIBRARY_PATH=$b/lib/.libs "$b/bin/.libs/zrcube" +I"$tmp/$v.pov" \
      +O"$tmp/$v-build$k.png" +W160 +H120 -D +WT1 >/dev/null 2>&1
  done
done
k=0; for b in $builds; do k=$((k + 1)); echo "# build$k: $b"; done
/usr/bin/python3 - "$tmp" <<'PY'
import glob, os, sys
from skimage import io
regs = [('wall', (28, 35, 42, 60)), ('pillar', (95, 20, 110, 90)),
        ('floor', (60, 100, 140, 118)), ('rwall', (120, 40, 135, 60))]
print('# picture\t' + '\t'.join(n for n, _ in regs))
for p in sorted(glob.glob(os.path.join(sys.argv[1], '*.png'))):
    a = io.imread(p)[..., :3].astype(float)
    print(os.path.basename(p)[:-4] + '\t' + '\t'.join(
        '%.1f,%.1f,%.1f' % tuple(a[y0:y1, x0:x1].mean(axis=(0, 1)))
        for _, (x0, y0, x1, y1) in regs))
PY
