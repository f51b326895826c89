#!/bin/sh
# test_photon_bailout.sh - when a photon branch is dropped
# (lib/trace/photons.c, branch_kept), on bench/photon_bailout.pov's
# probes, against povray 3.7's statistics (bench/photon_bailout.sh
# bisects them): each case renders just above and just below the value
# at which povray stops storing the branch's photons (povray's interval
# +-2%), and the stored counts must say "stored" (over 100 photons)
# above and "dropped" (100 or fewer) below:
#   - one mirror at the default adc_bailout 1/255: povray keeps R 0.0630,
#     drops 0.0625 (R^2 >= adc_bailout, whatever the light's colour);
#   - two mirrors, the first of reflection 0.5: keeps 0.1255, drops 0.125;
#   - fresnel reflection {0, R} at ior 3: keeps 0.2402, drops 0.2397;
#   - metallic reflection 0.8 of a grey 0.5 pigment: keeps 0.0869, drops
#     0.0864;
#   - a clear slab whose transmit is Ta where photons enter: keeps 0.0044,
#     drops 0.0039 (a filter counts once, at each face).
# And a metal ball under a light 150000 units away stores as many
# photons as povray (15420, within 1%; it stored 134564 when the first
# hits, found from that far, were off the surface).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
scene=$srcdir/bench/photon_bailout.pov
fail=0
# stored DECLARES...: photons stored (0 on failure).
stored() {
  decl=""
  for d in "$@"; do decl="$decl Declare=$d"; done
  timeout 120 "$zrcube" +I"$scene" +Ob.png +W16 +H12 -D +WT1 +V \
    $decl </dev/null >b.log 2>&1 || { cat b.log >&2; echo 0; return; }
  n=$(sed -n 's/^Surface photons stored: *//p' b.log | tr -d ' ')
  echo "${n:-0}"
}
# edge WHAT VAR KEEP DROP DECLARES...
edge() {
  what=$1 var=$2 keep=$3 drop=$4
  shift 4
  nk=$(stored "$var=$keep" "$@")
  nd=$(stored "$var=$drop" "$@")
  if [ "$nk" -gt 100 ] && [ "$nd" -le 100 ]; then
    echo "ok: $what: $var $keep stores $nk, $drop stores $nd"
  else
    echo "FAIL: $what: $var $keep stores $nk, $drop stores $nd (povray: kept, dropped)"
    fail=1
  fi
}
edge "mirror" R 0.0640 0.0612 Case=1
edge "mirror, light rgb 3.43" R 0.0640 0.0612 Case=1 LC=3.43
edge "two mirrors, R1 0.5" R 0.1280 0.1225 Case=2 R1=0.5
edge "fresnel, ior 3" R 0.2450 0.2350 Case=1 Refl=4 FR=3
edge "metallic, grey 0.5" R 0.0887 0.0847 Case=1 Met=1 Pg=0.5
edge "clear slab, entering transmit" Ta 0.0045 0.0038 Case=4 Tb=1
n=$(stored Case=5)
if awk -v g="$n" 'BEGIN { d = g - 15420; if (d < 0) d = -d;
                          exit !(d <= 0.01 * 15420) }'; then
  echo "ok: metal ball under a far light: $n photons stored, povray 15420"
else
  echo "FAIL: metal ball under a far light: $n photons stored, povray 15420"
  fail=1
fi
exit $fail
