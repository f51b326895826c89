#!/bin/sh
# Builds the README's example program the way a user does, with
# pkg-config (against the uninstalled library), and renders a scene.
set -eu
: "${ZR_SRCDIR:?}" "${ZR_BUILDDIR:?}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export PKG_CONFIG_PATH="$ZR_BUILDDIR${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
if [ -e "$ZR_BUILDDIR/lib/.libs/libzrcube.so" ]; then
  libs=$(pkg-config --libs libzrcube)
else
  libs=$(pkg-config --static --libs libzrcube)
fi
# shellcheck disable=SC2086
${CC:-cc} ${ZR_TEST_CFLAGS:-} $(pkg-config --cflags libzrcube) \
  "$ZR_SRCDIR/examples/render.c" $libs ${ZR_TEST_LDFLAGS:-} -o "$tmp/render"
cat > "$tmp/scene.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -4>, rgb 1 }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.2, 0.1> } }
plane { y, 0 pigment { rgb 0.8 } }
POV
LD_LIBRARY_PATH="$ZR_BUILDDIR/lib/.libs" "$tmp/render" "$tmp/scene.pov" \
  "$tmp/out.png"
# The picture must exist and hold the 8-byte PNG signature.
test "$(head -c 8 "$tmp/out.png" | od -An -tx1 | tr -d ' \n')" = \
  "89504e470d0a1a0a"
# Its 4 threads give the bytes of the command line's one thread, with the
# same defaults (zr_render_params_init).
(cd "$tmp" && "$ZR_BUILDDIR/bin/zrcube" scene.pov +W160 +H120 +WT1 \
   +Ocli.png 2> cli.err) || { cat "$tmp/cli.err" >&2; exit 1; }
cmp "$tmp/out.png" "$tmp/cli.png"
# Cancelled at 30% of the render: the distinct status, no image.
if LD_LIBRARY_PATH="$ZR_BUILDDIR/lib/.libs" "$tmp/render" "$tmp/scene.pov" \
     "$tmp/cancel.png" 30 2> "$tmp/cancel.err"; then
  echo "a cancelled render succeeded" >&2; exit 1
fi
grep -q "render: cancelled by the caller" "$tmp/cancel.err" ||
  { echo "no cancel message:" >&2; cat "$tmp/cancel.err" >&2; exit 1; }
# Progress is reported per finished row block, so under load the printed
# percentages can step over 30 (29 -> 31): the render must have reached at
# least 30% and stopped before the end.
grep -Eq "phase 3: +(3[0-9]|[4-9][0-9])%" "$tmp/cancel.err"
if grep -q "phase 3: 100%" "$tmp/cancel.err"; then
  echo "the cancelled render ran to the end" >&2; exit 1
fi
test ! -e "$tmp/cancel.png"
# A bad scene must fail with a message that names the file and line.
printf 'sphere { <0,0,0>, 1 pigment { rgb foo } }\n' > "$tmp/bad.pov"
if LD_LIBRARY_PATH="$ZR_BUILDDIR/lib/.libs" "$tmp/render" "$tmp/bad.pov" \
     "$tmp/bad.png" 2> "$tmp/err"; then
  echo "bad scene rendered" >&2; exit 1
fi
grep -q "bad.pov:1:" "$tmp/err"
test ! -e "$tmp/bad.png"
echo "example: 3 passed, 0 failed"
