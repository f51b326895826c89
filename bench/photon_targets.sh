#!/bin/sh
# bench/photon_targets.sh - photons shot and stored by povray 3.7 and by
# zrcube (both with +V: "Number of photons shot", "Surface photons
# stored"), on tests/photon_targets.pov's cases (the numbers
# tests/test_photon_targets.sh records) and, with --stock, on the stock
# scenes advanced/benchmark and advanced/grenadine.  The photon pass does
# not depend on the image size, so the scenes render at 16x12.
#
# What the probes showed (2026-12-02, bench/results/photons-2026-12-02-s7.txt):
#   - two clear target slabs, the second over half of the first: povray
#     stores the photons of the union of their areas (32512 at spacing
#     0.02; one slab: 20039), not of both (the overlap lit twice): a
#     photon shot at one target that meets another first is dropped;
#   - a glass ball (reflection and refraction): stored photons at
#     max_trace_level 3, 4, 5, 6 are 4028, 4028, 5878, 8013, zrcube's at
#     n + 1 when the hit from the light counted as level 0;
#   - a shadowless light added shoots no photons (count unchanged), a
#     plain one doubles them.
#
# Usage: bench/photon_targets.sh [--stock] [BUILD]  (BUILD: a build
# folder, default build/).  Output: one line per case,
#   case  povray_shot  povray_stored  zrcube_shot  zrcube_stored
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
stock=0
[ "${1:-}" = "--stock" ] && { stock=1; shift; }
build=${1:-$root/build}
. "$root/bench/zrexe.sh"
scene=$root/tests/photon_targets.pov
work=$(mktemp -d "${TMPDIR:-/tmp}/photon_targets.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM
counts() { # log: "shot stored"
  s=$(sed -n 's/^Number of photons shot: *//p' "$1" | tr -d ' \r')
  t=$(sed -n 's/^Surface photons stored: *//p' "$1" | tr -d ' \r')
  echo "${s:--} ${t:--}"
}
run_both() { # name dir file declares...
  name=$1 dir=$2 file=$3
  shift 3
  decl=""
  for d in "$@"; do decl="$decl Declare=$d"; done
  (cd "$dir" && povray +I"$file" +O"$work/p.png" +W16 +H12 -D -A +WT1 +V \
    $decl </dev/null >"$work/p.log" 2>&1)
  (cd "$dir" && "$zrcube" +I"$file" +O"$work/z.png" +W16 +H12 -D +WT1 +V \
    $decl </dev/null >"$work/z.log" 2>&1)
  printf '%s\t%s\t%s\n' "$name" "$(counts "$work/p.log" | tr ' ' '\t')" \
    "$(counts "$work/z.log" | tr ' ' '\t')"
}
printf 'case\tpovray_shot\tpovray_stored\tzrcube_shot\tzrcube_stored\n'
run_both one_slab "$root/tests" "$scene" Case=1
run_both two_slabs "$root/tests" "$scene" Case=2
for m in 3 4 5 6; do
  run_both ball_mtl$m "$root/tests" "$scene" Case=3 Mtl=$m
done
run_both ball_shadowless "$root/tests" "$scene" Case=4
run_both ball_two_lights "$root/tests" "$scene" Case=5
run_both textured_mesh "$root/tests" "$scene" Case=6
if [ $stock = 1 ]; then
  s=/usr/share/povray-3.7/scenes/advanced
  run_both benchmark "$s/benchmark" benchmark.pov
  run_both grenadine "$s/grenadine" grenadine.pov
fi
