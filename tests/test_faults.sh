#!/bin/sh
# test_faults.sh - hostile input and faults (issue 10): each case asserts
# the exit status, the message, and that a file written before the run
# (old.png, and the scene itself) is byte for byte unchanged.
#   budgets: branching macro recursion and nested #zfor stop on the work
#     budget; #include "/dev/zero" and an oversized include stop on the
#     file size cap; array[100000000] is cheap, filling it past
#     --memory-limit stops, and so does a large image map;
#   messages: control bytes are escaped, an error on a 2 MB line prints
#     a bounded window with the caret;
#   values: 1e400, inf/inf, a zero-length cylinder or cone and a camera
#     looking at its own location stop; a negative sphere radius and a
#     degenerate triangle warn;
#   faults: kill -9 of one rank under mpirun, SIGINT and SIGTERM, a full
#     disk (ulimit -f), too little memory (ulimit -v, normal build only:
#     sanitizers reserve terabytes of address space), a corrupt radiosity
#     file, a corrupt or truncated image of each format read (PNG JPEG GIF
#     TGA PPM PFM POT HDR EXR BMP TIFF), an 11000 x 11000 height field in
#     a 256 MiB budget, and a scene of 10^6 objects, which must render.
#
# Environment: ZR_BUILDDIR (where bin/zrcube is), MPIRUN, ZR_TEST_CFLAGS
# (to tell a sanitizer build).
set -u
sanitized=0
case "${ZR_TEST_CFLAGS:-}" in *-fsanitize*) sanitized=1 ;; esac
TEST_NAME=test_faults
. "$(dirname "$0")/cli_env.sh"
cd "$work" || exit 99

failures=0
cases=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# A file that must survive every run.
printf 'old picture bytes\n' > old.png
cp old.png old.ref

# run NAME WANT ARGS...: zrcube ARGS with NAME.out / NAME.err; WANT is
# an exit status.  Checks that old.png is intact and no temporary file
# was left beside it.
run() {
  r_name=$1 r_want=$2
  shift 2
  cases=$((cases + 1))
  r_start=$(date +%s)
  "$ZRCUBE" "$@" >"$r_name.out" 2>"$r_name.err"
  got=$?
  echo "$r_name: status $got in $(( $(date +%s) - r_start )) s"
  [ "$got" -eq "$r_want" ] ||
    { fail "$r_name: exit status $got, expected $r_want"
      sed "s/^/  $r_name: /" "$r_name.err" | head -20 >&2; }
  if grep -q -e 'Sanitizer' -e 'runtime error:' "$r_name.err"; then
    fail "$r_name: sanitizer report"
  fi
  intact "$r_name"
}

intact() {
  cmp -s old.png old.ref || fail "$1: old.png changed"
  leftovers=$(ls -a | grep -c -e '\.tmp' -e '^\.zr' )
  [ "$leftovers" -eq 0 ] || fail "$1: temporary files left: $(ls -a)"
}

# expect NAME TEXT: NAME.err holds TEXT (a fixed string).
expect() {
  grep -q -F -e "$2" "$1.err" ||
    { fail "$1: stderr lacks '$2'"; sed "s/^/  $1: /" "$1.err" | head >&2; }
}

scene_head='camera { location <0, 0, -5> look_at 0 }
light_source { <5, 5, -5> rgb 1 }'

# ---- 4: the work budget ------------------------------------------------
cat > recurse.pov <<'EOF'
#macro M(N) #if (N > 0) M(N - 1) M(N - 1) #end #end
M(60)
EOF
run recurse 1 recurse.pov --max-work=100000 -q +Orecurse.png
expect recurse "recurse.pov:1:"
expect recurse "work budget of 100000 steps"
expect recurse "--max-work"
[ -e recurse.png ] && fail "recurse: an image was written"

cat > zfor.pov <<'EOF'
#zfor (1000000) #zfor (1000000) #zfor (1000000) #zend #zend #zend
EOF
run zfor 1 zfor.pov --max-work=100000 -q +Ozfor.png
expect zfor "zfor.pov:1:"
expect zfor "work budget"

# The old option name still sets the same budget.
cat > endless.pov <<'EOF'
#declare I = 0; #while (I < 1) #declare J = I; #end
EOF
run endless 1 endless.pov --max-loop-iterations=1000 -q +Oendless.png
expect endless "endless.pov:1:"
expect endless "work budget of 1000 steps"

# ---- 3: file size cap, arrays, memory budget ---------------------------
printf '#include "/dev/zero"\n' > zero.pov
run devzero 1 zero.pov --max-file-size=1M -q +Ozero.png
# The I/O policy refuses devices by name before any byte is read.
expect devzero "zero.pov:1:10: error: cannot read include file: '/dev/zero' is a character device"

head -c 200000 /dev/zero | tr '\0' ' ' > big.inc
printf '#include "big.inc"\nsphere { 0, 1 }\n' > bigincl.pov
run bigincl 1 bigincl.pov --max-file-size=100K -q +Obigincl.png
expect bigincl "cannot read include file"
expect bigincl "larger than the file size limit"
run bigincl_ok 0 bigincl.pov --parse-only
run bigscene 1 big.inc --max-file-size=100K -q +Obigscene.png
expect bigscene "cannot open scene file 'big.inc': it is larger than the file size limit of 100 KiB"

cat > hugearray.pov <<EOF
$scene_head
#declare A = array[100000000];
#declare A[99999999] = 1;
sphere { 0, A[99999999] pigment { rgb 1 } }
EOF
run hugearray 0 hugearray.pov --parse-only --memory-limit=64M
grep -q '^objects: 1$' hugearray.out || fail "hugearray: no sphere"

cat > fillarray.pov <<'EOF'
#declare A = array[10000000];
#for (I, 0, 9999999) #declare A[I] = I; #end
EOF
run fillarray 1 fillarray.pov --parse-only --memory-limit=16M
expect fillarray "fillarray.pov:2:"
expect fillarray "past the memory budget of 16 MiB"
expect fillarray "--memory-limit"

# A 4000 x 4000 colour image map (48 MB of codes) against a 32 MiB
# budget; the same picture in grey is kept one byte a pixel (16 MB, and
# its copy in the scene), so it fits in 40 MiB (28 bytes a pixel before).
{ printf 'P6\n4000 4000\n255\n'; head -c 48000000 /dev/zero; } > big.ppm
cat > bigimage.pov <<EOF
$scene_head
plane { z, 1 pigment { image_map { ppm "big.ppm" } } }
EOF
run bigimage 1 bigimage.pov --parse-only --memory-limit=32M
expect bigimage "4000x4000 image"
expect bigimage "past the memory budget"
{ printf 'P5\n4000 4000\n255\n'; head -c 16000000 /dev/zero; } > big.pgm
printf '%s\nplane { z, 1 pigment { image_map { ppm "big.pgm" } } }\n' \
  "$scene_head" > grey_image.pov
run grey_image 0 grey_image.pov --parse-only --memory-limit=40M
printf '%s\nplane { z, 1 normal { bump_map { ppm "big.pgm" } } }\n' \
  "$scene_head" > grey_bump.pov
run grey_bump 0 grey_bump.pov --parse-only --memory-limit=40M

# An 11000 x 11000 grey PNG (about 150 KB) as a height field: its
# samples stay one byte each (121 MB) and the tracer walks a block
# hierarchy over them (2.5 MB), so it renders within a 256 MiB budget
# (it took 3.55 GB, then 16.9 GB, as triangles); 64 MiB stops it.
if "${ZR_BUILDDIR:-.}/tests/mkhfpng" hf.png 11000; then
  printf '%s\n%s\n' 'camera { location <0.5, 1.5, -1> look_at <0.5, 0, 0.5> }
light_source { <5, 5, -5> rgb 1 }' \
    'height_field { png "hf.png" pigment { rgb 1 } }' > hfbig.pov
  start=$(date +%s)
  run hfbig 0 hfbig.pov +W64 +H48 -q +WT1 --memory-limit=256M +Ohfbig.png
  [ -s hfbig.png ] || fail "hfbig: no image"
  echo "11000 x 11000 height field: $(( $(date +%s) - start )) s"
  run hfbig_budget 1 hfbig.pov +W64 +H48 -q --memory-limit=64M \
    +Ohfbig2.png
  expect hfbig_budget "the 11000x11000 height field 'hf.png'"
  expect hfbig_budget "past the memory budget of 64 MiB"
  [ -e hfbig2.png ] && fail "hfbig_budget: an image was written"
  rm -f hf.png
else
  fail "mkhfpng: no picture"
fi

# ---- 5 and 6: messages -------------------------------------------------
printf 'sphere { 0, 1 \033[2J }\n' > escape.pov
run escape 1 escape.pov --parse-only
expect escape '\x1b'
if tr -d '\n' < escape.err | grep -q "$(printf '\033')"; then
  fail "escape: a raw ESC byte reached stderr"
fi

{ printf '#declare A = '; head -c 300000 /dev/zero | tr '\0' 1; \
  printf ' + foo;\n'; } > longline.pov
run longline 1 longline.pov --parse-only
expect longline "longline.pov:1:300017: error: undefined identifier 'foo'"
size=$(wc -c < longline.err)
[ "$size" -lt 1000 ] || fail "longline: $size bytes of message"
# The caret sits under the 'f' of foo in the window.
quote=$(sed -n 2p longline.err)
caret=$(sed -n 3p longline.err)
qcol=$(printf '%s\n' "$quote" | awk '{print index($0, "foo")}')
ccol=$(printf '%s\n' "$caret" | awk '{print index($0, "^")}')
[ "$qcol" -gt 0 ] && [ "$qcol" -eq "$ccol" ] ||
  fail "longline: caret at $ccol, 'foo' at $qcol"
expect longline "| ...1111"

# ---- 8: values ---------------------------------------------------------
value_case() {
  printf '%s\n%s\n' "$scene_head" "$2" > "$1.pov"
  run "$1" "$3" "$1.pov" +W32 +H24 +O"$1.png"
  expect "$1" "$4"
}
value_case overflow 'sphere { 0, 1e400 pigment { rgb 1 } }' 1 \
  "overflow.pov:3:13: error: this value is not a finite number (inf)"
value_case nan '#declare I = 1e300 * 1e300;
sphere { 0, 1 pigment { rgb <I / I, 0, 0> } }' 1 \
  "not a finite number (nan in one of its components)"
value_case scaleinf 'sphere { 0, 1 scale 1e999 }' 1 \
  "not a finite number"
value_case cylinder 'cylinder { <0, 1, 0>, <0, 1, 0>, 1 }' 1 \
  "degenerate cylinder: its base point and cap point are the same"
value_case cone 'cone { <0, 1, 0>, 1, <0, 1, 0>, 0.5 }' 1 \
  "degenerate cone: its base point and cap point are the same"
value_case negsphere 'sphere { 0, -1 pigment { rgb 1 } }' 0 \
  "warning: a sphere with a negative radius (-1) is drawn with radius 1"
value_case triangle 'triangle { <0, 0, 0>, <1, 1, 0>, <2, 2, 0> }' 0 \
  "warning: degenerate triangle"
printf 'camera { location <0, 0, -5> look_at <0, 0, -5> }\n' > lookat.pov
run lookat 1 lookat.pov +W32 +H24 -q +Olookat.png
expect lookat "lookat.pov:1:38: error: the camera's location and look_at point must be different"

# ---- faults: signals, a killed rank, a full disk, little memory --------
# A scene slow enough to be interrupted: glass spheres, deep reflection.
cat > slow.pov <<EOF
$scene_head
global_settings { max_trace_level 20 }
#for (I, 0, 40)
  sphere { <mod(I, 7) - 3, div(I, 7) - 3, mod(I * 3, 5)>, 0.6
    pigment { rgbf 0.9 } finish { reflection 0.9 } interior { ior 1.5 } }
#end
EOF
# A command started with & by a script ignores SIGINT: perl (part of
# every Debian system) gives it back its default before exec.
for sig in 2 15; do
  cases=$((cases + 1))
  cp old.ref old.png
  perl -e '$SIG{INT} = "DEFAULT"; exec @ARGV or exit 127' "$ZRCUBE" \
    slow.pov +W400 +H300 +A0.0 +R4 +WT1 -q +Oold.png >sig.out 2>sig.err &
  pid=$!
  sleep 2
  kill -s "$( [ $sig = 2 ] && echo INT || echo TERM)" "$pid"
  wait "$pid"
  got=$?
  want=$((128 + sig))
  [ "$got" -eq "$want" ] || fail "SIG$sig: exit status $got, want $want"
  signame=$( [ $sig = 2 ] && echo SIGINT || echo SIGTERM)
  grep -q -F "zrcube: rendering stopped by $signame; the image was not written" \
    sig.err || { fail "SIG$sig: stderr lacks the message"; cat sig.err >&2; }
  intact "SIG$sig"
done

if command -v "$MPIRUN" >/dev/null 2>&1 && command -v ps >/dev/null 2>&1; then
  cases=$((cases + 1))
  env ASAN_OPTIONS="$MPI_ASAN" "$MPIRUN" -n 2 "$ZRCUBE" slow.pov \
    +W400 +H300 +A0.0 +R4 +WT1 -q +Oold.png >kill9.out 2>kill9.err &
  mpid=$!
  sleep 3
  # The ranks are mpirun's children (this test started mpirun).
  ranks=$(ps -o pid= --ppid "$mpid" | tr -d ' ')
  victim=$(printf '%s\n' "$ranks" | tail -n 1)
  start=$(date +%s)
  if [ -n "$victim" ]; then
    kill -9 "$victim"
    # The job must end by itself within seconds.
    t=0
    while kill -0 "$mpid" 2>/dev/null && [ "$t" -lt 30 ]; do
      sleep 1; t=$((t + 1))
    done
    if kill -0 "$mpid" 2>/dev/null; then
      fail "kill -9: mpirun still running after 30 s"
      kill -9 "$mpid" $ranks 2>/dev/null
    fi
    wait "$mpid"
    got=$?
    [ "$got" -ne 0 ] || fail "kill -9: mpirun exited 0"
    # OpenMPI's launcher names the rank and the signal.
    grep -q -e 'exited on signal 9' kill9.err kill9.out ||
      { fail "kill -9: no message naming signal 9"; cat kill9.err >&2; }
    echo "kill -9 of rank pid $victim: job ended in $(( $(date +%s) - start )) s, status $got"
  else
    fail "kill -9: no rank found under mpirun $mpid"
    kill "$mpid"; wait "$mpid"
  fi
  intact "kill -9"
fi

# A full disk: writes past ulimit -f fail with EFBIG (SIGXFSZ ignored).
printf '%s\nsphere { 0, 1 pigment { rgb 1 } }\n' "$scene_head" > small.pov
cases=$((cases + 1))
( trap '' XFSZ; ulimit -f 8; exec "$ZRCUBE" small.pov +W400 +H300 -q \
    +Oold.png ) >disk.out 2>disk.err
got=$?
[ "$got" -eq 1 ] || fail "disk full: exit status $got, expected 1"
expect disk "old.png: write failed: File too large"
intact "disk full"
( trap '' XFSZ; ulimit -f 8; exec "$ZRCUBE" small.pov +W400 +H300 -q \
    +Onew.png ) >disk2.out 2>disk2.err
[ -e new.png ] && fail "disk full: a partial new.png was left"

if [ "$sanitized" -eq 0 ]; then
  cases=$((cases + 1))
  cat > memory.pov <<'EOF'
#declare A = array[20000000];
#for (I, 0, 19999999) #declare A[I] = I; #end
EOF
  ( ulimit -v 600000; exec "$ZRCUBE" memory.pov --parse-only ) \
    >oom.out 2>oom.err
  got=$?
  [ "$got" -eq 1 ] || fail "ulimit -v: exit status $got, expected 1"
  expect oom "memory.pov:2:"
  expect oom "past the memory budget"
  intact "ulimit -v"
fi

# ---- a corrupt radiosity file -----------------------------------------
cat > rad.pov <<EOF
$scene_head
plane { y, -1 pigment { rgb 1 } }
box { <-1, -1, -1>, <1, 1, 1> pigment { rgb 1 } finish { emission 1 } }
EOF
run radsave 0 rad.pov +W16 +H12 -q --radiosity --bf-eps=0.05 \
  --radiosity-save=rad.sol +Orad.png
if [ -s rad.sol ]; then
  n=$(wc -c < rad.sol)
  head -c $((n / 2)) rad.sol > half.sol
  run radtrunc 1 rad.pov +W16 +H12 -q --radiosity-load=half.sol \
    +Oradt.png
  expect radtrunc "half.sol"
  { head -c 64 rad.sol; head -c 4096 /dev/urandom; } > junk.sol
  run radjunk 1 rad.pov +W16 +H12 -q --radiosity-load=junk.sol \
    +Oradj.png
  expect radjunk "junk.sol"
  [ -e radt.png ] || [ -e radj.png ] && fail "radiosity: image written"
else
  fail "radsave: no radiosity file"
fi

# ---- corrupt and truncated images --------------------------------------
run mkpng 0 small.pov +W64 +H48 -q +Ogood.png
run mkppm 0 small.pov +W64 +H48 -q +Ogood.ppm
run mkpfm 0 small.pov +W64 +H48 -q +Ogood.pfm
head -c 100 good.png > trunc.png
head -c 40 good.ppm > trunc.ppm
head -c 60 good.pfm > trunc.pfm
# JPEG: the start-of-image marker and a frame header claiming 64x48,
# then nothing.
printf '\377\330\377\300\000\021\010\000\060\000\100\003\001\042\000' \
  > trunc.jpg
printf '\377\330\377\340garbage-garbage' > junk.jpg
# GIF: a screen of 16x16 and a global palette, cut before the image.
printf 'GIF89a\020\000\020\000\200\000\000\000\000\000' > trunc.gif
printf 'GIF89a\020\000\020\000\000\000\000,\000\000\000\000\020\000\020\000\000\010\377\377\377' > junk.gif
# TGA: an uncompressed 24-bit 100x100 header, then 10 bytes.
printf '\000\000\002\000\000\000\000\000\000\000\000\000\144\000\144\000\030\000' > trunc.tga
head -c 10 /dev/zero >> trunc.tga
# POT: a GIF holding heights.
cp trunc.gif trunc.pot
# Radiance HDR and OpenEXR, as zrcube writes them, cut short; OpenEXR
# only when zrcube was built with it.
run mkhdr 0 small.pov +W64 +H48 -q +Ogood.hdr
head -c 100 good.hdr > trunc.hdr
head -c 11 good.hdr > junk.hdr
head -c 4096 /dev/urandom >> junk.hdr
exr=
if "$ZRCUBE" small.pov +W64 +H48 -q +Ogood.exr >mkexr.out 2>&1; then
  head -c 200 good.exr > trunc.exr
  exr=trunc.exr
fi
rm -f good.exr
# BMP: a 64x48 24-bit header and no pixels; a header of nonsense sizes.
printf 'BM\066\000\000\000\000\000\000\000\066\000\000\000\050\000\000\000\100\000\000\000\060\000\000\000\001\000\030\000' \
  > trunc.bmp
printf 'BM\377\377\377\377\000\000\000\000\377\377\377\377\050\000\000\000\377\377\377\177\377\377\377\177\001\000\030\000' \
  > junk.bmp
# TIFF: a little-endian header whose directory lies past the end.
printf 'II*\000\010\000\000\000\377\377' > junk.tif
for img in trunc.png trunc.ppm trunc.pfm trunc.jpg junk.jpg trunc.gif \
    junk.gif trunc.tga trunc.hdr junk.hdr $exr trunc.bmp junk.bmp \
    junk.tif; do
  ext=${img##*.}
  name=img_$(echo "$img" | tr . _)
  case $ext in
    pfm) map="image_map { \"$img\" }" ;; # read by its extension
    jpg) map="image_map { jpeg \"$img\" }" ;;
    tif) map="image_map { tiff \"$img\" }" ;;
    *) map="image_map { $ext \"$img\" }" ;;
  esac
  printf '%s\nplane { z, 1 pigment { %s } }\n' "$scene_head" "$map" \
    > "$name.pov"
  cp "$img" "$img.ref"
  run "$name" 1 "$name.pov" +W16 +H12 -q +O"$name.png"
  expect "$name" "$img"
  expect "$name" "error: cannot use '$img' as an image_map"
  cmp -s "$img" "$img.ref" || fail "$name: the image file changed"
  [ -e "$name.png" ] && fail "$name: an image was written"
done
printf '%s\nheight_field { pot "trunc.pot" }\n' "$scene_head" > img_pot.pov
run img_pot 1 img_pot.pov +W16 +H12 -q +Oimg_pot.png
expect img_pot "trunc.pot"
# The same files as height fields (their own decoding, lib/image/heights.c).
for img in trunc.png trunc.ppm trunc.jpg trunc.gif trunc.tga trunc.bmp \
    junk.bmp junk.tif; do
  name=hf_$(echo "$img" | tr . _)
  printf '%s\nheight_field { "%s" }\n' "$scene_head" "$img" > "$name.pov"
  run "$name" 1 "$name.pov" +W16 +H12 -q +O"$name.png"
  expect "$name" "error: cannot use '$img' as a height_field"
  cmp -s "$img" "$img.ref" || fail "$name: the image file changed"
  [ -e "$name.png" ] && fail "$name: an image was written"
done

# ---- a scene of 10^6 objects -------------------------------------------
cat > million.pov <<EOF
$scene_head
#for (I, 0, 999999)
  sphere { <mod(I, 1000) / 250 - 2, div(I, 1000) / 250 - 2, 0>, 0.003 }
#end
EOF
start=$(date +%s)
run million 0 million.pov +W32 +H24 -q +WT1 +Omillion.png
[ -s million.png ] || fail "million: no image"
echo "10^6 spheres: $(( $(date +%s) - start )) s"

echo "test_faults.sh: $cases cases, $failures failures"
[ "$failures" -eq 0 ]
