#!/bin/sh
# test_cli.sh - zrcube end to end: the same image bytes from 1, 2 and 3
# MPI ranks and from 1 or 2 threads, with and without antialiasing; bad
# input (syntax error, unknown identifier, unsupported keyword, missing
# include, missing scene, bad option values) ends with a non-zero status,
# the expected message once on stderr and no crash; --help, --version,
# the default output name and the refusal to overwrite the scene.
#
# Environment: ZR_BUILDDIR (where bin/zrcube is), MPIRUN (mpirun).
# OpenMPI leaks memory at exit, so LeakSanitizer is turned off for the
# runs under mpirun only; the runs without mpirun never initialise MPI
# and keep it on.  A sanitizer report on stderr fails the test in any
# build.

set -u
TEST_NAME=test_cli
. "$(dirname "$0")/cli_env.sh"
cd "$work" || exit 99

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# run NAME WANT COMMAND...: runs COMMAND with its output in NAME.out and
# NAME.err; WANT is an exit status, or "fail" for any failure status.
run() {
  r_name=$1 r_want=$2
  shift 2
  "$@" >"$r_name.out" 2>"$r_name.err"
  got=$?
  if [ "$got" -ge 128 ]; then
    fail "$r_name: killed by a signal (status $got)"
  elif [ "$r_want" = fail ] && [ "$got" -eq 0 ]; then
    fail "$r_name: succeeded but should have failed"
  elif [ "$r_want" != fail ] && [ "$got" -ne "$r_want" ]; then
    fail "$r_name: exit status $got, expected $r_want"
  fi
  if grep -q -e 'Sanitizer' -e 'runtime error:' "$r_name.err"; then
    fail "$r_name: sanitizer report"
  fi
  if [ "$r_want" = 0 ] && [ "$got" -ne 0 ]; then
    sed "s/^/  $r_name: /" "$r_name.err" >&2
  fi
}

serial() { run "$@"; }
# mpi NAME WANT N ARGS...: zrcube under mpirun with N ranks.
mpi() {
  m_name=$1 m_want=$2 m_ranks=$3
  shift 3
  run "$m_name" "$m_want" env ASAN_OPTIONS="$MPI_ASAN" \
    $MPIRUN -n "$m_ranks" "$ZRCUBE" "$@"
}

# expect NAME TEXT: NAME.err holds TEXT (a fixed string).
expect() {
  grep -q -F -e "$2" "$1.err" ||
    { fail "$1: stderr lacks '$2'"; sed "s/^/  $1: /" "$1.err" >&2; }
}

# expect_once NAME TEXT: TEXT is on exactly one line of NAME.err, so only
# rank 0 printed it.
expect_once() {
  count=$(grep -c -F -e "$2" "$1.err")
  [ "$count" -eq 1 ] || fail "$1: '$2' printed $count times, expected once"
}

same() {
  cmp -s "$1" "$2" || fail "$1 and $2 differ"
}

is_png() {
  [ -s "$1" ] && [ "$(head -c 4 "$1" | od -An -c | tr -d ' ')" = '211PNG' ] ||
    fail "$1 is not a PNG file"
}

# ---- a scene with edges, a shadow, a reflection and an include -----

mkdir inc
cat >inc/colours.inc <<'POV'
#declare Ground = pigment { color rgb <0.8, 0.8, 0.6> }
POV
cat >scene.pov <<'POV'
#include "colours.inc"
camera { location <0, 1.2, -4> look_at <0, 0.6, 0> }
light_source { <4, 6, -5>, color rgb 1 }
plane { y, 0 pigment { Ground } }
box { <-2, 0, 1>, <-1, 1.5, 2> pigment { color rgb <0.2, 0.4, 1> } }
sphere { <0, 0.8, 0>, 0.8
  pigment { color rgb <0.9, 0.3, 0.2> }
  finish { reflection 0.3 phong 0.8 }
}
POV
SIZE="+W64 +H48"

serial ref_aa 0 "$ZRCUBE" scene.pov +Linc $SIZE +A0.1 +WT1 +Oref_aa.png
is_png ref_aa.png
serial ref 0 "$ZRCUBE" scene.pov +Linc $SIZE -A +WT1 +Oref.png
is_png ref.png
cmp -s ref.png ref_aa.png && fail "antialiasing changed nothing"
serial aa_wt3 0 "$ZRCUBE" scene.pov +Linc $SIZE +A0.1 +WT3 +Oaa_wt3.png
same ref_aa.png aa_wt3.png
# One process of several threads encodes the PNG on a thread of its
# own, row by row as the threads finish them (lib/par/par.c
# render_band's follow): the same bytes as one thread writing after.
for t in 2 3 4; do
  serial "plain_wt$t" 0 "$ZRCUBE" scene.pov +Linc $SIZE -A "+WT$t" \
    "+Oplain_wt$t.png"
  same ref.png "plain_wt$t.png"
done
# On one host the ranks take rows from a shared counter (lib/par/par.c
# shared_rows); ZRCUBE_ROWS=static keeps the static deal.  Both must
# make the same bytes as one process.
for rows in shared static; do
if [ "$rows" = static ]; then
  ZRCUBE_ROWS=static
  export ZRCUBE_ROWS
fi
for n in 1 2 3; do
  mpi "aa_n${n}_$rows" 0 "$n" scene.pov +Linc $SIZE +A0.1 +WT2 "+Oaa_n${n}_$rows.png"
  same ref_aa.png "aa_n${n}_$rows.png"
  mpi "plain_n${n}_$rows" 0 "$n" scene.pov +Linc $SIZE +WT2 "+Oplain_n${n}_$rows.png"
  same ref.png "plain_n${n}_$rows.png"
done
mpi "aa_wt1_$rows" 0 2 scene.pov +Linc $SIZE +A0.1 +WT1 "+Oaa_wt1_$rows.png"
same ref_aa.png "aa_wt1_$rows.png"
# Pass 2 sends rank 0 only the pixels that differ from their centre
# (issue 15): the same bytes with alpha, a window and +AM2, and far
# fewer pixel bytes than pass 1's (every pixel of the rank's rows).
for extra in "+UA" "+SR0.3 +ER0.7 +SC0.25 +EC0.6" "+AM2 +R2"; do
  tag=$(echo "$extra" | tr -dc 'A-Za-z0-9')
  if [ "$rows" = shared ]; then
    # shellcheck disable=SC2086
    serial "sparse_ref_$tag" 0 "$ZRCUBE" scene.pov +Linc $SIZE +A0.1 $extra \
      +WT1 "+Osparse_ref_$tag.png"
  fi
  for n in 2 3; do
    # shellcheck disable=SC2086
    mpi "sparse_${tag}_n${n}_$rows" 0 "$n" scene.pov +Linc $SIZE +A0.1 $extra \
      +WT1 "+Osparse_${tag}_n${n}_$rows.png"
    same "sparse_ref_$tag.png" "sparse_${tag}_n${n}_$rows.png"
  done
done
# Rank 0 encodes the PNG while the other ranks render the last bands
# alone (lib/par/writer.h): ZRCUBE_WRITE_PIXEL_SECONDS makes the
# encoder look slow, so that most bands go to them; the same bytes with
# and without antialiasing, and -v says the ranks rendered a tail.
ZRCUBE_WRITE_PIXEL_SECONDS=1e-3
export ZRCUBE_WRITE_PIXEL_SECONDS
for n in 2 3; do
  mpi "tail_n${n}_$rows" 0 "$n" scene.pov +Linc $SIZE -v +WT1 "+Otail_n${n}_$rows.png"
  same ref.png "tail_n${n}_$rows.png"
  mpi "tail_aa_n${n}_$rows" 0 "$n" scene.pov +Linc $SIZE +A0.1 -v +WT1 \
    "+Otail_aa_n${n}_$rows.png"
  same ref_aa.png "tail_aa_n${n}_$rows.png"
  for t in "tail_n${n}_$rows" "tail_aa_n${n}_$rows"; do
    bands=$(sed -n 's/.*rank 0: .*; tail bands \([0-9]*\)$/\1/p' "$t.err")
    [ -n "$bands" ] && [ "$bands" -gt 0 ] ||
      fail "$t: rank 0 rendered every band ('$bands' bands of tail)"
    grep -q "rank 0: .*; tail rows joined [0-9]*;" "$t.err" ||
      fail "$t: -v lacks the tail rows rank 0 joined"
  done
done
unset ZRCUBE_WRITE_PIXEL_SECONDS
done
unset ZRCUBE_ROWS
# Rank 0 takes rows of the tail beside the others once its encoder has
# encoded the rows told (lib/par/par.c render_band): the encoder said to
# be slow leaves it most bands, a julia_fractal makes each band of 4
# rows take the other rank a few milliseconds, which the encoder of a
# few rows takes microseconds of.  The same bytes; -v counts its rows
# (the other ranks print 0: the largest count is rank 0's, even where
# mpirun interleaves the ranks' lines).
cat >join.pov <<'POV'
camera { location <0, 0, -3> look_at <0, 0, 0> }
light_source { <4, 6, -5>, color rgb 1 }
julia_fractal {
  <-0.083, 0.0, -0.83, -0.025> quaternion sqr
  max_iteration 100 precision 200
  pigment { color rgb <1, 0.3, 0.2> }
}
POV
serial join_ref 0 "$ZRCUBE" join.pov +W48 +H256 -A +WT1 +Ojoin_ref.png
ZRCUBE_WRITE_PIXEL_SECONDS=1e-3
export ZRCUBE_WRITE_PIXEL_SECONDS
mpi join_n2 0 2 join.pov +W48 +H256 -A -v +WT1 +Ojoin_n2.png
unset ZRCUBE_WRITE_PIXEL_SECONDS
same join_ref.png join_n2.png
joined=$(grep -o "tail rows joined [0-9]*" join_n2.err |
  sed 's/.* //' | sort -n | tail -n 1)
[ "${joined:-0}" -gt 0 ] ||
  fail "join_n2: rank 0 took no rows of the tail ('$joined')"
# With the static deal rank 1 renders 23 or 24 of the 48 rows (the
# chunks follow the clock) in each pass, 768 bytes of floats a row: pass 1 sends them all
# (>= 17664 bytes), pass 2 a bit a pixel and the changed pixels, so the
# total stays under the 35328 bytes whole rows in both passes would be.
ZRCUBE_ROWS=static
export ZRCUBE_ROWS
mpi sparse_bytes 0 2 scene.pov +Linc $SIZE +A0.1 +WT1 -v +Osparse_bytes.png
unset ZRCUBE_ROWS
same ref_aa.png sparse_bytes.png
sent=$(sed -n 's/.*rank 1: .*pixels \([0-9]*\);.*/\1/p' sparse_bytes.err)
if [ -z "$sent" ] || [ "$sent" -lt 17664 ] || [ "$sent" -ge 35328 ]; then
  fail "sparse_bytes: rank 1 sent '$sent' pixel bytes, expected 17664 to 35327"
fi
# GNU spellings make the same picture.
serial long 0 "$ZRCUBE" --input=scene.pov --include-path inc --width=64 \
  --height=48 --antialias=0.1 --threads=2 --output=long.png
same ref_aa.png long.png

# ---- output names ---------------------------------------------------

serial default_name 0 "$ZRCUBE" scene.pov +Linc $SIZE
is_png scene.png
same ref.png scene.png
mkdir out
serial into_dir 0 "$ZRCUBE" scene +Linc $SIZE +Oout
is_png out/scene.png
# Rank 0 finds "scene" as scene.pov and tells the other ranks.
mpi no_ext 0 2 scene +Linc $SIZE +Ono_ext.png
same ref.png no_ext.png
serial ppm 0 "$ZRCUBE" scene.pov +Linc $SIZE +FP +Oimage
[ "$(head -c 2 image.ppm)" = P6 ] ||
  fail "+FP +Oimage did not write a P6 image.ppm"
cp scene.pov scene.keep
serial overwrite 2 "$ZRCUBE" scene.pov +Linc $SIZE +Oscene.pov
expect overwrite \
  "zrcube: refusing to overwrite the scene file 'scene.pov' with the image"
same scene.keep scene.pov
# A directory that is not there fails before the render, not after.
serial nodir 1 "$ZRCUBE" scene.pov +Linc $SIZE +Ono_such_dir/x.png
expect nodir "zrcube: cannot write the image to 'no_such_dir/x.png': \
cannot create a file in 'no_such_dir': No such file or directory"
serial verbose 0 "$ZRCUBE" scene.pov +Linc $SIZE +V -F
# POV-Ray's statistics layout (bin/zrcube.c, print_statistics).
pixels_line=$(printf '%-10s%14s' 'Pixels:' 3072)
expect verbose "$pixels_line"
expect verbose "Render Statistics"
# Statistics are summed over the ranks and printed by rank 0.
mpi verbose_mpi 0 3 scene.pov +Linc $SIZE +V -F
expect_once verbose_mpi "$pixels_line"
expect verbose_mpi "3 ranks x "
# No progress line when stderr is not a terminal.
grep -q 'rendering' ref.err && fail "progress line printed to a file"

# ---- warnings: printed once, by rank 0; --quiet drops them ---------

cat >warn.pov <<'POV'
camera { location <0, 1, -4> look_at 0 }
light_source { <4, 6, -5>, color rgb 1 }
sphere { <0, 1, 0>, 1 scale <1, 0, 1> pigment { color rgb 1 } }
POV
mpi warn 0 2 warn.pov $SIZE
expect_once warn "warn.pov:3:29: warning:"
serial warn_quiet 0 "$ZRCUBE" warn.pov $SIZE -q
[ -s warn_quiet.err ] && fail "warn_quiet: --quiet still printed"

# ---- with the fatal stream off (-GF, -GA) a failed run still says why --

# povray -GA still prints its fatal error; zrcube printed nothing and
# left with status 1 (session 22).
printf 'camera { location <0, 1, -4> look_at 0 }\n  foo\n' >ga.pov
serial ga fail "$ZRCUBE" ga.pov $SIZE -GA
expect ga "ga.pov:2:3: error: undefined identifier 'foo'"
serial gf fail "$ZRCUBE" ga.pov $SIZE -GF +GFga.log
expect gf "ga.pov:2:3: error: undefined identifier 'foo'"
grep -q -F "ga.pov:2:3: error" ga.log || fail "gf: +GFga.log lacks the error"
serial ga_ok 0 "$ZRCUBE" warn.pov $SIZE -GA
[ -s ga_ok.err ] && fail "ga_ok: -GA printed on a run that succeeded"

# ---- ranks parse at once; one that read other bytes gets rank 0's -----

# Rank 0 alone writes gen.inc, blue over the red left there, then
# includes it: rank 1, reading its disk, finds the red one or the blue
# one; with the red it must parse again from the files rank 0 read
# (bin/zrcube.c, read_scene).  Either way the picture is rank 0's.
# written NAME: NAME.pov, which writes NAME.inc, alone and under 2
# ranks with NAME.inc red before each run: the same picture.
written() {
  echo '#declare C = rgb <1, 0, 0>;' >"$1.inc"
  serial "$1" 0 "$ZRCUBE" "$1.pov" $SIZE "+O$1.png"
  echo '#declare C = rgb <1, 0, 0>;' >"$1.inc"
  mpi "$1_mpi" 0 2 "$1.pov" $SIZE "+O$1_mpi.png"
  same "$1.png" "$1_mpi.png"
}
cat >gen.pov <<'POV'
#fopen Out "gen.inc" write
#write (Out, "#declare C = rgb <0, 0, 1>;\n")
#fclose Out
#include "gen.inc"
camera { location <0, 1, -4> look_at 0 }
light_source { <4, 6, -5>, color rgb 1 }
sphere { <0, 1, 0>, 1 pigment { C } }
POV
written gen

# The same with an include of more than a mebibyte, which rank 0 keeps
# as its digest only and reads again when another rank needs it
# (bin/zrcube.c, BUNDLE_DEFER_FROM): rank 1, which writes nothing, is
# at its #include before rank 0 has written 1.2 MB, so it finds the red
# one left there or a part of the blue one, and must get rank 0's.
cat >gen_big.pov <<'POV'
#fopen Out "gen_big.inc" write
#declare I = 0;
#while (I < 20000)
#write (Out, "// a line of padding, so this file is more than a MiB.\n")
#declare I = I + 1;
#end
#write (Out, "#declare C = rgb <0, 0, 1>;\n")
#fclose Out
#include "gen_big.inc"
camera { location <0, 1, -4> look_at 0 }
light_source { <4, 6, -5>, color rgb 1 }
sphere { <0, 1, 0>, 1 pigment { C } }
POV
written gen_big
[ "$(wc -c <gen_big.inc)" -gt 1048576 ] || fail "gen_big.inc: not > 1 MiB"

# The same with a mesh large enough for a shared build (16,562
# triangles, above obj_mesh.c's 16,384), which zrcube's ranks no longer
# share (bin/zrcube.c, read_scene): a rank that finds the old
# gen_mesh.inc has another mesh and parses again from rank 0's files.
# The picture is one process's; -v's "exchanges" counts the team's
# calls.
cat >gen_mesh.pov <<'POV'
#fopen Out "gen_mesh.inc" write
#write (Out, "#declare A = 3;\n")
#fclose Out
#include "gen_mesh.inc"
#declare N = 92;
camera { location <46, 60, -40> look_at <46, 0, 46> }
light_source { <0, 100, -50>, color rgb 1 }
mesh {
#declare J = 0;
#while (J < N - 1)
  #declare I = 0;
  #while (I < N - 1)
    #declare Y00 = A * sin(I * 0.37) * cos(J * 0.21);
    #declare Y10 = A * sin((I + 1) * 0.37) * cos(J * 0.21);
    #declare Y01 = A * sin(I * 0.37) * cos((J + 1) * 0.21);
    #declare Y11 = A * sin((I + 1) * 0.37) * cos((J + 1) * 0.21);
    triangle { <I, Y00, J>, <I + 1, Y10, J>, <I, Y01, J + 1> }
    triangle { <I + 1, Y10, J>, <I + 1, Y11, J + 1>, <I, Y01, J + 1> }
    #declare I = I + 1;
  #end
  #declare J = J + 1;
#end
  pigment { rgb <0.8, 0.7, 0.5> }
}
POV
echo '#declare A = 1;' >gen_mesh.inc
serial gen_mesh 0 "$ZRCUBE" gen_mesh.pov $SIZE +Ogen_mesh.png
echo '#declare A = 1;' >gen_mesh.inc
mpi gen_mesh_mpi 0 2 gen_mesh.pov $SIZE -v +Ogen_mesh_mpi.png
same gen_mesh.png gen_mesh_mpi.png
mpi gen_mesh_mpi3 0 3 gen_mesh.pov $SIZE +WT2 +Ogen_mesh_mpi3.png
same gen_mesh.png gen_mesh_mpi3.png
# The mesh without the file: every rank reads the same mesh and builds
# its hierarchy alone, without a call of the team.
sed -e '1,3d' -e 's/^#include "gen_mesh.inc"/#declare A = 3;/' \
  gen_mesh.pov >mesh_shared.pov
mpi mesh_shared 0 2 mesh_shared.pov $SIZE -v +Omesh_shared.png
same gen_mesh.png mesh_shared.png
calls=$(sed -n 's/.*rank 0: .*exchanges \([0-9]*\);.*/\1/p' mesh_shared.err)
[ "$calls" = 0 ] ||
  fail "mesh_shared: rank 0 made '$calls' team calls, expected none"

# ---- help and version -----------------------------------------------

serial help 0 "$ZRCUBE" --help
grep -q '^Usage: zrcube' help.out || fail "--help printed no usage"
serial version 0 "$ZRCUBE" --version
grep -q '^zrcube [0-9][0-9.]* (libzrcube' version.out ||
  fail "--version printed '$(cat version.out)'"

# ---- bad input --------------------------------------------------------

cat >syntax.pov <<'POV'
camera { location <0, 1, -4> look_at 0 }
sphere { <0, 1, 0>, 1 pigment { color rgb 1 } }
}
POV
cat >undefined.pov <<'POV'
camera { location <0, 1, -4> look_at 0 }
light_source { <4, 6, -5>, color rgb 1 }
sphere { <0, 1, 0>, Radius_typo pigment { color rgb 1 } }
POV
cat >unsupported.pov <<'POV'
camera { location <0, 1, -4> look_at 0 }
light_source { <4, 6, -5>, color rgb 1 }
tiff { }
POV
cat >noinclude.pov <<'POV'
#include "no_such_file.inc"
camera { location <0, 1, -4> look_at 0 }
POV

# bad NAME PLACE TEXT FILE ARGS...: fails alone and on 2 ranks, printing
# PLACE ("file:line:col: error:") and TEXT once.
bad() {
  b_name=$1 b_place=$2 b_text=$3
  shift 3
  serial "$b_name" 1 "$ZRCUBE" "$@"
  expect "$b_name" "$b_place"
  expect "$b_name" "$b_text"
  mpi "${b_name}_mpi" 1 2 "$@"
  expect_once "${b_name}_mpi" "$b_place"
  expect "${b_name}_mpi" "$b_text"
}
bad syntax "syntax.pov:3:1: error:" "}" syntax.pov $SIZE
bad undefined "undefined.pov:3:21: error:" "Radius_typo" undefined.pov $SIZE
bad unsupported "unsupported.pov:3:1: error:" "tiff" unsupported.pov $SIZE
bad noinclude "noinclude.pov:1:" "no_such_file.inc" noinclude.pov $SIZE
bad missing "zrcube: cannot open scene file 'nowhere.pov'" \
  "No such file or directory" nowhere.pov $SIZE
[ -e syntax.png ] && fail "a failed parse wrote an image"

for args in "+Wabc" "+W0" "+W-5"; do
  serial "badopt$args" 2 "$ZRCUBE" scene.pov "$args"
  expect "badopt$args" \
    "zrcube: '$args': the width must be a whole number from 1 to 65535"
done
mpi badopt_mpi 2 2 scene.pov +H12x
expect_once badopt_mpi \
  "zrcube: '+H12x': the height must be a whole number from 1 to 65535"
serial unknown 2 "$ZRCUBE" scene.pov +Z1
expect unknown "zrcube: unknown option '+Z1' (try 'zrcube --help')"
serial noscene 2 "$ZRCUBE" +W10
expect noscene "zrcube: no scene file given (try 'zrcube --help')"

if [ "$failures" -ne 0 ]; then
  echo "test_cli.sh: $failures failure(s)" >&2
  exit 1
fi
echo "test_cli.sh: all checks passed"
