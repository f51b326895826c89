#!/bin/sh
# exit_fresnel_probe.sh [ZRCUBE] - the ray counts behind the exit-Fresnel
# rule (lib/trace/shade.c, out_within): tests/exit_fresnel.pov at 16x12
# by povray 3.7 (+V) and by zrcube, for each case.  povray counts a
# reflected ray where the Fresnel share is left at rounding size (~1e-32,
# the iors equal) and then saves it by adc_bailout ("Saved"); zrcube
# spawns none there, so povray's reflected less saved is zrcube's
# reflected.  Cases 2, 5, 6 (the glass inside another object) have no
# inside reflection; 1, 3, 4, 8 have one at every back face.
# Run from the source tree.
zr=${1:-build/bin/zrcube}
scene=tests/exit_fresnel.pov
printf 'case\tpov_reflected\tpov_saved\tpov_refracted\tzr_reflected\tzr_refracted\n'
for c in 1 2 3 4 5 6 7 8 9; do
  p=$(povray +I$scene -O- +W16 +H12 -D -A +WT1 +V Declare=Case=$c 2>&1)
  z=$("$zr" +I$scene +O/tmp/exit_fresnel_probe_$$.png +W16 +H12 -D +WT1 +V \
      Declare=Case=$c 2>&1)
  rm -f /tmp/exit_fresnel_probe_$$.png
  pr=$(echo "$p" | awk '/^Reflected Rays:/ {print $3}')
  ps=$(echo "$p" | awk '/^Rays:/ {print $4}')
  pt=$(echo "$p" | awk '/^Refracted Rays:/ {print $3}')
  zr_r=$(echo "$z" | awk '/^Reflected Rays:/ {print $3}')
  zr_t=$(echo "$z" | awk '/^Refracted Rays:/ {print $3}')
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' $c "${pr:-0}" "${ps:-0}" "${pt:-0}" \
    "${zr_r:-0}" "${zr_t:-0}"
done
