#!/bin/sh
# Measures two lengths of POV-Ray 3.7's atmospheric media that the
# manual does not give (lib/trace/media.c uses both):
#  - how far a ray that hits nothing crosses them: the background seen
#    through absorbing media of absorption a is exp(-a L), so
#    L = -ln(pixel / background) / a;
#  - how far along a ray a spotlight lights them when the ray never
#    leaves its cone: a camera at the light looks down the beam at a
#    black background through scattering media s with extinction 0, so
#    the pixel is s times that length (a point light does not dim with
#    distance).
# 16-bit PPM with File_Gamma 1 keeps the pixels linear.
# Usage: bench/media_sky.sh
set -u
command -v povray >/dev/null 2>&1 || { echo "media_sky.sh: no povray" >&2; exit 77; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_sky.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
# The last pixel's red, linear.
last_red() {
    tail -c 6 "$1" | od -An -tu1 | awk '{ print ($1 * 256 + $2) / 65535 }'
}
render() {
    (cd "$tmp" && timeout 60 povray +Ip.pov +Op.ppm +W16 +H12 -D -A +WT1 -GA \
        +FP16 File_Gamma=1.0 </dev/null >/dev/null 2>&1)
}
for a in 1e-10 3e-11 1e-11; do
    cat > "$tmp/p.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
background { rgb 1 }
media { absorption $a }
POV
    render
    v=$(last_red "$tmp/p.ppm")
    echo "sky: absorption $a background kept $v length $(awk -v v="$v" -v a="$a" 'BEGIN { printf "%.5g", -log(v) / a }')"
done
for s in 1e-8 3e-8; do
    cat > "$tmp/p.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,0> look_at <0,0,1> angle 10 }
background { rgb 0 }
light_source { <0,0,-1> rgb 1 spotlight point_at <0,0,1> radius 30 falloff 30 }
media { scattering { 1, $s extinction 0 } }
POV
    render
    v=$(last_red "$tmp/p.ppm")
    echo "beam: scattering $s pixel $v length $(awk -v v="$v" -v s="$s" 'BEGIN { printf "%.5g", v / s }')"
done
