#!/bin/sh
# test_formats_povray.sh - issue 12's image formats against POV-Ray 3.7,
# both ways:
#   - writing: one scene (a light brighter than 1, so HDR and OpenEXR
#     hold values above white) rendered by povray and by zrcube with
#     +FJ, +FT, +FC, +FB, +FH and +FE; each zRcube file is read back by
#     zr_image_read (tests/imgcmp) and compared with POV-Ray's file of
#     the same format: SSIM >= 0.98, no 8x8 block off by more than 0.02
#     (the two renders match to 1.0000 in PNG; the margin is for JPEG's
#     own rounding);
#   - reading: povray writes a picture as TGA, BMP (+FB), JPEG, HDR and
#     OpenEXR; a scene maps each one onto a plane with image_map and its
#     type keyword (tga, bmp, jpeg, hdr, exr), and the two renders must
#     agree as above;
#   - a height field from a BMP file povray wrote (colour pixels: the
#     red and green bytes make the height).
# 160x120, no antialiasing, one thread; skips (77) without povray.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
ZR_NEEDS_POVRAY=1
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
inc=/usr/share/povray-3.7/include
exr=yes
"$zrcube" +I/dev/null +FE 2>&1 | grep -q "built without OpenEXR" && exr=no

cat >scene.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <5, 10, -5> rgb 1 }
background { rgb <0.2, 0.3, 0.6> }
plane { y, 0 pigment { checker rgb 1 rgb <0.8, 0.1, 0.1> } }
sphere { <0, 0.8, 0>, 0.8 pigment { rgb <0.2, 0.9, 0.3> }
  finish { phong 0.8 } }
sphere { <1.4, 0.4, -0.5>, 0.4 pigment { rgb 4 }
  finish { ambient 1 diffuse 0 } }
POV

passed=0
failed=0
pov() { # scene output options...
  s=$1 o=$2
  shift 2
  timeout 120 povray +I"$s" +O"$o" +W160 +H120 -D -A +WT1 -GA +L"$inc" \
    "$@" </dev/null >>pov.log 2>&1
}
zr() {
  s=$1 o=$2
  shift 2
  timeout 120 "$zrcube" +I"$s" +O"$o" +W160 +H120 -D +WT1 "$@" \
    </dev/null >>zr.log 2>&1
}
check() { # label ours theirs
  if r=$("$imgcmp" "$2" "$3" --ssim-min 0.98 --delta-max 0.02 2>&1); then
    echo "$1: $r ok"
    passed=$((passed + 1))
  else
    echo "$1: $r FAIL"
    failed=$((failed + 1))
  fi
}

for f in J:jpg T:tga C:tga B:bmp H:hdr E:exr; do
  t=${f%%:*} ext=${f#*:}
  [ "$t" = E ] && [ "$exr" = no ] && { echo "+FE: no OpenEXR in this build, skipped"; continue; }
  pov scene.pov "pov_$t.$ext" "+F$t" || { echo "povray +F$t failed" >&2; tail -3 pov.log >&2; exit 99; }
  if ! zr scene.pov "zr_$t.$ext" "+F$t"; then
    echo "write +F$t: zrcube failed: $(tail -1 zr.log)"
    failed=$((failed + 1))
    continue
  fi
  check "write +F$t" "zr_$t.$ext" "pov_$t.$ext"
done
# BMP: the same 54 header bytes as povray's (24 bits, bottom up).
if [ -f zr_B.bmp ] && [ -f pov_B.bmp ]; then
  if cmp -s -n 54 zr_B.bmp pov_B.bmp; then
    echo "+FB header: same as povray's ok"
    passed=$((passed + 1))
  else
    echo "+FB header: differs from povray's FAIL"
    failed=$((failed + 1))
  fi
fi

# The picture to map: colours and a highlight above 1 for HDR and EXR.
cat >pic.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0>
  right x up y }
plane { z, 0 pigment { gradient x color_map { [0 rgb <1, 0.2, 0>]
  [0.5 rgb <0.1, 0.6, 1>] [1 rgb <0.9, 0.9, 0.1>] } }
  finish { ambient 1 diffuse 0 } }
disc { <0.7, 0.6, -0.01>, z, 0.15 pigment { rgb <3, 2, 1> }
  finish { ambient 1 diffuse 0 } }
POV
for f in tga:T bmp:B jpeg:J hdr:H exr:E; do
  kw=${f%%:*} t=${f#*:}
  [ "$t" = E ] && [ "$exr" = no ] && { echo "exr image_map: no OpenEXR in this build, skipped"; continue; }
  timeout 60 povray +Ipic.pov +Opic_$kw +W64 +H48 -D -A +WT1 -GA "+F$t" \
    </dev/null >>pov.log 2>&1 || { echo "povray +F$t failed" >&2; exit 99; }
  file=$(ls pic_$kw.* | head -1)
  cat >"map_$kw.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 0.5, -1.2> look_at <0.5, 0.5, 0> }
plane { z, 0 pigment { image_map { $kw "$file" } }
  finish { ambient 1 diffuse 0 } }
POV
  pov "map_$kw.pov" "povmap_$kw.png" || { echo "povray map_$kw failed" >&2; tail -3 pov.log >&2; exit 99; }
  if ! zr "map_$kw.pov" "zrmap_$kw.png"; then
    echo "read $kw: zrcube failed: $(tail -2 zr.log)"
    failed=$((failed + 1))
    continue
  fi
  check "read $kw ($file)" "zrmap_$kw.png" "povmap_$kw.png"
done
cat >hfpic.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0>
  right x up y }
plane { z, 0 pigment { function { 0.5 + 0.5 * sin(x * 9) * cos(y * 7) }
  color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }
POV
cat >hf.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 1.6, -0.9> look_at <0.5, 0.1, 0.5> }
light_source { <3, 5, -2> rgb 1 }
height_field { bmp "hf.bmp" smooth pigment { rgb <0.9, 0.8, 0.6> }
  scale <1, 0.3, 1> }
POV
timeout 60 povray +Ihfpic.pov +Ohf.bmp +FB +W64 +H64 -D -A +WT1 -GA \
  </dev/null >>pov.log 2>&1 || { echo "povray +FB failed" >&2; exit 99; }
pov hf.pov hf_pov.png || { echo "povray hf.pov failed" >&2; exit 99; }
if zr hf.pov hf_zr.png; then
  check "height_field bmp" hf_zr.png hf_pov.png
else
  echo "height_field bmp: zrcube failed: $(tail -2 zr.log)"
  failed=$((failed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
