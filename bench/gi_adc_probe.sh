#!/bin/sh
# gi_adc_probe.sh - the weight POV-Ray 3.7 gives a radiosity sample ray,
# against which the radiosity block's adc_bailout is compared (issue 11;
# lib/gi/cache.c SAMPLE_WEIGHT).
#
#   bench/gi_adc_probe.sh [BUILD_DIR]
#
# The scene: a white floor under a black plane that transmits T of the
# light of a white sky_sphere, no light source, radiosity on.  A sample
# ray from the floor reaches the sky only through the plane, so the
# floor is lit when the transmitted ray's weight w0 * T is above
# adc_bailout and black when it is below.  For T = 0.5 and 0.8 the
# script renders adc_bailout on a ladder and prints the last value that
# lit the floor and the first that did not; w0 lies between their
# ratios to T.  Measured 2026-12-02 (povray 3.7.0): T 0.5 lit at 0.24,
# black at 0.26; T 0.8 lit at 0.35, black at 0.45; independent of count
# (35, 200), recursion_limit (1, 2) and the floor's diffuse (1, 0.5):
# w0 = 0.5.  With BUILD_DIR, zrcube's renders are measured the same way.
# Exit 77 without povray.
set -eu
povray=${POVRAY:-povray}
command -v "$povray" >/dev/null ||
  { echo "gi_adc_probe.sh: $povray not found" >&2; exit 77; }
zrcube=
[ $# -ge 1 ] && zrcube=$(cd "$1" && pwd)/bin/zrcube
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-adc.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work"

# The floor's mean level (0-255) in the lower half of a PNG.
level() {
  /usr/bin/python3 -c "
import sys
from skimage import io
im = io.imread(sys.argv[1])
print(int(im[im.shape[0] // 2:, :, :3].mean()))" "$1"
}

scene() { # T adc
  cat <<EOF
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { adc_bailout $2 } }
camera { location <0, 1.5, -2> look_at <0, 0, 0> }
sky_sphere { pigment { rgb 1 } }
plane { y, 0 pigment { rgb 1 } finish { diffuse 1 ambient 0 } }
plane { y, 2 pigment { rgbt <0, 0, 0, $1> } finish { diffuse 0 ambient 0 }
        hollow }
EOF
}

for who in povray zrcube; do
  [ $who = zrcube ] && [ -z "$zrcube" ] && continue
  for T in 0.5 0.8; do
    lit=- dark=-
    for a in 0.1 0.2 0.22 0.24 0.26 0.28 0.3 0.35 0.38 0.42 0.45 0.5 0.6; do
      scene "$T" "$a" >s.pov
      if [ $who = povray ]; then
        timeout 120 "$povray" +Is.pov +Os.png +W80 +H60 -D -A +WT1 -GA -V \
          >/dev/null 2>&1
      else
        timeout 120 "$zrcube" s.pov +Os.png +W80 +H60 -D +WT1 -q \
          >/dev/null 2>&1
      fi
      if [ "$(level s.png)" -gt 20 ]; then
        lit=$a
      elif [ "$dark" = - ]; then
        dark=$a
      fi
    done
    echo "$who: transmit $T: lit up to adc_bailout $lit, black from $dark"
  done
done
