#!/bin/sh
# Black-box measurements of finish { metallic } and reflection { metallic }
# (issue 17): how far a highlight or a reflection takes the surface's
# colour, by angle, as POV-Ray 3.7 or zrcube renders it.
#
# Usage: bench/metallic_probe.sh [RENDERER]      (default: povray)
#
# A plane of pigment rgb <1, 0.25, 0> is seen square on by an
# orthographic camera (so every pixel has the same angles), in linear
# light (assumed_gamma 1; POV-Ray writes a 16-bit PPM with
# File_Gamma=1.0, zrcube a PFM).  With diffuse and ambient 0 a pixel is
# the highlight h times the light times the tint T = 1 + k (C - 1), so
# from its red R = h, green G and blue B the tint's strength is
#   k_G = (1 - G / R) / 0.75   and   k_B = 1 - B / R,
# the same number when the tint is linear in the colour.  Prints
#   CASE light_deg view_deg metallic  R G B  k_G k_B
# Cases: "spec" a specular 1 roughness 1 highlight with the light at an
# angle to the normal and the view along it; "view" the plane tilted,
# the light along the normal and the view at the angle; "phong" phong 1
# phong_size 1 as spec; "refl" reflection { 1 metallic M } of a white
# background, no light, the view at the angle.
set -u
renderer=${1:-povray}
case $renderer in */*) renderer=$(cd "$(dirname "$renderer")" &&
    pwd)/$(basename "$renderer") ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_metallic_probe.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT

# scene LIGHT_DEG VIEW_DEG FINISH: the plane tilted by VIEW_DEG about x,
# a parallel light at LIGHT_DEG from its normal (in the plane of the
# tilt, on the other side), or no light when LIGHT_DEG is "none".
scene() {
    echo '#version 3.7;'
    echo 'global_settings { assumed_gamma 1 max_trace_level 5 }'
    echo 'camera { orthographic location <0, 0, 5> look_at 0'
    echo '  right 0.01 * x up 0.01 * y }'
    echo 'background { rgb 1 }'
    if [ "$1" != none ]; then
        echo "#declare N = vrotate(z, <-$2, 0, 0>);"
        echo "#declare L = vaxis_rotate(N, x, -$1);"
        echo 'light_source { 10 * L rgb 1 parallel point_at 0 }'
    fi
    echo "plane { z, 0 rotate <-$2, 0, 0>"
    echo '  pigment { rgb <1, 0.25, 0> }'
    echo "  finish { ambient 0 diffuse 0 $3 } }"
}

# Prints R G B of the middle of a linear render.
render() {
    case $renderer in
    *povray*)
        ( cd "$tmp" && timeout 60 "$renderer" +Is.pov +Oo.ppm +W4 +H4 -D \
            -A +FP16 File_Gamma=1.0 >/dev/null 2>&1 )
        img=$tmp/o.ppm ;;
    *)
        ( cd "$tmp" && timeout 60 "$renderer" +Is.pov +Oo.pfm +W4 +H4 -D \
            -q >/dev/null 2>&1 )
        img=$tmp/o.pfm ;;
    esac
    /usr/bin/python3 - "$img" <<'EOF'
import struct, sys
data = open(sys.argv[1], 'rb').read()
def fields(data, n):
    out, pos = [], 0
    while len(out) < n:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b'#':
            pos = data.index(b'\n', pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        out.append(data[pos:end].decode())
        pos = end
    return out, pos + 1
if data[:2] == b'PF':
    (magic, w, h, scale), pos = fields(data, 4)
    w, h, scale = int(w), int(h), float(scale)
    fmt = '<' if scale < 0 else '>'
    px = struct.unpack(fmt + '%df' % (3 * w * h), data[pos:pos + 12 * w * h])
    row, col = h // 2, w // 2  # PFM rows are stored bottom first
    i = 3 * ((h - 1 - row) * w + col)
else:
    (magic, w, h, maxval), pos = fields(data, 4)
    w, h, maxval = int(w), int(h), int(maxval)
    n = 3 * w * h
    px = struct.unpack('>%dH' % n, data[pos:pos + 2 * n])
    px = [v / maxval for v in px]
    i = 3 * ((h // 2) * w + w // 2)
r, g, b = px[i:i + 3]
kg = (1 - g / r) / 0.75 if r > 0 else float('nan')
kb = 1 - b / r if r > 0 else float('nan')
print('%.5f %.5f %.5f  %.5f %.5f' % (r, g, b, kg, kb))
EOF
}

probe() {
    scene "$2" "$3" "$5" > "$tmp/s.pov"
    echo "$1 $2 $3 $4  $(render)"
}

for m in 1 0.5; do
    for a in 0 20 40 60 70 80 85 88; do
        probe spec "$a" 0 "$m" "specular 1 roughness 1 metallic $m"
    done
done
for a in 0 20 40 60 70 80 85; do
    probe view 0 "$a" 1 "specular 1 roughness 1 metallic 1"
done
for a in 0 30 60 80; do
    probe phong "$a" 0 1 "phong 1 phong_size 1 metallic 1"
done
for a in 0 5 10 15 20 25 30 35 40 45 50 55 60 65 70 72.5 75 77.5 80 \
    82.5 85 86 87 88 89 89.5; do
    probe refl none "$a" 1 "reflection { 1 metallic 1 }"
done
for a in 0 40 80 88; do
    probe refl none "$a" 0.5 "reflection { 1 metallic 0.5 }"
done
