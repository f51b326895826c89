#!/bin/sh
# test_mesh_textures.sh - a mesh2's texture_list moves with the object:
# tests/mesh_texture_list.pov scales and moves a mesh whose faces take
# an agate texture from its list.  The picture must equal the same mesh
# written already in place with the texture moved by hand (byte for
# byte), and, with povray installed, povray's (SSIM >= 0.99; before the
# fix the listed texture stayed where the mesh was written: 0.83).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/mesh_texture_list.pov" moved.pov || exit 99
# The same picture built in place: vertices at their final positions,
# the texture given the object's scale and translation itself.
sed -e 's/vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }/vertex_vectors { 4, <0.25,0.25,0>, <0.75,0.25,0>, <0.75,0.75,0>, <0.25,0.75,0> }/' \
    -e 's/texture_list { 1, texture { T } }/texture_list { 1, texture { T scale 0.5 translate <0.25, 0.25, 0> } }/' \
    -e 's/^object { M scale 0.5 translate <0.25, 0.25, 0> }/object { M }/' \
    moved.pov >inplace.pov
fail=0
for s in moved inplace; do
  timeout 60 "$zrcube" +I$s.pov +O$s.png +W120 +H120 -D +WT1 >$s.log 2>&1 ||
    { echo "zrcube failed on $s:" >&2; cat $s.log >&2; exit 1; }
done
if out=$("$imgcmp" moved.png inplace.png --ssim-min 0.999); then
  echo "ok: the listed texture moved with the mesh: $out"
else
  echo "FAIL: the listed texture did not move with the mesh: $out"
  fail=1
fi
if command -v povray >/dev/null 2>&1; then
  timeout 120 povray +Imoved.pov +Opov.png +W120 +H120 -D -A +WT1 -GA \
    </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
  if out=$("$imgcmp" moved.png pov.png --ssim-min 0.99); then
    echo "ok: against povray: $out"
  else
    echo "FAIL: against povray: $out"
    fail=1
  fi
fi
exit $fail
