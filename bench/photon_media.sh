#!/bin/sh
# bench/photon_media.sh - the probes behind photons in media
# (lib/trace/photons.c: PLAIN photons and media photons): povray 3.7
# and zrcube on bench/photon_media/*.pov and tests/media_photons.pov,
# with their photon counts (+V) and the mean colour of regions of the
# 160x120 pictures (tests/region_mean.py).
#
# What they showed (2026-12-04, bench/results/photons-2026-12-04-s21.md):
#   - pass.pov: a glass-ball target inside a clear box: with the box not
#     a target povray stores no photon (the ball's photons meet the box
#     first and are dropped); with photons { target } on the box (no
#     refraction or reflection) 373555 stored of 317952 shot: photons go
#     through the box unbent, land on the floor and go through the ball;
#   - slab.pov BOXTARGET: the beam in a clear target box of media is
#     made of media photons: the same picture with the light's
#     media_interaction off, and dark (7-20 levels) with media 0: the
#     light reaches what is behind a clear target only as photons;
#     1016075 media photons at spacing 0.02, 839014 at media 100, 2,
#     488553 at 100, 4, 209371 at spacing 0.04 (max_steps 100 caps most
#     at factor 1): the step along a photon's path is spacing * factor;
#   - tests/media_photons.pov: a mirror without a photons block inside
#     the clear target box reflects the beam (12450 stored, as with
#     reflection on; 8627 with reflection off);
#   - smirror.pov: the same mirror under a refracting target lens
#     reflects nothing (povray 7847 stored, zrcube 7852 stopping there).
#
# Usage: bench/photon_media.sh [BUILD]  (BUILD: a build folder, default
# build/).  Output: per case the counts of both, then region means.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
. "$root/bench/zrexe.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/photon_media.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM
counts() { # log
  what='Number of photons shot\|Surface photons stored\|Media photons stored'
  tr '\r' '\n' <"$1" | sed -n "s/^\($what\): *\([0-9]*\).*/\2/p" |
    tr '\n' ' '
}
mean() { # png region
  /usr/bin/python3 "$root/tests/region_mean.py" "$1" "$2=0,0,0" --tol 1e9 |
    sed 's/.* mean \([^ ]*\), want.*/\1/'
}
run_both() { # name file regions declares...
  name=$1 file=$2 regions=$3
  shift 3
  decl=""
  for d in "$@"; do decl="$decl Declare=$d"; done
  dir=$(dirname "$file")
  (cd "$dir" && nice -n 10 povray +I"$file" +O"$work/p.png" +W160 +H120 -D \
    -A +WT1 +V $decl </dev/null >"$work/p.log" 2>&1)
  (cd "$dir" && nice -n 10 "$zrcube" +I"$file" +O"$work/z.png" +W160 \
    +H120 -D +WT1 +V $decl </dev/null >"$work/z.log" 2>&1)
  echo "== $name: povray $(counts "$work/p.log")|" \
    "zrcube $(counts "$work/z.log")"
  for r in $regions; do
    echo "   $r  povray $(mean "$work/p.png" "$r")" \
      " zrcube $(mean "$work/z.png" "$r")"
  done
}
b=$root/bench/photon_media
run_both pass_plain "$b/pass.pov" "55:65,40:120"
run_both pass_boxtarget "$b/pass.pov" "55:65,40:120" BOXTARGET=1
run_both slab_boxtarget "$b/slab.pov" "55:65,16:72 55:65,88:152" BOXTARGET=1
run_both slab_boxtarget_f2 "$b/slab.pov" "55:65,16:72 55:65,88:152" \
  BOXTARGET=1 FACTOR=2
run_both slab_media0 "$b/slab.pov" "55:65,16:72 55:65,88:152" BOXTARGET=1 \
  MEDIA_PH=0
run_both slab_no_interaction "$b/slab.pov" "55:65,16:72 55:65,88:152" \
  BOXTARGET=1 NOMI=1
run_both lens "$b/lens.pov" "55:65,80:150"
run_both smirror "$b/smirror.pov" "40:80,100:160"
for c in 1 2 3 4; do
  run_both mirror_case$c "$root/tests/media_photons.pov" \
    "15:35,75:85 55:65,20:60 45:55,100:150" Case=$c
done
