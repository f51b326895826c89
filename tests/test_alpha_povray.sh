#!/bin/sh
# test_alpha_povray.sh - +UA against povray 3.7 +UA (the measurements
# behind lib/trace/atmosphere.c zr__sky_clear and the +UA shares in
# lib/trace/shade.c): scenes rendered by both at 64x48, one thread, PNG
# RGBA, and each pixel's alpha and colour compared.
#   legacy    no #version: the background (a colour) is clear and black
#             through and around a transmit 0.5 sphere and a filter 0.7
#             sphere (filter passes the grey of its colour, twice)
#   discs     filter 1 on pure red, green and blue and rgbft 0.5/0.2
#             flat discs: the grey weights 0.297 0.589 0.114
#   fog       a fog with transmit 0.3 before a clear background
#   v37       #version 3.7: an rgbt 0.5 background is half clear, a
#             mirror shows it opaque, glass lets it through clear
#   sky       #version 3.7, a sky_sphere with filter over no background
#   fisheye   #version 3.7, no background: clear outside the circle
#   aa        legacy with +A0.1: alpha averaged over the supersamples
# Without antialiasing every alpha must be within 1/255 of povray's and
# every colour (where the alpha is not 0) within 0.04 (0.035 is the
# worst of the renders without +UA here, a silhouette pixel); with
# antialiasing, 97% of the pixels (the supersampled sets differ a
# little: lib/trace/render.c).  Prints the worst differences.
# Skipped (77) without povray or /usr/bin/python3 with numpy and skimage.
set -u
TEST_NAME=test_alpha_povray
. "$(dirname "$0")/cli_env.sh"
POVRAY=${POVRAY:-povray}
command -v "$POVRAY" >/dev/null 2>&1 || { echo "no povray: skipped"; exit 77; }
PY=/usr/bin/python3
"$PY" -c 'import numpy, skimage' 2>/dev/null || { echo "no skimage: skipped"; exit 77; }
cd "$work" || exit 99

head='camera { location <0,0,-4> look_at 0 }
light_source { <5,5,-5> rgb 1 }'
cat >legacy.pov <<POV
$head
background { rgb <0.2,0.4,0.8> }
sphere { <-0.6,0,0>, 0.8 pigment { rgbt <1,0.5,0.2,0.5> } }
sphere { <1.2,0,0>, 0.6 pigment { rgbf <0.2,0.5,1,0.7> } }
POV
cat >discs.pov <<POV
$head
disc { <-1,0,0>, -z, 0.8 pigment { rgbf <1,0,0,1> } finish { ambient 0 diffuse 0 } }
disc { <1,0,0>, -z, 0.8 pigment { rgbf <0,1,0,1> } finish { ambient 0 diffuse 0 } }
disc { <0,1,0>, -z, 0.5 pigment { rgbf <0,0,1,1> } finish { ambient 0 diffuse 0 } }
disc { <0,-1,0>, -z, 0.5 pigment { rgbft <1,0.5,0,0.5,0.2> } finish { ambient 1 diffuse 0 } }
POV
cat >fog.pov <<POV
$head
background { rgb <0.2,0.4,0.8> }
fog { distance 5 rgbt <0.5,0.6,0.7,0.3> }
sphere { 0, 1 pigment { rgb <1,0.5,0.2> } }
POV
cat >v37.pov <<POV
#version 3.7;
$head
background { rgbt <0.2,0.4,0.8,0.5> }
sphere { <-1.1,0,0>, 0.9 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.5 } }
sphere { <1.1,0,0>, 0.9 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }
disc { <0,1.2,0>, -z, 0.4 pigment { rgbft <1,0,0,0.5,0.2> } finish { ambient 0 diffuse 0 } }
POV
cat >sky.pov <<POV
#version 3.7;
$head
sky_sphere { pigment { rgbf <0.2,0.4,0.8,0.5> } }
sphere { <-1.1,0,0>, 0.9 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.5 } }
sphere { <1.1,0,0>, 0.9 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }
POV
cat >fisheye.pov <<POV
#version 3.7;
camera { fisheye location <0,0,-4> look_at 0 angle 180 }
light_source { <5,5,-5> rgb 1 }
sphere { 0, 1 pigment { rgb <1,0.5,0.2> } }
POV
cp legacy.pov aa.pov

failures=0
for s in legacy discs fog v37 sky fisheye aa; do
  aa=-A
  [ "$s" = aa ] && aa=+A0.1
  timeout 120 "$POVRAY" "+I$s.pov" "+Opov_$s.png" +W64 +H48 -D $aa +WT1 -GA \
    +UA +FN >/dev/null 2>&1 || { echo "povray $s failed" >&2; exit 99; }
  timeout 120 "$ZRCUBE" "$s.pov" "+Ozr_$s.png" +W64 +H48 -D $aa +WT1 +UA +FN \
    2>"zr_$s.err" || { echo "FAIL: zrcube $s: $(tail -1 "zr_$s.err")" >&2; failures=$((failures + 1)); }
done
"$PY" - <<'PY' || failures=$((failures + 1))
import numpy as np
from skimage import io
bad = 0
for s in ('legacy', 'discs', 'fog', 'v37', 'sky', 'fisheye', 'aa'):
    p = io.imread('pov_%s.png' % s).astype(np.float64) / 255
    z = io.imread('zr_%s.png' % s).astype(np.float64) / 255
    if p.shape != z.shape or p.shape[2] != 4:
        print('%s: shapes %s %s FAIL' % (s, p.shape, z.shape))
        bad += 1
        continue
    da = np.abs(p[..., 3] - z[..., 3])
    seen = (p[..., 3] > 0) | (z[..., 3] > 0)
    dc = np.where(seen[..., None], np.abs(p[..., :3] - z[..., :3]), 0).max(axis=2)
    ok = (da <= 1.5 / 255) & (dc <= 0.04)
    share = ok.mean()
    need = 0.97 if s == 'aa' else 1.0
    print('%s: alpha max diff %.4f, colour max diff %.4f, pixels within '
          'tolerance %.4f (need %.2f)%s' % (s, da.max(), dc.max(), share,
                                             need, '' if share >= need else ' FAIL'))
    if share < need:
        bad += 1
raise SystemExit(1 if bad else 0)
PY
[ "$failures" -eq 0 ] || exit 1
exit 0
