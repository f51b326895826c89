#!/bin/sh
# fade_power_probe.sh [ZRCUBE] - povray 3.7's fading through one clear
# block (shadow_fade_probe.pov, cases 28 and 29) for fade_power 0,
# between 0 and 1, 1 and below 0, fade_distance 0, 1 and 2, in shadow
# rays and camera rays (View=1).  Prints the light left (1 = none
# taken), povray's and, given ZRCUBE, zrcube's.  What povray 3.7.0.10
# printed: the formula 1 / (1 + (d / fade_distance)^fade_power) for
# every power in camera rays, power 0 included (0.5 at any thickness;
# case 29, fade_color red 0.5: 0.75), and only for powers above 0 in
# shadow rays (1.0 for 0 and -1); nothing for fade_distance 0:
#   P=0 TH=0.1/1/3 shadow 1.0000, view 0.5000
#   P=0.25 TH=0.1 0.6401, TH=1 0.5000, TH=3 0.4318 (shadow and view)
#   P=0.5 TH=0.1 0.7597, TH=1 0.5000, TH=3 0.3660
#   P=1 TH=0.1 0.9091, TH=1 0.5000, TH=3 0.2500
#   P=-1 TH=0.1 shadow 1.0000 view 0.0909, TH=3 shadow 1.0000 view 0.7500
#   FA=0 P=1 and P=0: 1.0000 both; FA=2 P=0: shadow 1.0000, view 0.5000
# (A negative fade_distance, -1 with power 1, gives 1.1111 at 0.1 and 0
# at 3 in both, the formula again: interior_fade_negative.sh measures it
# further, and zrcube follows it since session 13.)
# Usage: bench/conform/fade_power_probe.sh [build/bin/zrcube] (needs
# povray and /usr/bin/python3 with numpy).
set -eu
. "$(cd "$(dirname "$0")" && pwd)/probe_value.sh"
frow() { row "$*" "$@"; } # the declares are the label
for p in 0 0.25 0.5 1 -1; do
  for th in 0.1 1 3; do
    for v in 0 1; do
      frow Case=28 FA=1 PA=$p TH=$th View=$v
    done
  done
done
for d in "FA=0 PA=1" "FA=0 PA=0" "FA=2 PA=0"; do
  for v in 0 1; do
    frow Case=28 $d TH=3 View=$v
  done
done
for v in 0 1; do
  frow Case=29 FA=1 PA=0 TH=3 View=$v
done
