#!/bin/sh
# test_rad_cli.sh - zrcube --radiosity end to end on the emissive Cornell
# box (the scene of ../shared/reference/cbox_emissive.pov, kept in
# scenes/cornell.pov or bench/radiosity/cornell.pov):
#   - a 64x64 render with --radiosity is finite (no NaN or infinity) and
#     lit (mean above a floor);
#   - the same bytes from 1 and 2 MPI ranks and from 1 and 2 threads;
#   - --radiosity-save then --radiosity-load gives the same bytes;
#   - --radiosity-only gives the same bytes as the full render, because
#     the scene has no light source, highlight or mirror: anything the
#     shading added (ambient, emission counted twice) would show;
#   - emission leaves the sides it gets away from (the default): the
#     lamp wound the other way shows its radiance from below and lights
#     the room as much (within 2%); with --one-sided-emission=1 only the
#     front emits, and the lamp wound the other way is black from below;
#   - --radiosity-stats prints the key=value words bench/radiosity.sh
#     reads;
#   - a 256x256 +A0.05 +R3 render is within a relative RMSE of 0.2 of
#     the path-traced ground truth when that file is present (measured
#     0.115 at the default bf_eps; 0.2 leaves room for solver changes
#     but fails a render that lost the indirect light, which measures
#     above 0.4);
#   - light sources shoot into the mesh and the render adds only their
#     interreflected light to the tracer's direct light: a floor alone
#     under a point light renders the same bytes with and without
#     --radiosity (nothing bounces back); two plates, a box and a point
#     light render, per pixel, the direct image (no radiosity) plus the
#     --radiosity-only image to float rounding (1e-5), the indirect part
#     is not black, and ranks and threads give the same bytes;
#   - --radiosity-mesh=FILE writes the solution's mesh at the render's
#     size, the same bytes from 1 and 2 ranks, with edge pixels (pure
#     black or white) that grow in number as BF_eps refines the mesh;
#   - bad option values and bad solution files: exact messages, exit
#     status 2 for the command line and 1 for a file.
#
# Environment: ZR_BUILDDIR, ZR_SRCDIR, MPIRUN, as for test_cli.sh.

set -u
ZRCUBE="${ZR_BUILDDIR:-$(pwd)}/bin/zrcube"
IMGCMP="${ZR_BUILDDIR:-$(pwd)}/tests/imgcmp"
SRCDIR="${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}"
MPIRUN="${MPIRUN:-mpirun}"
: "${OMPI_ALLOW_RUN_AS_ROOT:=1}" "${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:=1}"
: "${OMPI_MCA_rmaps_base_oversubscribe:=1}"
export OMPI_ALLOW_RUN_AS_ROOT OMPI_ALLOW_RUN_AS_ROOT_CONFIRM \
  OMPI_MCA_rmaps_base_oversubscribe
MPI_ASAN="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
TRUTH="$SRCDIR/../shared/reference/cbox_emissive-256.pfm"

if [ ! -x "$ZRCUBE" ]; then
  echo "test_rad_cli.sh: no zrcube at $ZRCUBE" >&2
  exit 99
fi
scene_src=
for f in "$SRCDIR/scenes/cornell.pov" "$SRCDIR/bench/radiosity/cornell.pov"
do
  if [ -f "$f" ]; then
    scene_src=$f
    break
  fi
done
if [ -z "$scene_src" ]; then
  echo "test_rad_cli.sh: no cornell.pov in scenes/ or bench/radiosity/" >&2
  exit 99
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_test_rad_cli.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 99

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# run NAME WANT COMMAND...: as in test_cli.sh.
run() {
  r_name=$1 r_want=$2
  shift 2
  "$@" >"$r_name.out" 2>"$r_name.err"
  got=$?
  if [ "$got" -ge 128 ]; then
    fail "$r_name: killed by a signal (status $got)"
  elif [ "$got" -ne "$r_want" ]; then
    fail "$r_name: exit status $got, expected $r_want"
  fi
  if grep -q -e 'Sanitizer' -e 'runtime error:' "$r_name.err"; then
    fail "$r_name: sanitizer report"
  fi
  if [ "$r_want" = 0 ] && [ "$got" -ne 0 ]; then
    sed "s/^/  $r_name: /" "$r_name.err" >&2
  fi
}
mpi() {
  m_name=$1 m_want=$2 m_ranks=$3
  shift 3
  run "$m_name" "$m_want" env ASAN_OPTIONS="$MPI_ASAN" \
    $MPIRUN -n "$m_ranks" "$ZRCUBE" "$@"
}
# expect NAME TEXT: NAME.err holds exactly the line TEXT.
expect() {
  grep -q -x -F -e "$2" "$1.err" ||
    { fail "$1: stderr lacks the line '$2'"; sed "s/^/  $1: /" "$1.err" >&2; }
}
same() {
  cmp -s "$1" "$2" || fail "$1 and $2 differ"
}

# pfm_stats FILE W H: "nonfinite mean max" over the RGB floats of a PFM
# file of W x H pixels (little-endian, as zrcube writes it on this host);
# the mean clips each value to [0, 1] so that the lamp (30 times a
# colour) does not outweigh the room, the max does not.
pfm_stats() {
  tail -c $(($2 * $3 * 12)) "$1" | od -An -v -t f4 |
    awk '{ for (i = 1; i <= NF; i++) {
             v = $i
             if (v ~ /nan|inf/) { bad++; continue }
             v += 0
             s += v < 0 ? 0 : v > 1 ? 1 : v
             if (v > m) m = v
             n++
           } }
         END { printf "%d %.6f %.6f\n", bad, n ? s / n : 0, m }'
}

# The radiosity block of POV-Ray's version of the scene is for POV-Ray's
# own method; zrcube turns its radiosity on from the command line, so the
# block is dropped in case the parser does not read it.
awk '/radiosity[ \t]*\{/ { skip = 1 } !skip { print } skip && /\}/ { skip = 0 }' \
  "$scene_src" >cornell.pov
SIZE="+W64 +H64"

run rad1 0 "$ZRCUBE" cornell.pov $SIZE +WT1 --radiosity --radiosity-stats \
  +Orad1.pfm
set -- $(pfm_stats rad1.pfm 64 64)
[ "$1" -eq 0 ] || fail "rad1.pfm has $1 values that are not finite"
# The floor and walls of the lit box average about 0.2; black is 0.
awk -v m="$2" 'BEGIN { exit !(m > 0.05) }' ||
  fail "rad1.pfm is too dark (mean $2)"
for key in elements= links= iterations= residual= seconds=; do
  grep -q -e " $key[0-9]" rad1.err ||
    fail "--radiosity-stats printed no $key"
done

run rad2t 0 "$ZRCUBE" cornell.pov $SIZE +WT2 --radiosity +Orad2t.pfm
same rad1.pfm rad2t.pfm
mpi radmpi1 0 1 cornell.pov $SIZE +WT1 --radiosity +Oradmpi1.pfm
mpi radmpi2 0 2 cornell.pov $SIZE +WT1 --radiosity +Oradmpi2.pfm
same rad1.pfm radmpi1.pfm
same radmpi1.pfm radmpi2.pfm

run save 0 "$ZRCUBE" cornell.pov $SIZE --radiosity \
  --radiosity-save=sol.zrr +Osave.pfm
[ -s sol.zrr ] || fail "--radiosity-save wrote no file"
run load 0 "$ZRCUBE" cornell.pov $SIZE --radiosity-load=sol.zrr \
  +Oload.pfm
same save.pfm load.pfm
same rad1.pfm load.pfm
mpi loadmpi 0 2 cornell.pov $SIZE --radiosity-load=sol.zrr +Oloadmpi.pfm
same rad1.pfm loadmpi.pfm
# The ranks solve one solution together (issue 15: transfer factors,
# refinement plans and gathering split among them and exchanged): with
# 2 and 3 ranks, and 2 threads each, the saved solution and the image
# are the bytes one rank alone makes.
mpi solmpi2 0 2 cornell.pov $SIZE +WT1 --radiosity --radiosity-save=sol2.zrr \
  +Osolmpi2.pfm
mpi solmpi3 0 3 cornell.pov $SIZE +WT2 --radiosity --radiosity-save=sol3.zrr \
  +Osolmpi3.pfm
same sol.zrr sol2.zrr
same sol.zrr sol3.zrr
same rad1.pfm solmpi2.pfm
same rad1.pfm solmpi3.pfm

run only 0 "$ZRCUBE" cornell.pov $SIZE --radiosity-only +Oonly.pfm
same rad1.pfm only.pfm

# Emission leaves both sides of a flat emitter by default, each by the
# share of its light that gets away from it: the lamp's back, 0.01 below
# the ceiling, sends almost nothing.  So the lamp wound the other way
# (its front normal, (p1 - p0) x (p2 - p0), then facing the ceiling)
# shows its radiance, 30 * <1, 0.67, 0.21>, from below and lights the
# room as much as before.  With --one-sided-emission=1 only the front
# emits: wound the other way it is black from below (the brightest pixel
# is then the lit room, below 2).
sed -e 's/<21.3, 54.87, 22.7>, <34.3, 54.87, 22.7>, <34.3, 54.87, 33.2>/<34.3, 54.87, 22.7>, <21.3, 54.87, 22.7>, <34.3, 54.87, 33.2>/' \
    -e 's/<21.3, 54.87, 22.7>, <34.3, 54.87, 33.2>, <21.3, 54.87, 33.2>/<34.3, 54.87, 33.2>, <21.3, 54.87, 22.7>, <21.3, 54.87, 33.2>/' \
    cornell.pov >flipped.pov
cmp -s cornell.pov flipped.pov && fail "flipped.pov: the lamp was not found"
set -- $(pfm_stats rad1.pfm 64 64)
one=$2
awk -v m="$3" 'BEGIN { exit !(m > 25) }' ||
  fail "lamp facing down: brightest value $3, expected 30"
run flipped 0 "$ZRCUBE" flipped.pov $SIZE --radiosity-only +Oflipped.pfm
set -- $(pfm_stats flipped.pfm 64 64)
awk -v m="$3" 'BEGIN { exit !(m > 25) }' ||
  fail "lamp facing up: brightest value $3, expected 30"
awk -v a="$one" -v b="$2" 'BEGIN { exit !(b > 0.98 * a && b < 1.02 * a) }' ||
  fail "lamp facing up: mean $2, facing down $one (want within 2%)"
run flipped1 0 "$ZRCUBE" flipped.pov $SIZE --radiosity-only \
  --one-sided-emission=1 +Oflipped1.pfm
set -- $(pfm_stats flipped1.pfm 64 64)
awk -v m="$3" 'BEGIN { exit !(m < 2) }' ||
  fail "front only, lamp facing up: brightest value $3, expected black"
run flipped2 0 "$ZRCUBE" flipped.pov $SIZE --radiosity-only \
  --one-sided-emission=0 +Oflipped2.pfm
set -- $(pfm_stats flipped2.pfm 64 64)
awk -v m="$3" 'BEGIN { exit !(m > 25) }' ||
  fail "two-sided, lamp facing up: brightest value $3, expected 30"

# Without radiosity the scene has no light source and ambient 0: the
# lamp alone shows, the rest is black.  So --radiosity is what lights it.
run plain 0 "$ZRCUBE" cornell.pov $SIZE +Oplain.pfm
set -- $(pfm_stats plain.pfm 64 64)
awk -v a="$one" -v b="$2" 'BEGIN { exit !(b < 0.5 * a) }' ||
  fail "without --radiosity the mean is $2, with it $one"

# ---- light sources ---------------------------------------------------

# floats FILE W H: the RGB floats of a PFM file, one a line.
floats() {
  tail -c $(($2 * $3 * 12)) "$1" | od -An -v -t f4 | tr -s ' ' '\n' |
    grep -v '^$'
}
cat >floor.pov <<'EOF2'
#declare F = texture { pigment { rgb 1 } finish { diffuse 0.5 ambient 0 } }
triangle { <-2,0,-2>, <2,0,-2>, <2,0,2> texture { F } }
triangle { <-2,0,-2>, <2,0,2>, <-2,0,2> texture { F } }
light_source { <0,1,0> color rgb 1 }
camera { location <0,1.5,-3> look_at <0,0,0> }
EOF2
run floor0 0 "$ZRCUBE" floor.pov $SIZE +Ofloor0.pfm
run floor1 0 "$ZRCUBE" floor.pov $SIZE --radiosity --bf-eps=1e-3 \
  --radiosity-stats +Ofloor1.pfm
same floor0.pfm floor1.pfm
grep -q -e ' lights=[1-9]' floor1.err ||
  fail "floor1: --radiosity-stats shows no light power from the light"

cat >plates.pov <<'EOF2'
#declare F = texture { pigment { rgb 1 } finish { diffuse 0.5 ambient 0 } }
triangle { <-1,0,-1>, <1,0,-1>, <1,0,1> texture { F } }
triangle { <-1,0,-1>, <1,0,1>, <-1,0,1> texture { F } }
triangle { <-1,1,-1>, <1,1,-1>, <1,1,1> texture { F } }
triangle { <-1,1,-1>, <1,1,1>, <-1,1,1> texture { F } }
box { <-0.3,0,-0.2>, <0.2,0.3,0.3>
      texture { pigment { rgb <1,0.4,0.3> } finish { diffuse 0.8 ambient 0 } } }
light_source { <0.3,0.6,-0.2> color rgb 1 }
camera { location <0,0.5,-2.5> look_at <0,0.4,0> }
EOF2
LIT="--radiosity --bf-eps=1e-3"
run plain_l 0 "$ZRCUBE" plates.pov $SIZE +Oplain_l.pfm
run full_l 0 "$ZRCUBE" plates.pov $SIZE $LIT +WT1 +Ofull_l.pfm
run only_l 0 "$ZRCUBE" plates.pov $SIZE $LIT --radiosity-only +Oonly_l.pfm
floats full_l.pfm 64 64 >full_l.txt
floats plain_l.pfm 64 64 >plain_l.txt
floats only_l.pfm 64 64 >only_l.txt
set -- $(paste full_l.txt plain_l.txt only_l.txt |
  awk '{ d = $1 - $2 - $3; if (d < 0) d = -d; if (d > m) m = d; s += $3 }
       END { printf "%g %g\n", m, NR ? s / NR : 0 }')
awk -v m="$1" 'BEGIN { exit !(m < 1e-5) }' ||
  fail "plates: full render minus direct minus indirect is up to $1"
awk -v m="$2" 'BEGIN { exit !(m > 0.005) }' ||
  fail "plates: the indirect light is too dark (mean $2)"
run full_l2 0 "$ZRCUBE" plates.pov $SIZE $LIT +WT2 +Ofull_l2.pfm
same full_l.pfm full_l2.pfm
mpi full_lmpi 0 2 plates.pov $SIZE $LIT +WT1 +Ofull_lmpi.pfm
same full_l.pfm full_lmpi.pfm

# ---- the mesh image --------------------------------------------------

# ink FILE: how many pixels of a 64 x 64 PFM are pure black or white.
ink() {
  floats "$1" 64 64 | awk '{ v[NR % 3] = $1 }
    NR % 3 == 0 { if ((v[1] == 0 && v[2] == 0 && v[0] == 0) ||
                      (v[1] == 1 && v[2] == 1 && v[0] == 1)) n++ }
    END { print n + 0 }'
}
run mesh1 0 "$ZRCUBE" cornell.pov $SIZE --radiosity --bf-eps=1e-2 \
  --radiosity-mesh=mesh1.pfm +Omesh1r.pfm
mpi mesh2 0 2 cornell.pov $SIZE --radiosity --bf-eps=1e-2 \
  --radiosity-mesh=mesh2.pfm +Omesh2r.pfm
same mesh1.pfm mesh2.pfm
run mesh3 0 "$ZRCUBE" cornell.pov $SIZE --radiosity --bf-eps=1e-3 \
  --radiosity-mesh=mesh3.pfm +Omesh3r.pfm
[ -s mesh1.pfm ] || fail "--radiosity-mesh wrote no file"
coarse=$(ink mesh1.pfm) fine=$(ink mesh3.pfm)
[ "$coarse" -gt 100 ] || fail "mesh1.pfm shows only $coarse edge pixels"
[ "$fine" -gt "$coarse" ] ||
  fail "a finer mesh shows no more edges ($fine against $coarse)"
run meshbad 1 "$ZRCUBE" cornell.pov $SIZE --radiosity \
  --radiosity-mesh=nodir/mesh.png +Omeshbad.pfm

if [ -f "$TRUTH" ] && [ -x "$IMGCMP" ]; then
  run big 0 "$ZRCUBE" cornell.pov +W256 +H256 +A0.05 +R3 --radiosity \
    +Obig.pfm
  rmse=$("$IMGCMP" big.pfm "$TRUTH" --rmse 2>/dev/null |
         sed -n 's/^rmse=//p')
  awk -v e="${rmse:-9}" 'BEGIN { exit !(e < 0.2) }' ||
    fail "relative RMSE against the ground truth is ${rmse:-unknown}"
else
  echo "test_rad_cli.sh: no ground truth or imgcmp, comparison skipped"
fi

# ---- bad input ------------------------------------------------------

bad() { # NAME MESSAGE OPTION
  run "$1" 2 "$ZRCUBE" cornell.pov $SIZE +O"$1.pfm" "$3"
  expect "$1" "$2"
}
bad bf "zrcube: '--bf-eps=-1': --bf-eps must be a number >= 0" --bf-eps=-1
bad bf2 "zrcube: '--bf-eps=x': --bf-eps must be a number >= 0" --bf-eps=x
bad area "zrcube: '--area-eps=1': --area-eps must be a number between 0 \
and 1 (a fraction of the scene's surface area)" --area-eps=1
bad vis "zrcube: '--vis-rays=0': --vis-rays must be a whole number from \
1 to 16" --vis-rays=0
bad unif "zrcube: '--uniform=3': --uniform takes N for N x N elements per \
surface, a power of two from 2 to 1024" --uniform=3
bad iter "zrcube: '--max-iterations=0': --max-iterations must be a whole \
number from 1 to 100000000" --max-iterations=0
bad res "zrcube: '--residual=0': --residual must be a number > 0" \
  --residual=0
bad res2 "zrcube: '--residual=nan': --residual must be a number > 0" \
  --residual=nan
bad side "zrcube: '--one-sided-emission=2': --one-sided-emission takes 0 \
or 1 (or on, off), or open" --one-sided-emission=2
bad shoot "zrcube: '--shooting=1': --shooting takes no value" --shooting=1
bad save "zrcube: '--radiosity-save' needs a value" --radiosity-save

run missing 1 "$ZRCUBE" cornell.pov $SIZE --radiosity-load=none.zrr \
  +Omissing.pfm
expect missing "error: radiosity: cannot read 'none.zrr': No such file or \
directory"
[ ! -e missing.pfm ] || fail "a failed load still wrote an image"
printf 'not a solution\n' >junk.zrr
run junk 1 "$ZRCUBE" cornell.pov $SIZE --radiosity-load=junk.zrr +Ojunk.pfm
expect junk "error: radiosity: 'junk.zrr' is not a zRcube radiosity file"
sed 's/rgb <0.75, 0.75, 0.75>/rgb <0.7, 0.75, 0.75>/' cornell.pov >other.pov
run other 1 "$ZRCUBE" other.pov $SIZE --radiosity-load=sol.zrr +Oother.pfm
grep -q -F "error: radiosity: 'sol.zrr' was solved for another scene" \
  other.err || fail "other: no message about another scene"

if [ "$failures" -ne 0 ]; then
  echo "test_rad_cli.sh: $failures failure(s)" >&2
  exit 1
fi
echo "test_rad_cli.sh: all passed"
