#!/bin/sh
# Measures the scale of POV-Ray 3.7's media phase functions, which the
# manual gives only as plots ("Scattering"): lib/trace/media.c takes its
# normalisation constants from what this prints.
#
# Scene: the camera looks (orthographic, along +z) through a hollow box
# 1 unit deep holding scattering media of colour s (0.8 / shape, below) with extinction
# 0, so no light is lost on the way in or out and the medium is the same
# everywhere: every quadrature of the ray is exact and a pixel is
#     s * depth * L * p(cos)
# with L the light's colour (1) and p the phase function for cos, the
# cosine between the direction toward the parallel light and the ray's.
# The background is black; assumed_gamma 1, File_Gamma 1 and 16-bit PPM
# output keep the value linear and precise to 2e-5.
#
# Prints, per scattering type and cos, the measured p and p divided by
# the shape written in lib/trace/media.c (from the literature): a
# constant quotient confirms the shape, and the quotient is the scale.
#   type 1 isotropic        1
#   type 2 Mie hazy         1 + 9 ((1 + cos) / 2)^8
#   type 3 Mie murky        1 + 50 ((1 + cos) / 2)^32
#   type 4 Rayleigh         1 + cos^2
#   type 5 Henyey-Greenstein (1 - g^2) / (1 + g^2 - 2 g cos)^1.5, g 0.5
# Usage: bench/media_phase.sh [ZRCUBE]   (also measures zRcube when given)
set -u
command -v povray >/dev/null 2>&1 || { echo "media_phase.sh: no povray" >&2; exit 77; }
zr=${1:-}
case $zr in ''|/*) ;; *) zr=$(pwd)/$zr ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_phase.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
printf '# renderer\ttype\tcos\tp_measured\tp/shape\n'
{
for renderer in povray ${zr:+zrcube}; do
for type in 1 2 3 4 5; do
for cos in -1 -0.5 0 0.5 0.9 1; do
    ecc=; [ "$type" = 5 ] && ecc="eccentricity 0.5"
    # s = 0.8 / shape keeps every pixel between 0.4 and 1 (precise, not
    # clipped) whatever the scale turns out to be (up to 1.25).
    s=$(/usr/bin/python3 -c "
c, g = $cos, 0.5
print(0.8 / {1: 1.0, 2: 1 + 9 * ((1 + c) / 2) ** 8, 3: 1 + 50 * ((1 + c) / 2) ** 32,
             4: 1 + c * c, 5: (1 - g * g) / (1 + g * g - 2 * g * c) ** 1.5}[$type])")
    cat > "$tmp/p.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-5> direction z right x up y }
background { rgb 0 }
#declare C = $cos;
#declare S = sqrt(max(0, 1 - C*C));
// Direction toward the light: cos with +z (the ray), sin along +x.
light_source { <S, 0, C> * 1000 rgb 1 parallel point_at <0,0,0> }
box { <-10,-10,-0.5>, <10,10,0.5>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 specular 0 }
  hollow no_shadow
  interior { media { scattering { $type, $s $ecc extinction 0 }
    method 3 samples 5, 5 intervals 1 } } }
POV
    if [ "$renderer" = povray ]; then
        (cd "$tmp" && timeout 60 povray +Ip.pov +Op.ppm +W8 +H8 -D -A +WT1 -GA \
            +FP16 File_Gamma=1.0 </dev/null >/dev/null 2>&1)
    else
        # zRcube writes linear floats to a PFM file.
        (cd "$tmp" && timeout 60 "$zr" +Ip.pov +Op.pfm +W8 +H8 -D +WT1 \
            </dev/null >/dev/null 2>&1 && mv p.pfm p.ppm)
    fi
    [ -s "$tmp/p.ppm" ] || { echo "$renderer failed on type $type" >&2; continue; }
    /usr/bin/python3 - "$tmp/p.ppm" "$type" "$cos" "$renderer" "$s" <<'PY'
import sys
import numpy as np
data = open(sys.argv[1], 'rb').read()
pfm = data[:2] == b'PF'
fields, i = [], 2
while len(fields) < 3:  # width, height, maxval; '#' starts a comment
    while data[i:i + 1].isspace():
        i += 1
    if data[i:i + 1] == b'#':
        i = data.index(b'\n', i)
        continue
    j = i
    while not data[j:j + 1].isspace():
        j += 1
    fields.append(float(data[i:j]))
    i = j
w, h, maxval = int(fields[0]), int(fields[1]), fields[2]
raw = data[i + 1:]
if pfm:
    a = np.frombuffer(raw, dtype='<f4' if maxval < 0 else '>f4',
                      count=w * h * 3).astype(np.float64)
else:
    a = np.frombuffer(raw, dtype='>u2' if maxval > 255 else 'u1',
                      count=w * h * 3).astype(np.float64) / maxval
a = a.reshape(h, w, 3)
t, c = int(sys.argv[2]), float(sys.argv[3])
p = a[..., 0].mean() / (float(sys.argv[5]) * 1.0)
g = 0.5
shape = {1: 1.0, 2: 1 + 9 * ((1 + c) / 2) ** 8, 3: 1 + 50 * ((1 + c) / 2) ** 32,
         4: 1 + c * c, 5: (1 - g * g) / (1 + g * g - 2 * g * c) ** 1.5}[t]
print('%s\t%d\t%g\t%.6f\t%.6f' % (sys.argv[4], t, c, p, p / shape))
PY
    rm -f "$tmp/p.ppm"
done
done
done
} | tee "$tmp/all"
# The scale of each type: the mean quotient and its spread.
/usr/bin/python3 - "$tmp/all" <<'PY'
import sys
rows = {}
for line in open(sys.argv[1]):
    f = line.split()
    rows.setdefault((f[0], f[1]), []).append(float(f[4]))
for (r, t), q in sorted(rows.items()):
    print('# %s type %s scale %.5f (min %.6f, max %.6f)'
          % (r, t, sum(q) / len(q), min(q), max(q)))
PY
