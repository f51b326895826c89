#!/bin/sh
# examples/mpi_render.c (zrcube_mpi.h: a caller's communicator) under
# mpirun with 1, 2 and 3 ranks, on a radiosity scene (the ranks solve
# together) and a sky-lit one (the ranks pretrace the irradiance cache
# together): the pictures must be the same bytes for every rank count,
# and the same as zrcube's own at the same settings.
# Environment: ZR_BUILDDIR, ZR_SRCDIR, MPIRUN.
set -u
: "${ZR_SRCDIR:?}" "${ZR_BUILDDIR:?}"
MPIRUN="${MPIRUN:-mpirun}"
command -v "$MPIRUN" >/dev/null 2>&1 || { echo "no mpirun: skipped"; exit 77; }
EXAMPLE="$ZR_BUILDDIR/examples/mpi_render"
ZRCUBE="$ZR_BUILDDIR/bin/zrcube"
MPI_ASAN="${ASAN_OPTIONS:-}${ASAN_OPTIONS:+:}detect_leaks=0"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
passed=0 failed=0
fail() { echo "FAIL: $*" >&2; failed=$((failed + 1)); }
ok() { passed=$((passed + 1)); }

cat > room.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { } }
camera { location <0, 1, -2.6> look_at <0, 1, 0> }
#declare W = texture { pigment { rgb 0.7 } finish { diffuse 1 ambient 0 } }
box { <-1, 0, -1>, <1, 2, 1> texture { W } }
box { <-0.3, 1.98, -0.3>, <0.3, 1.999, 0.3>
  texture { pigment { rgb 1 } finish { emission 8 diffuse 0 ambient 0 } } }
box { <-0.2, 0, -0.2>, <0.3, 0.6, 0.3>
  texture { pigment { rgb <0.8, 0.2, 0.1> } finish { diffuse 1 ambient 0 } } }
POV
cat > sky.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { } }
camera { location <0, 1.2, -3> look_at <0, 0.4, 0> }
sky_sphere { pigment { rgb <0.6, 0.7, 1> } }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb 0.8 } finish { diffuse 0.8 } }
plane { y, 0 pigment { rgb 0.6 } }
POV
for scene in room sky; do
  for n in 1 2 3; do
    if ASAN_OPTIONS="$MPI_ASAN" "$MPIRUN" -n $n "$EXAMPLE" $scene.pov \
         ${scene}_$n.png 2>${scene}_$n.err; then
      ok
    else
      fail "$scene: mpirun -n $n exited $?"
      sed "s/^/  /" ${scene}_$n.err >&2
    fi
  done
  cmp -s ${scene}_1.png ${scene}_2.png && ok || fail "$scene: 1 and 2 ranks differ"
  cmp -s ${scene}_1.png ${scene}_3.png && ok || fail "$scene: 1 and 3 ranks differ"
  ASAN_OPTIONS="$MPI_ASAN" "$ZRCUBE" $scene.pov +W160 +H120 -D +WT1 \
    +O${scene}_cli.png 2>/dev/null || fail "$scene: zrcube failed"
  cmp -s ${scene}_1.png ${scene}_cli.png && ok ||
    fail "$scene: the example and zrcube differ"
done
echo "mpi example: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
