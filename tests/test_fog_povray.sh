#!/bin/sh
# test_fog_povray.sh - fog and solid objects, zRcube against POV-Ray 3.7
# (tests/fog/solid_fog.pov, 16x12, the middle pixel, 8-bit sRGB): a
# camera inside a solid plane sees no fog (the manual's "Empty and Solid
# Objects"), inside the same plane made hollow it does, and a light with
# media_attenuation on is dimmed by the fog ("Atmospheric Attenuation").
# Each must be within 3 levels of povray's.  Not checked: a light with
# media_attenuation whose path runs inside a solid object (povray does
# not dim it; zRcube does, lib/trace/media.c).
# Skips (77) when povray is not installed.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
srcdir=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
builddir=${ZR_BUILDDIR:-$srcdir/build}
zrcube=$builddir/bin/zrcube
scene=$srcdir/tests/fog/solid_fog.pov
inc=/usr/share/povray-3.7/include
command -v povray >/dev/null 2>&1 || { echo "no povray: skipped"; exit 77; }
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
[ -x "$zrcube" ] || { echo "$zrcube is not built" >&2; exit 99; }
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_fog.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work" || exit 99
good=0 bad=0
for d in "" "Declare=H=1" "Declare=H=1 Declare=MA=1"; do
  rm -f z.png p.png
  timeout 60 "$zrcube" +I"$scene" +Oz.png +W16 +H12 -D +WT1 +L"$inc" $d \
    </dev/null >z.log 2>&1
  timeout 60 povray +I"$scene" +Op.png +W16 +H12 -D -A +WT1 -GA +L"$inc" $d \
    </dev/null >p.log 2>&1
  if /usr/bin/python3 - "$d" <<'PY'
import sys
from skimage import io
try:
    a, b = io.imread('z.png'), io.imread('p.png')
except Exception as e:
    print('%s: no picture (%s) FAIL' % (sys.argv[1] or 'solid', e))
    sys.exit(1)
za, pa = [int(v) for v in a[6, 8, :3]], [int(v) for v in b[6, 8, :3]]
ok = max(abs(x - y) for x, y in zip(za, pa)) <= 3
print('%s: zrcube %s povray %s %s' % (sys.argv[1] or 'solid', za, pa,
                                      'ok' if ok else 'FAIL'))
sys.exit(0 if ok else 1)
PY
  then good=$((good + 1)); else bad=$((bad + 1)); fi
done
echo "$good passed, $bad failed"
[ "$bad" -eq 0 ]
