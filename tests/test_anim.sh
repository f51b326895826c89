#!/bin/sh
# test_anim.sh - animation and render control end to end (issue 12):
#   - a 10-frame animation through mpirun -n 2 (whole frames per rank,
#     and rows split across ranks) gives the same bytes as the frames
#     rendered one by one with +K (the clock of each frame);
#   - output names numbered as POV-Ray numbers them (out01.png ..
#     out10.png; the subset +SF/+EF; +KC's clock);
#   - a partial render (+SR +ER +SC +EC) is the whole render's pixels
#     inside the window and black outside;
#   - +O- writes the image to standard output; Declare= reaches the
#     scene; -GW silences warnings, +GSfile copies statistics to a file;
#   - every INI file POV-Ray ships renders a tiny image (when installed).
set -u
TEST_NAME=test_anim
. "$(dirname "$0")/cli_env.sh"
cd "$work" || exit 99

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# run NAME COMMAND...: must succeed; output in NAME.out and NAME.err.
run() {
  r_name=$1
  shift
  "$@" >"$r_name.out" 2>"$r_name.err"
  got=$?
  if [ "$got" -ne 0 ]; then
    fail "$r_name: exit status $got"
    sed "s/^/  $r_name: /" "$r_name.err" >&2
  fi
  if grep -q -e 'Sanitizer' -e 'runtime error:' "$r_name.err"; then
    fail "$r_name: sanitizer report"
  fi
}
mpi() {
  m_name=$1 m_ranks=$2
  shift 2
  run "$m_name" env ASAN_OPTIONS="$MPI_ASAN" $MPIRUN -n "$m_ranks" \
    "$ZRCUBE" "$@"
}
same() {
  cmp -s "$1" "$2" || fail "$1 and $2 differ"
}

cat >anim.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.3 } }
sphere { <2 * clock - 1, 0, 0>, 0.6
  pigment { rgb <1, clock, 1 - clock> } finish { phong 0.5 } }
#if (clock_on)
  #debug concat("frame ", str(frame_number, 0, 0), " of ",
                str(initial_frame, 0, 0), "..", str(final_frame, 0, 0),
                " delta ", str(clock_delta, 0, 4), "\n")
#end
POV

size="+W40 +H30 +A0.1 -D"
# The frames one by one, with the clock POV-Ray gives frame k of 10:
# (k - 1) / 9.
for k in 1 2 3 4 5 6 7 8 9 10; do
  clock=$(awk "BEGIN { printf \"%.17g\", ($k - 1) / 9 }")
  run "one$k" "$ZRCUBE" anim.pov $size "+K$clock" "+Oone$k.png"
done
# Whole frames per rank (the default with more frames than ranks).
mpi anim_frames 2 anim.pov $size +KFF10 +Oframes.png
# Rows split across ranks for each frame.
mpi anim_rows 2 anim.pov $size +KFF10 +Orows.png --frames-per-rank=no
for k in 01 02 03 04 05 06 07 08 09 10; do
  n=${k#0}
  same "frames$k.png" "one$n.png"
  same "rows$k.png" "one$n.png"
done
[ -e frames1.png ] && fail "frame names must have two digits with +KFF10"
grep -q "frame 7 of 1..10 delta 0.1111" anim_frames.err ||
  fail "anim_frames: #debug lacks frame 7's identifiers"

# Subsets and cyclic animation (measured with povray 3.7.0: +KFF12
# +KC gives final_frame 13 and clock_delta 1/12).
run subset "$ZRCUBE" anim.pov $size +KFF12 +KC +SF0.5 +EF0.6 +Osub.png
ls sub*.png | tr '\n' ' ' | grep -q '^sub06.png sub07.png $' ||
  fail "subset: wrote $(ls sub*.png | tr '\n' ' ')"
grep -q "frame 6 of 1..13 delta 0.0833" subset.err ||
  fail "subset: cyclic identifiers wrong: $(cat subset.err)"

# A partial render: the window's pixels are the whole render's (pass 1
# covers a margin, so antialiasing decides the same), black elsewhere.
run whole "$ZRCUBE" anim.pov $size +K0.5 +Owhole.ppm
run part "$ZRCUBE" anim.pov $size +K0.5 +SR0.25 +ER20 +SC5 +EC0.75 \
  +Opart.ppm
# Compare the raw pixels: 40x30 P6 files have a 15-byte header.
for f in whole part; do
  tail -c 3600 "$f.ppm" | od -A n -t u1 -v | tr -s ' ' '\n' | sed '/^$/d' \
    >"$f.bytes"
done
paste whole.bytes part.bytes | awk '
  { i = NR - 1; p = int(i / 3); x = p % 40; y = int(p / 40)
    inside = (y >= 7 && y < 20 && x >= 4 && x < 30)
    if (inside && $1 != $2) bad++
    if (!inside && $2 != 0) bad++ }
  END { exit bad > 0 }' || fail "partial render differs from the window"

# +O-: the image on standard output, the same bytes as a file.
"$ZRCUBE" anim.pov $size +K0.5 +FN +O- >stdout.png 2>stdout.err ||
  fail "+O- failed: $(cat stdout.err)"
run file "$ZRCUBE" anim.pov $size +K0.5 +Ofile.png
same stdout.png file.png

# Declare= reaches the scene; text streams.
cat >declare.pov <<'POV'
#debug concat("RAD is ", str(RAD, 0, 1), "\n")
#warning "a warning"
camera { location -2 * z look_at 0 } sphere { 0, 1 pigment { rgb 1 } }
POV
run declare "$ZRCUBE" declare.pov +W8 +H6 Declare=RAD=2.5 -GW +V \
  +GSstats.txt +Odeclare.png
grep -q "RAD is 2.5" declare.err || fail "declare: $(cat declare.err)"
grep -q "a warning" declare.err && fail "-GW: the warning was shown"
grep -q "Render Statistics" stats.txt ||
  fail "+GSstats.txt: no statistics in the file"

# +HIfile: a header include, not +H (found where #include looks).
echo '#declare HeaderColour = rgb <0, 1, 0>;' >head.inc
echo 'camera { location -3 * z look_at 0 } sphere { 0, 1 pigment { HeaderColour } }' >header.pov
run header "$ZRCUBE" header.pov +HIhead.inc +W8 +H6 +Oheader.png

# Every INI file POV-Ray ships, tiny (later options win).
inidir=/usr/share/povray-3.7/ini
if [ -d "$inidir" ]; then
  for ini in "$inidir"/*.ini; do
    name=$(basename "$ini" .ini)
    "$ZRCUBE" anim.pov "+L$inidir" "$ini" +W8 +H6 -A -C \
      +FN "+Oini_$name.png" >"ini_$name.out" 2>"ini_$name.err"
    st=$?
    if [ "$st" -ne 0 ] &&
      ! grep -q "Targa output is not supported" "ini_$name.err"; then
      fail "stock $name.ini: status $st: $(cat "ini_$name.err")"
    fi
  done
fi

[ "$failures" -eq 0 ] || { echo "test_anim.sh: $failures failure(s)" >&2; exit 1; }
exit 0
