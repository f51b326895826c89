#!/bin/sh
# normal_probe.sh [ZRCUBE] - measure how far POV-Ray 3.7 tilts a shading
# normal for each normal pattern, bump size and scale, beside zRcube.
#
# Each case renders normal_probe.pov (a plane lit by three coloured
# parallel lights, 128x128, orthographic, 16-bit PNG) with POV-Ray and
# with zRcube, and normal_probe.py reads the normals back.  The gains in
# lib/scene/texture.c (tilt_gain) come from these lines: gradient's
# median tilt at bump size A is 0.13333 A; for ripples and waves the
# gain is POV-Ray's tilt_rms over zRcube's with
# gain 1 at bump size 0.1 (small tilts, where the read-back is linear).
# bumps, dents and wrinkles: see bump_fit.py.  Run from anywhere; needs povray and /usr/bin/python3 (numpy).
set -u
here=$(cd "$(dirname "$0")" && pwd)
zr=${1:-$here/../../build/bin/zrcube}
case $zr in /*) ;; *) zr=$(pwd)/$zr ;; esac
command -v povray >/dev/null || { echo "normal_probe: no povray" >&2; exit 77; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_nprobe.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
names="gradient bumps ripples waves wrinkles dents granite gradient+slope_map gradient<1,0,1> gradient<1,0,-1> gradient_z"
# probe PAT AMT SCALE SIDE [EXTRA-FILE]
probe() {
    { echo "#declare PAT=$1; #declare AMT=$2; #declare SC=$3;"
      echo "#declare SIDE=$4; #declare EXTRA=\"${5:-}\";"
      cat "$here/normal_probe.pov"; } > "$tmp/p.pov"
    pv=$( cd "$tmp" && timeout 60 povray +Ip.pov +Opov.png +W128 +H128 -D -A \
          +WT1 -GA +FN16 >/dev/null 2>&1 &&
          /usr/bin/python3 "$here/normal_probe.py" pov.png )
    zv=$( cd "$tmp" && timeout 60 "$zr" +Ip.pov +Ozr.png +W128 +H128 -D +WT1 \
          +FN16 -q >/dev/null 2>&1 &&
          /usr/bin/python3 "$here/normal_probe.py" zr.png )
    n=$(echo $names | cut -d' ' -f$(($1 + 1)))
    printf '%-10s A=%-4s scale=%-4s side=%-2s %s\n' "$n" "$2" "$3" "$4" "${5:-}"
    printf '    povray %s\n    zrcube %s\n' "$pv" "$zv"
}
for a in 0.5 1 4; do probe 0 $a 0.5 1; done
for sc in 0.01 10; do probe 0 1 $sc 1; done
probe 0 1 0.5 -1
echo "accuracy 0.005" > "$tmp/acc.inc"; probe 0 1 0.5 1 acc.inc
probe 7 1 0.5 1
probe 8 4 0.5 1; probe 8 4 0.5 -1
for pat in 1 2 3 4 5 6; do
    for sc in 0.1 0.3 1; do probe $pat 0.5 $sc 1; done
    probe $pat 0.1 0.3 1
done
