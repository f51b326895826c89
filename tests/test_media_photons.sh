#!/bin/sh
# test_media_photons.sh - photons in media (global photons { media N, F },
# lib/trace/photons.c) on tests/media_photons.pov, a spotlight through a
# clear target box of scattering media with a mirror inside:
#   1. the beams' brightness in regions of the picture against povray
#      3.7's recorded means (tests/region_mean.py, 12 levels): the beam
#      a mirror without a photons block reflects (media photons, which
#      main did not store: 16 there against povray's 193), a red-
#      reflecting cyan filter, reflection off (no beam), and media 0
#      (the box's media left dark behind its target: povray 8.7, main 189),
#      Mie murky scattering (the phase for each photon's direction);
#   2. the same bytes with 1 and 2 threads and under mpirun -n 2;
#   3. bad 'media' values stop with a located error.
# With povray installed its own renders are compared too (SSIM 0.95;
# main: 0.73, 0.86, 0.85 for cases 1 to 3).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/media_photons.pov" . || exit 99
fail=0
render() { # case output threads
  timeout 120 "$zrcube" +Imedia_photons.pov +O"$2" +W160 +H120 -D +WT"$3" \
    Declare=Case="$1" </dev/null >"$2.log" 2>&1 ||
    { echo "zrcube failed on case $1:" >&2; cat "$2.log" >&2; exit 1; }
}
# povray 3.7's means (rows 15:35 above the mirror, where its reflected
# beam goes; rows 55:65 the incoming beam; rows 45:55 behind the mirror).
recorded_1="15:35,75:85=192.6,192.6,192.6 55:65,20:60=192.6,192.6,192.6"
recorded_2="15:35,75:85=192.7,18.6,18.6 55:65,20:60=192.8,192.8,192.8 45:55,100:150=30.5,190.2,190.2"
recorded_3="15:35,75:85=24.3,24.3,24.3 55:65,20:60=192.8,192.8,192.8"
# Case 4 within 20 levels: zRcube's beam region is 26 (main: 189), the
# floor's grazing photons spread over it, where povray's floor stays dark.
recorded_4="55:65,20:60=8.7,8.7,8.7"
recorded_5="15:35,75:85=140.2,140.2,140.2 55:65,20:60=140.5,140.5,140.5"
for c in 1 2 3 4 5; do
  render $c z$c.png 1
  eval "want=\$recorded_$c"
  echo "case $c:"
  tol=12
  [ $c = 4 ] && tol=20
  /usr/bin/python3 "$srcdir/tests/region_mean.py" z$c.png $want --tol $tol ||
    fail=1
  if command -v povray >/dev/null 2>&1 &&
     timeout 120 povray +Imedia_photons.pov +Op$c.png +W160 +H120 -D -A \
       +WT1 -GA Declare=Case=$c </dev/null >p$c.log 2>&1; then
    # Case 4's dark box is mostly noise to SSIM: 0.46 (main: 0.32).
    min=0.95
    [ $c = 4 ] && min=0.4
    if out=$("$imgcmp" z$c.png p$c.png --ssim-min $min); then
      echo "ok: case $c against povray: $out"
    else
      echo "FAIL: case $c against povray: $out"
      fail=1
    fi
  fi
done
# Photons are shot on every rank before the render, in the same order.
render 2 t2.png 2
if cmp -s z2.png t2.png; then
  echo "ok: 1 and 2 threads give the same bytes"
else
  echo "FAIL: 1 and 2 threads differ"
  fail=1
fi
if [ "${ZR_WITH_MPI:-yes}" != no ] && command -v mpirun >/dev/null 2>&1; then
  : "${OMPI_ALLOW_RUN_AS_ROOT:=1}" "${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:=1}"
  : "${OMPI_MCA_rmaps_base_oversubscribe:=1}"
  export OMPI_ALLOW_RUN_AS_ROOT OMPI_ALLOW_RUN_AS_ROOT_CONFIRM \
    OMPI_MCA_rmaps_base_oversubscribe
  if ASAN_OPTIONS="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}" \
     timeout 300 mpirun -n 2 "$zrcube" +Imedia_photons.pov +Om2.png +W160 \
       +H120 -D +WT1 Declare=Case=2 </dev/null >m2.log 2>&1 &&
     cmp -s z2.png m2.png; then
    echo "ok: mpirun -n 2 gives the same bytes"
  else
    echo "FAIL: mpirun -n 2 differs or failed: $(tail -1 m2.log)"
    fail=1
  fi
fi
# Bad values stop with a located message.
while IFS='|' read -r text expect; do
  printf '%s\nsphere { 0, 1 }\n' "$text" >bad.pov
  if "$zrcube" +Ibad.pov +Obad.png +W8 +H8 -D >bad.log 2>&1; then
    echo "FAIL: '$text' was accepted"
    fail=1
  elif grep -q "bad.pov:1:[0-9]*: error: .*$expect" bad.log; then
    echo "ok: '$text': $(head -1 bad.log)"
  else
    echo "FAIL: '$text': $(head -1 bad.log)"
    fail=1
  fi
done <<'BAD'
global_settings { photons { count 10 media -1 } }|whole number of steps from 0 to 1e6, not -1
global_settings { photons { count 10 media 2.5 } }|whole number of steps from 0 to 1e6, not 2.5
global_settings { photons { count 10 media 100, 0 } }|'media 100, 0': the spacing factor must be above 0
global_settings { photons { count 10 media 100, -2 } }|'media 100, -2': the spacing factor must be above 0
global_settings { photons { count 10 media 1, 2, 3 } }|'media' in photons { } takes up to 2 numbers
BAD
exit $fail
