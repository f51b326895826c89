#!/bin/sh
# embree.sh - pictures of meshes traced with the Embree backend (configure
# --with-embree, lib/trace/embree.c) against the built-in hierarchy's:
# scenes/mesh.pov, tests/mesh_texture_list.pov and tests/embree_scene.pov
# (a flat terrain that shadows itself, a mesh cut by CSG through its
# inside_vector and placed twice, a mirror), each rendered at 160x120
# with --accel=builtin and --accel=embree, one thread and two.
#
# Embree only names candidate triangles; our double-precision test gives
# t, normal and uv, so the pictures may differ only in the pixels whose
# ray passes within single precision of an edge.  Required: SSIM >=
# 0.999 and a worst 8x8 block difference delta <= 0.01 (tests/imgcmp;
# one wrong pixel in a block gives delta <= 1/64 x 4 channels of 1 /
# box filter; a wrong surface over an area gives far more), and the
# Embree picture the same bytes with one thread and two.  A build
# without Embree skips (77).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
printf 'camera { location -z look_at 0 }\n' >probe.pov
if ! "$zrcube" +Iprobe.pov +W4 +H4 -D -A --accel=embree +Oprobe.png \
     >probe.log 2>&1; then
  if grep -q "built without Embree" probe.log; then
    echo "zrcube was built without Embree: skipped"
    exit 77
  fi
  cat probe.log >&2
  exit 99
fi
fail=0
for scene in scenes/mesh.pov tests/mesh_texture_list.pov \
             tests/embree_scene.pov; do
  name=$(basename "$scene" .pov)
  cp "$srcdir/$scene" "$name.pov" || exit 99
  for run in builtin:1 embree:1 embree:2; do
    accel=${run%:*}
    threads=${run#*:}
    timeout 120 "$zrcube" "+I$name.pov" "+O$name-$accel-$threads.png" \
      +W160 +H120 -A -D "+WT$threads" "--accel=$accel" \
      >"$name.log" 2>&1 ||
      { echo "zrcube --accel=$accel failed on $name:" >&2
        cat "$name.log" >&2; exit 1; }
  done
  same=
  cmp -s "$name-builtin-1.png" "$name-embree-1.png" && same=" (same bytes)"
  if out=$("$imgcmp" "$name-embree-1.png" "$name-builtin-1.png" \
             --ssim-min 0.999 --delta-max 0.01); then
    echo "ok: $name, embree against builtin: $out$same"
  else
    echo "FAIL: $name, embree against builtin: $out"
    fail=1
  fi
  if cmp -s "$name-embree-1.png" "$name-embree-2.png"; then
    echo "ok: $name, embree: the same bytes with 1 and 2 threads"
  else
    echo "FAIL: $name, embree: other bytes with 2 threads"
    fail=1
  fi
done
exit $fail
