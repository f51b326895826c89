#!/bin/sh
# Where POV-Ray 3.7's media integration converges: a box 2 units deep of
# constant absorption 1 and emission 0.4 in front of black, seen along
# its depth, at growing `samples` (method 3).  The exact solution of
# dL/ds = e - a L is e (1 - exp(-a d)) / a = 0.345866; lib/trace/media.c
# computes that at any sample count, POV-Ray approaches it from above
# (0.547 at samples 3, 0.407 at its default 10, 0.350 at 160).  So on
# scenes with emitting or lit absorbing media, POV-Ray's default picture
# is brighter than its converged one, and zRcube's is the converged one.
# 16-bit PPM with File_Gamma 1 keeps the pixel linear.
# Usage: bench/media_converge.sh
set -u
command -v povray >/dev/null 2>&1 || { echo "media_converge.sh: no povray" >&2; exit 77; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_converge.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
printf '# samples\tpovray\texact\n'
for n in 3 10 40 160 640; do
    cat > "$tmp/p.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-10> look_at 0 right x up y }
background { rgb 0 }
box { <-1,-1,-1>, <1,1,1> pigment { rgbt 1 } hollow
  interior { media { absorption 1 emission 0.4 samples $n } } }
POV
    (cd "$tmp" && timeout 120 povray +Ip.pov +Op.ppm +W8 +H8 -D -A +WT1 -GA \
        +FP16 File_Gamma=1.0 </dev/null >/dev/null 2>&1)
    v=$(tail -c 6 "$tmp/p.ppm" | od -An -tu1 | awk '{ print ($1 * 256 + $2) / 65535 }')
    printf '%d\t%s\t%s\n' "$n" "$v" \
        "$(awk 'BEGIN { printf "%.6f", 0.4 * (1 - exp(-2)) }')"
done
