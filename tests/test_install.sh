#!/bin/sh
# test_install.sh - `make install` and `make uninstall` of this build:
#   - installs into a temporary directory (DESTDIR), builds the README's
#     example (examples/render.c) against the installed library with the
#     installed libzrcube.pc, as a user would, and renders a scene;
#   - links the same program statically with `pkg-config --static`
#     (libzrcube.a alone in the directory, so the linker must find every
#     library it needs from the .pc file's Requires.private and
#     Libs.private) and renders again;
#   - uninstalls, after which no file is left, nor zRcube's own folder
#     under share/.
# The .pc file names the configured prefix; under DESTDIR it is moved
# with pkg-config's --define-variable=prefix.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR, CC, ZR_TEST_CFLAGS, ZR_TEST_LDFLAGS
# (set by `make check`).
set -u
: "${ZR_SRCDIR:?}" "${ZR_BUILDDIR:?}"
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_install.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT INT TERM
dest=$work/root
# MAKEFLAGS of the enclosing `make check` (-j, jobserver) are not ours.
if ! env -u MAKEFLAGS -u MFLAGS make -s -C "$ZR_BUILDDIR" install \
     DESTDIR="$dest" >"$work/install.log" 2>&1; then
  echo "make install failed:"; tail -5 "$work/install.log"; exit 1
fi
prefix=$(sed -n 's/^prefix=//p' "$ZR_BUILDDIR/libzrcube.pc")
root=$dest$prefix
pcdir=$(dirname "$(find "$dest" -name libzrcube.pc | head -1)")
[ -f "$pcdir/libzrcube.pc" ] || { echo "no libzrcube.pc installed"; exit 1; }
for f in bin/zrcube bin/zrcube-mpirun include/zrcube.h; do
  [ -e "$root/$f" ] || { echo "not installed: $f"; exit 1; }
done
pc() { PKG_CONFIG_PATH=$pcdir pkg-config --define-variable=prefix="$root" "$@"; }
cat >"$work/scene.pov" <<'POV'
#version 3.7;
camera { location <0, 1, -3> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
POV
failed=0
libdir=$(pc --variable=libdir libzrcube)
# shellcheck disable=SC2046,SC2086
if [ -e "$libdir/libzrcube.so" ]; then
  if ${CC:-cc} ${ZR_TEST_CFLAGS:-} $(pc --cflags libzrcube) \
       "$ZR_SRCDIR/examples/render.c" $(pc --libs libzrcube) \
       ${ZR_TEST_LDFLAGS:-} -o "$work/render-shared" &&
     LD_LIBRARY_PATH=$libdir "$work/render-shared" "$work/scene.pov" \
       "$work/shared.png"; then
    echo "shared: built with pkg-config and rendered"
  else
    echo "shared: FAIL"; failed=1
  fi
fi
# Static: hide the shared library so that -lzrcube finds the archive.
mkdir "$work/static"
cp "$libdir/libzrcube.a" "$work/static/" || { echo "no libzrcube.a installed"; exit 1; }
# shellcheck disable=SC2046,SC2086
if ${CC:-cc} ${ZR_TEST_CFLAGS:-} $(pc --cflags libzrcube) \
     "$ZR_SRCDIR/examples/render.c" -L"$work/static" \
     $(pc --static --libs libzrcube) ${ZR_TEST_LDFLAGS:-} \
     -o "$work/render-static" 2>"$work/static.log" &&
   ! ldd "$work/render-static" | grep -q libzrcube &&
   "$work/render-static" "$work/scene.pov" "$work/static.png"; then
  echo "static: linked with pkg-config --static and rendered"
else
  echo "static: FAIL"; head -5 "$work/static.log"; failed=1
fi
if ! env -u MAKEFLAGS -u MFLAGS make -s -C "$ZR_BUILDDIR" uninstall \
     DESTDIR="$dest" >"$work/uninstall.log" 2>&1; then
  echo "make uninstall failed:"; tail -5 "$work/uninstall.log"; failed=1
fi
left=$(find "$dest" ! -type d)
[ -d "$root/share/zrcube" ] && left="$left $root/share/zrcube/"
if [ -n "$left" ]; then
  echo "uninstall left:"; echo "$left"; failed=1
else
  echo "uninstall: no file left"
fi
[ "$failed" = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit "$failed"
