#!/bin/sh
# test_gtk.sh - zrcube-gtk's OpenGL preview draws each object where the
# scene's camera puts it.  zrcube-gtk --screenshot draws
# tests/gtk_scene.pov once under xvfb-run (Mesa's llvmpipe gives the
# GL), and the picture is checked pixel by pixel against positions
# worked out from the camera alone: camera at <0, 0, -10> looking at
# the origin with POV-Ray's default vectors (direction 1 long, right
# 4/3, up 1), so a point (x, y, z) lands at u = x / (4/3 (z + 10)),
# v = y / (z + 10), pixel ((0.5 + u) W, (0.5 - v) H):
#   - the red sphere (centre <2, 0, 0>, radius 1) covers (0.650, 0.5)
#     and, its outline about 0.075 W from there, (0.650 +- 0.06, 0.5)
#     but not (0.650 +- 0.10, 0.5);
#   - the green box (<-3, -1, -1> to <-1, 1, 1>; front face at z = -1
#     from u = -0.25 to -0.083) covers (0.35, 0.5) and (0.27, 0.5),
#     not (0.22, 0.5);
#   - the blue floor y = -2 is drawn over the plane bounds (the box
#     around the objects, stretched to the plane and widened by 10% of
#     its diagonal: z from -1.73 to 1.73), so it covers v from -0.171 to
#     -0.242: (0.5, 0.70) is floor, (0.5, 0.63) and (0.5, 0.77) are
#     the picture's grey background, as is the corner (0.02, 0.02).
# A mirrored or shifted projection, a wrong aspect ratio, a missing
# plane patch or a missing object fails one of these; the orbit's half
# turn and zoom (--orbit, what a drag and the wheel do) move them where
# the turned camera puts them.  --render (the
# Render button's worker thread and Save) writes the same bytes as
# zrcube at the same size.  A scene with an
# error exits 1 and prints the error with its file, line and column; a
# bad option exits 2.
#
# Skips (77) when zrcube-gtk was not built (configure found no GTK 4),
# when xvfb-run is missing, or when the X server gives no OpenGL
# (zrcube-gtk exits 3).  GTK and Mesa keep memory until exit that
# LeakSanitizer reports, so leak detection is off for this test alone
# (ASAN_OPTIONS=detect_leaks=0); ASan's other checks stay on.
set -u
: "${ZR_SRCDIR:?}" "${ZR_BUILDDIR:?}"
gui=$ZR_BUILDDIR/gui/zrcube-gtk
if [ ! -x "$gui" ]; then
  echo "test_gtk.sh: zrcube-gtk was not built (configure --with-gtk);" \
       "skipped"
  exit 77
fi
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "test_gtk.sh: no xvfb-run (Debian: apt-get install xvfb xauth);" \
       "skipped"
  exit 77
fi
ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
export ASAN_OPTIONS
# No session bus or accessibility bus under xvfb-run: GTK says so on
# stderr otherwise, and it is noise here.
NO_AT_BRIDGE=1
export NO_AT_BRIDGE
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_test_gtk.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

run_gui() {
  timeout 180 xvfb-run -a -s "-screen 0 1024x768x24" "$gui" "$@"
}

# check.py IMAGE FX,FY=KIND ...: the picture is 4:3 (the render's
# 320 x 240, whatever size the window gave it) and the pixel at each
# fraction (FX, FY) of its width and height is of that kind.
cat >"$work/check.py" <<'PY'
import sys
from skimage import io

img = io.imread(sys.argv[1])[..., :3].astype(int)
h, w = img.shape[:2]
ok = abs(w / h - 4 / 3) < 0.02
print('%s: %d x %d %s' % (sys.argv[1].split('/')[-1], w, h,
                          'ok' if ok else 'FAIL (not 4:3)'))
bad = 0 if ok else 1


def kind(p):
    r, g, b = p
    if r > 100 and g < 40 and b < 40:
        return 'red'
    if g > 100 and r < 40 and b < 40:
        return 'green'
    if b > 100 and r < 40 and g < 40:
        return 'blue'
    # The background the previewer clears to: 0.2 of full.
    if max(abs(c - 51) for c in p) <= 3:
        return 'background'
    return 'other %s' % (list(p),)


for arg in sys.argv[2:]:
    where, want = arg.split('=')
    fx, fy = (float(v) for v in where.split(','))
    x, y = int(fx * w), int(fy * h)
    got = kind(tuple(int(c) for c in img[y, x]))
    good = got == want
    bad += not good
    print('  (%.3f, %.3f) pixel %d,%d: %s, want %s %s'
          % (fx, fy, x, y, got, want, 'ok' if good else 'FAIL'))
sys.exit(1 if bad else 0)
PY

# shot NAME [OPTION ...]: a screenshot of the scene into $work/NAME.png;
# exits the test with 77 when there is no OpenGL.
shot() {
  name=$1
  shift
  run_gui "$@" --screenshot "$work/$name.png" \
    "$ZR_SRCDIR/tests/gtk_scene.pov" >"$work/out" 2>"$work/err"
  status=$?
  if [ $status -eq 3 ]; then
    echo "test_gtk.sh: the X server gives no OpenGL here; skipped:"
    cat "$work/err"
    exit 77
  fi
  if [ $status -ne 0 ] || [ ! -s "$work/$name.png" ]; then
    fail "zrcube-gtk $* --screenshot exited $status"
    cat "$work/err" >&2
    return 1
  fi
}

if shot scene; then
  /usr/bin/python3 "$work/check.py" "$work/scene.png" \
    0.650,0.50=red 0.590,0.50=red 0.710,0.50=red \
    0.550,0.50=background 0.750,0.50=background \
    0.350,0.50=green 0.270,0.50=green 0.220,0.50=background \
    0.500,0.70=blue 0.500,0.63=background 0.500,0.77=background \
    0.020,0.02=background || fail "pixel checks of the scene's view"
fi
# The orbit (what a drag and the wheel do), about the middle of the
# finite objects' box, the origin here.  Half a turn about the sky puts
# the camera at <0, 0, 10> with right along -x: the sphere lands at
# u = -0.15, the box at 0.15.  Zoom 2 puts it at <0, 0, -20>: the
# sphere's centre at u = 2 / (4/3 * 20) = 0.075, its outline 0.037 W
# from there.
if shot half_turn --orbit 180,0,1; then
  /usr/bin/python3 "$work/check.py" "$work/half_turn.png" \
    0.350,0.50=red 0.650,0.50=green 0.500,0.50=background ||
    fail "pixel checks after half a turn"
fi
if shot zoom --orbit 0,0,2; then
  /usr/bin/python3 "$work/check.py" "$work/zoom.png" \
    0.575,0.50=red 0.425,0.50=green 0.650,0.50=background \
    0.350,0.50=background || fail "pixel checks zoomed out"
fi

# Render, as the button does on its worker thread, and Save: the same
# bytes as zrcube's picture of the scene at the same size.
run_gui --render "$work/gui.png" "$ZR_SRCDIR/tests/gtk_scene.pov" \
  >"$work/out" 2>"$work/err"
status=$?
[ $status -eq 0 ] ||
  fail "zrcube-gtk --render exited $status: $(cat "$work/err")"
"$ZR_BUILDDIR/bin/zrcube" "$ZR_SRCDIR/tests/gtk_scene.pov" +W320 +H240 \
  +O"$work/cli.png" >"$work/out" 2>&1 ||
  fail "zrcube on the scene: $(cat "$work/out")"
cmp -s "$work/gui.png" "$work/cli.png" ||
  fail "zrcube-gtk's render differs from zrcube's"

# A scene with an error: the message names its place, the exit is 1.
printf '%s\n' '#version 3.7;' 'sphere { <0, 0, 0>, 1' \
  '  pigment { rgb <1, 0, 0> } }' 'box { 1 }' >"$work/bad.pov"
run_gui --screenshot "$work/bad_shot.png" "$work/bad.pov" \
  >"$work/out" 2>"$work/err"
status=$?
[ $status -eq 1 ] || fail "a scene with an error exited $status, not 1"
grep -q "bad.pov:4:[0-9]*: error" "$work/err" ||
  fail "the error was not located: $(cat "$work/err")"
[ ! -e "$work/bad_shot.png" ] || fail "a scene with an error was drawn"
run_gui --render "$work/bad_render.png" "$work/bad.pov" \
  >"$work/out" 2>"$work/err"
status=$?
[ $status -eq 1 ] || fail "--render of a scene with an error exited $status"
grep -q "bad.pov:4:[0-9]*: error" "$work/err" ||
  fail "--render: the error was not located: $(cat "$work/err")"
[ ! -e "$work/bad_render.png" ] || fail "a scene with an error was rendered"

# Bad command lines, before any display is needed.
"$gui" --width 0 x.pov >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "--width 0 was not refused with status 2"
grep -q "whole number" "$work/err" || fail "--width 0: $(cat "$work/err")"
"$gui" --screenshot x.png >/dev/null 2>&1
[ $? -eq 2 ] || fail "--screenshot without a scene was not refused"

[ $failures -eq 0 ] || exit 1
echo "test_gtk.sh: the preview puts every object where the camera does"
