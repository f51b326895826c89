#!/bin/sh
# bench/photon_bailout.sh - the rule by which povray 3.7 drops a photon
# branch, measured from its statistics ("Surface photons stored" with
# +V) on bench/photon_bailout.pov's probes, and zrcube's agreement.
# Each line bisects one value of a probe (a reflection or transmit
# amount) for the smallest at which the branch's photons are stored,
# with povray and with zrcube, and prints the value the rule predicts.
#
# The rule found (2026-12-03, bench/results/photons-2026-12-03-bench.txt):
# a branch goes on while  S * max(C) >= adc_bailout,  where C is the
# branch's colour relative to what the photon left the light with (each
# reflection's amount with metallic tint, each filter met: a clear
# slab's transmit at both faces) and S the product of its reflections'
# weights: the largest channel of the larger of the reflection block's
# two colours, or with fresnel the amount at the angle (no metallic
# tint).  So one plain mirror needs R^2 >= adc_bailout (R >= 0.0627 at
# 1/255); the light's colour does not matter; a transmit counts once.
# Probe geometry: case 1's light meets the mirror at cos 0.6 (falloff
# weight (1 - 0.6)^VF, fresnel at ior FR from that angle).
#
# Usage: bench/photon_bailout.sh [BUILD]  (BUILD: a build folder, default
# build/).  Output: probe, povray's interval, zrcube's interval,
# predicted threshold.  About 10 minutes at load 10.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
. "$root/bench/zrexe.sh"
scene=$root/bench/photon_bailout.pov
work=$(mktemp -d "${TMPDIR:-/tmp}/photon_bailout.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM
STEPS=${STEPS:-11}

stored() { # renderer decls... -> photons stored (0 when none)
  r=$1; shift
  d=""; for x in "$@"; do d="$d Declare=$x"; done
  if [ "$r" = povray ]; then
    (cd "$work" && povray +I"$scene" +O"$work/p.png" +W16 +H12 -D -A +WT1 \
      +V $d </dev/null >"$work/log" 2>&1)
  else
    (cd "$work" && "$zrcube" +I"$scene" +O"$work/z.png" +W16 +H12 -D +WT1 \
      +V $d </dev/null >"$work/log" 2>&1)
  fi
  n=$(sed -n 's/^Surface photons stored: *//p' "$work/log" | tr -d ' \r')
  echo "${n:-0}"
}

bisect() { # renderer var decls... -> "lo hi": stored above hi, not at lo
  r=$1 v=$2; shift 2
  lo=0 hi=1
  i=0
  while [ $i -lt "$STEPS" ]; do
    mid=$(echo "scale=8; ($lo + $hi) / 2" | bc)
    n=$(stored "$r" "$v=$mid" "$@")
    if [ "$n" -gt 100 ]; then hi=$mid; else lo=$mid; fi
    i=$((i + 1))
  done
  echo "$lo $hi"
}

probe() { # name var predicted decls...
  name=$1 v=$2 pred=$3; shift 3
  p=$(bisect povray "$v" "$@")
  z=$(bisect zrcube "$v" "$@")
  printf '%s\t%s\t(%s]\t(%s]\t%s\n' "$name" "$v" "$(echo "$p" | tr ' ' ,)" \
    "$(echo "$z" | tr ' ' ,)" "$pred"
}

pred() { awk "BEGIN { a = 1 / 255; printf \"%.5f\", $1 }"; }
# Fresnel reflectance at cos 0.6 from air into ior n.
fres() { awk -v n="$1" 'BEGIN { c = 0.6; st = 0.8 / n; ct = sqrt(1 - st * st);
  rs = (c - n * ct) / (c + n * ct); rp = (ct - n * c) / (ct + n * c);
  printf "%.6f", 0.5 * (rs * rs + rp * rp) }'; }

printf 'probe\tvalue\tpovray\tzrcube\tpredicted\n'
probe mirror R "$(pred 'sqrt(a)')" Case=1
probe mirror_adc0.01 R "$(pred 'sqrt(0.01)')" Case=1 Adc=0.01
probe mirror_adc0.002 R "$(pred 'sqrt(0.002)')" Case=1 Adc=0.002
probe mirror_light3.43 R "$(pred 'sqrt(a)')" Case=1 LC=3.43
probe mirror_lightred R "$(pred 'sqrt(a)')" Case=1 LC=0.05
probe refl_red R "$(pred 'sqrt(a)')" Case=1 Refl=5 RR=1 RG=0 RB=0
probe refl_colour R "$(pred 'sqrt(a)')" Case=1 Refl=5 RR=0.5 RG=1 RB=0.25
probe falloff_0_R R "$(pred 'sqrt(a / 0.4)')" Case=1 Refl=1 VF=1
probe falloff_0_R_exp2 R "$(pred 'sqrt(a / 0.16)')" Case=1 Refl=1 VF=2
probe falloff_R_0 R "$(pred 'sqrt(a / 0.6)')" Case=1 Refl=2 VF=1
probe falloff_R_halfR R "$(pred 'sqrt(a / 0.8)')" Case=1 Refl=3 VM=0.5
probe falloff_R_2R R "$(pred 'sqrt(a / 2.8)')" Case=1 Refl=3 VM=2
f3=$(fres 3)
probe fresnel_ior3 R "$(pred "sqrt(a) / $f3")" Case=1 Refl=4 FR=3
f15=$(fres 1.5)
probe fresnel_halfR_R R "$(pred "sqrt(a) / (0.5 + 0.5 * $f15)")" Case=1 \
  Refl=6 VM=0.5 FR=1.5
probe metallic_grey0.5 R - Case=1 Met=1 Pg=0.5
probe metallic_grey0.25 R - Case=1 Met=1 Pg=0.25
probe metallic_red R "$(pred 'sqrt(a)')" Case=1 Met=1 PR=1 PG=0 PB=0
probe two_mirrors_R1_0.5 R "$(pred 'sqrt(a) / 0.5')" Case=2 R1=0.5
probe two_mirrors_R1_0.1 R "$(pred 'sqrt(a) / 0.1')" Case=2 R1=0.1
probe mirror_slab_R1_0.5 R "$(pred 'sqrt(a) / 0.5')" Case=3 R1=0.5
probe slab_enter Ta "$(pred 'a')" Case=4 Tb=1
probe slab_leave Tb "$(pred 'a / 0.5')" Case=4 Ta=0.5
