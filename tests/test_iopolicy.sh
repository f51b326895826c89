#!/bin/sh
# test_iopolicy.sh - the I/O restrictions and the output file, end to end
# (issue 10, items 1, 2 and 7).  Every case checks the exit status, the
# message (with file:line:column where it comes from a scene) and that no
# file that was there before changed: a checksum of every file below the
# test's folders is taken before each case and compared after it.
#
# Layout in a temporary folder:
#   work/            the working directory; scene.pov and friends
#   work/outdir/     an output folder
#   outside/         a folder neither the scene nor the working directory
#                    holds: secret.inc, target.txt
#   extra/           a folder given with --read-path / --write-path
#
# Environment: ZR_BUILDDIR (where bin/zrcube is), MPIRUN (mpirun).

set -u
TEST_NAME=test_iopolicy
. "$(dirname "$0")/cli_env.sh"
top=$(cd "$work" && pwd -P)
mkdir -p "$top/work/outdir" "$top/outside" "$top/extra" "$top/logs" ||
  exit 99
cd "$top/work" || exit 99
logs=$top/logs

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# The checksums of every regular file in the test's folders but logs/.
sums() {
  find "$top" -path "$logs" -prune -o -type f -print | LC_ALL=C sort |
    while read -r f; do cksum "$f"; done
}

# run NAME WANT COMMAND...: runs COMMAND (at most 60 s) with stdout and
# stderr in logs/NAME.out and .err; WANT is the exit status expected.
run() {
  r_name=$1 r_want=$2
  shift 2
  timeout 60 "$@" >"$logs/$r_name.out" 2>"$logs/$r_name.err"
  got=$?
  if [ "$got" -eq 124 ]; then
    fail "$r_name: did not finish in 60 s"
  elif [ "$got" -ge 128 ]; then
    fail "$r_name: killed by a signal (status $got)"
  elif [ "$got" -ne "$r_want" ]; then
    fail "$r_name: exit status $got, expected $r_want"
    sed "s/^/  $r_name: /" "$logs/$r_name.err" >&2
  fi
  if grep -q -e 'Sanitizer' -e 'runtime error:' "$logs/$r_name.err"; then
    fail "$r_name: sanitizer report"
  fi
}

# refused NAME WANT COMMAND...: run, and no file that was there changed
# or vanished (new files are checked by the cases themselves).
refused() {
  sums >"$logs/before"
  run "$@"
  sums >"$logs/after"
  LC_ALL=C sort "$logs/before" >"$logs/before.sorted"
  LC_ALL=C sort "$logs/after" >"$logs/after.sorted"
  changed=$(LC_ALL=C comm -23 "$logs/before.sorted" "$logs/after.sorted")
  if [ -n "$changed" ]; then
    fail "$1: files changed or vanished"
    printf '%s\n' "$changed" | sed "s/^/  $1: /" >&2
  fi
}

# expect NAME TEXT: logs/NAME.err holds TEXT (a fixed string).
expect() {
  grep -q -F -e "$2" "$logs/$1.err" ||
    { fail "$1: stderr lacks '$2'"; sed "s/^/  $1: /" "$logs/$1.err" >&2; }
}

# absent NAME TEXT: logs/NAME.err does not hold TEXT.
absent() {
  if grep -q -F -e "$2" "$logs/$1.err"; then
    fail "$1: stderr shows '$2'"
  fi
}

# no_file NAME PATH: the case did not make PATH.
no_file() {
  if [ -e "$2" ] || [ -L "$2" ]; then
    fail "$1: made '$2'"
    rm -f "$2"
  fi
}

SIZE="+W16 +H12 -D -q"
cat >scene.pov <<'EOF'
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
EOF
# A scene that fails to parse: a check that comes first shows that it
# runs before the parse.
printf 'sphere { 0, 1 pigment { rgb 1 } \n' >broken.pov
echo 'secret-line-of-the-outside' >"$top/outside/secret.inc"
echo 'outside target' >"$top/outside/target.txt"
echo 'a file the user keeps' >abc.png
echo 'another file the user keeps' >full.png

# ---- item 1: the output name -------------------------------------------

# +Odir/abc: POV-Ray's rule (reference 3.2.4.2) appends the type's
# extension in the folder named; ./abc.png stays as it was.
refused outname 0 "$ZRCUBE" scene.pov $SIZE +Ooutdir/abc
[ -f outdir/abc.png ] || fail "outname: no outdir/abc.png"
# A folder: the scene's name inside it.
refused outfolder 0 "$ZRCUBE" scene.pov $SIZE +Ooutdir
[ -f outdir/scene.png ] || fail "outfolder: no outdir/scene.png"
# A device: refused by name, before parsing, and nothing written here.
refused device 2 "$ZRCUBE" broken.pov $SIZE +O/dev/full
expect device "zrcube: cannot write the image to '/dev/full': it is a \
character device, not a regular file or a directory"
absent device "broken.pov"
# A FIFO: refused, never opened (a write would block).
mkfifo pipe.png 2>/dev/null || fail "fifo: mkfifo failed"
refused fifo 2 "$ZRCUBE" scene.pov $SIZE +Opipe.png
expect fifo "zrcube: cannot write the image to 'pipe.png': it is a FIFO"
rm -f pipe.png
# +O- is standard output (issue 12), never a file named "-".
"$ZRCUBE" scene.pov $SIZE +O- >stdout.png 2>stdout.err ||
  fail "stdout: +O- failed: $(cat stdout.err)"
head -c 8 stdout.png | od -An -c | grep -q 'P   N   G' ||
  fail "stdout: +O- wrote no PNG to standard output"
[ -e ./- ] && fail "stdout: +O- made a file named '-'"
# A symbolic link is followed: the link stays, its file gets the image.
echo 'old image' >"$top/work/real.png"
ln -s real.png linked.png
run outlink 0 "$ZRCUBE" scene.pov $SIZE +Olinked.png
[ -L linked.png ] || fail "outlink: the link was replaced"
head -c 4 real.png | od -c | grep -q 'P   N   G' ||
  fail "outlink: real.png is not the new image"
# No temporary file is left anywhere.
leftover=$(find "$top" -name '*.tmp' | head -n 1)
[ -z "$leftover" ] || fail "temporary file left: $leftover"

# ---- item 7: checks before parsing ------------------------------------

# An output folder that is not there: found before the scene is parsed.
refused nodir 1 "$ZRCUBE" broken.pov $SIZE +Ono_such_dir/x.png
expect nodir "zrcube: cannot write the image to 'no_such_dir/x.png': \
cannot create a file in 'no_such_dir': No such file or directory"
absent nodir "broken.pov"
no_file nodir no_such_dir
# A radiosity save into a device or a missing folder: the same.
refused radsave 1 "$ZRCUBE" broken.pov $SIZE --radiosity-save=/dev/null
expect radsave "zrcube: cannot write the radiosity solution to \
'/dev/null': it is not a regular file"
refused radmesh 1 "$ZRCUBE" broken.pov $SIZE --radiosity-mesh=nodir/m.png
expect radmesh "cannot write the radiosity mesh to 'nodir/m.png'"
# A file the user may not write (skipped as root, who may).
if [ "$(id -u)" != 0 ]; then
  echo keep >readonly.png
  chmod a-w readonly.png
  refused readonly 1 "$ZRCUBE" broken.pov $SIZE +Oreadonly.png
  expect readonly "zrcube: cannot write the image to 'readonly.png': \
Permission denied"
  chmod u+w readonly.png
fi
# The image limit, with its numbers, before parsing.
refused toolarge 2 "$ZRCUBE" broken.pov +W20000 +H20000 -D -q +Obig.png
expect toolarge "zrcube: an image of 20000x20000 is 400000000 pixels, \
more than the limit of 134217728 (2^27) pixels"
absent toolarge "broken.pov"
no_file toolarge big.png
# Just at the limit is accepted by the check (parsed with --parse-only
# would skip it; -F renders nothing big here because the scene fails).
refused atlimit 1 "$ZRCUBE" broken.pov +W16384 +H8192 -D -q -F
expect atlimit "broken.pov:"

# ---- item 2: files a scene opens ---------------------------------------

# $1: name, $2: scene text.  Writes NAME.pov.
scene() { printf '%s\n' "$2" >"$1.pov"; }

scene inc_abs '#include "/etc/passwd"'
refused inc_abs 1 "$ZRCUBE" inc_abs.pov $SIZE -F
expect inc_abs "inc_abs.pov:1:10: error: cannot read include file: \
'/etc/passwd' is outside the folders a scene may read"
absent inc_abs "root:"

scene inc_proc '#include "/proc/self/environ"'
refused inc_proc 1 "$ZRCUBE" inc_proc.pov $SIZE -F
expect inc_proc "inc_proc.pov:1:10: error: cannot read include file: \
'/proc/self/environ' leads to '/proc/"
expect inc_proc "/environ', outside the folders a scene may read"

# Under "strict", relative names are confined too (the default reads
# them wherever they lead: see "relative names" below).
STRICT=--io-restrictions=strict
# A link in the scene's folder to a file outside: judged by its target,
# and the target's first line is not shown.
ln -s ../outside/secret.inc link.inc
scene inc_link '#include "link.inc"'
refused inc_link 1 "$ZRCUBE" inc_link.pov $SIZE -F $STRICT
expect inc_link "inc_link.pov:1:10: error: cannot read include file: \
'link.inc' leads to '$top/outside/secret.inc', outside the folders a \
scene may read"
absent inc_link "secret-line-of-the-outside"

scene inc_dotdot '#include "../outside/secret.inc"'
refused inc_dotdot 1 "$ZRCUBE" inc_dotdot.pov $SIZE -F $STRICT
expect inc_dotdot "inc_dotdot.pov:1:10: error: cannot read include file:"
absent inc_dotdot "secret-line-of-the-outside"

# Devices, FIFOs and folders, by name and without hanging.
scene inc_zero '#include "/dev/zero"'
refused inc_zero 1 "$ZRCUBE" inc_zero.pov $SIZE -F
expect inc_zero "inc_zero.pov:1:10: error: cannot read include file: \
'/dev/zero' is a character device, not a regular file"
mkfifo fifo.inc 2>/dev/null || fail "fifo.inc: mkfifo failed"
scene inc_fifo '#include "fifo.inc"'
refused inc_fifo 1 "$ZRCUBE" inc_fifo.pov $SIZE -F
expect inc_fifo "inc_fifo.pov:1:10: error: cannot read include file: \
'fifo.inc' is a FIFO, not a regular file"
scene inc_dir '#include "outdir"'
refused inc_dir 1 "$ZRCUBE" inc_dir.pov $SIZE -F
expect inc_dir "inc_dir.pov:1:10: error: cannot read include file: \
'outdir' is a directory, not a regular file"

# Every keyword that reads a file goes through the same rule.
scene img_zero 'sphere { 0, 1 pigment { image_map { png "/dev/zero" } } }'
refused img_zero 1 "$ZRCUBE" img_zero.pov $SIZE -F
expect img_zero "img_zero.pov:1:41: error: cannot read image_map: \
'/dev/zero' is a character device, not a regular file"
scene img_fifo 'sphere { 0, 1 pigment { image_map { png "fifo.inc" } } }'
refused img_fifo 1 "$ZRCUBE" img_fifo.pov $SIZE -F
expect img_fifo "img_fifo.pov:1:41: error: cannot read image_map: \
'fifo.inc' is a FIFO"
scene bump 'sphere { 0, 1 normal { bump_map { png "/etc/passwd" } } }'
refused bump 1 "$ZRCUBE" bump.pov $SIZE -F
expect bump "bump.pov:1:39: error: cannot read bump_map: '/etc/passwd' is \
outside the folders a scene may read"
scene hf 'height_field { png "../outside/secret.inc" }'
refused hf 1 "$ZRCUBE" hf.pov $SIZE -F $STRICT
expect hf "hf.pov:1:16: error: cannot read height_field file: \
'../outside/secret.inc' leads to '$top/outside/secret.inc', outside"
scene ttf 'text { ttf "/etc/passwd" "a" 1, 0 }'
refused ttf 1 "$ZRCUBE" ttf.pov $SIZE -F
expect ttf "ttf.pov:1:12: error: cannot read font: '/etc/passwd' is \
outside the folders a scene may read"
scene df3 'box { 0, 1 pigment { density_file df3 "/etc/passwd" } }'
refused df3 1 "$ZRCUBE" df3.pov $SIZE -F
expect df3 "df3.pov:1:39: error: cannot read density_file: '/etc/passwd' \
is outside the folders a scene may read"
scene fread '#fopen F "/etc/hostname" read'
refused fread 1 "$ZRCUBE" fread.pov $SIZE -F
expect fread "fread.pov:1:10: error: cannot read data file: \
'/etc/hostname' is outside the folders a scene may read"
# file_exists() says no for what the scene may not read.
scene exists '#debug concat("exists=", str(file_exists("/etc/passwd"), 0, 0), "\n")'
run exists 0 "$ZRCUBE" exists.pov $SIZE -F
expect exists "exists=0"

# Writes: below the working directory only, judged after links.
scene fwrite_out '#fopen F "../outside/new.txt" write'
refused fwrite_out 1 "$ZRCUBE" fwrite_out.pov $SIZE -F
expect fwrite_out "fwrite_out.pov:1:10: error: '#fopen' cannot open a file \
for writing: '../outside/new.txt' leads to '$top/outside/new.txt', outside \
the folders a scene may write"
no_file fwrite_out "$top/outside/new.txt"
ln -s ../outside/target.txt wlink.txt
scene fwrite_link '#fopen F "wlink.txt" write #write (F, "overwritten")'
refused fwrite_link 1 "$ZRCUBE" fwrite_link.pov $SIZE -F
expect fwrite_link "fwrite_link.pov:1:10: error: '#fopen' cannot open a \
file for writing: 'wlink.txt' leads to '$top/outside/target.txt'"
scene fappend_link '#fopen F "wlink.txt" append #write (F, "added")'
refused fappend_link 1 "$ZRCUBE" fappend_link.pov $SIZE -F
expect fappend_link "'#fopen' cannot open a file for appending"
scene fwrite_dev '#fopen F "/dev/full" write'
refused fwrite_dev 1 "$ZRCUBE" fwrite_dev.pov $SIZE -F
expect fwrite_dev "fwrite_dev.pov:1:10: error: '#fopen' cannot open a \
file for writing: '/dev/full' is a character device, not a regular file"
scene fwrite_ok '#fopen F "written.txt" write #write (F, "fine\n")'
run fwrite_ok 0 "$ZRCUBE" fwrite_ok.pov $SIZE -F
grep -q fine written.txt 2>/dev/null || fail "fwrite_ok: nothing written"

# ---- widening and switching off ----------------------------------------

# The include is read now: its text is an undefined name, not a refusal.
run readpath 1 "$ZRCUBE" inc_link.pov $SIZE -F $STRICT --read-path=../outside
expect readpath "link.inc:1:1: error: undefined identifier"
absent readpath "outside the folders"
printf 'Read_Path=../outside\n' >wide.ini
run readini 1 "$ZRCUBE" inc_link.pov wide.ini $SIZE -F $STRICT
expect readini "link.inc:1:1: error: undefined identifier"
absent readini "outside the folders"
scene inc_ok "#declare V = 1; #include \"$top/extra/ok.inc\" sphere { 0, V pigment { rgb 1 } }"
echo '#declare V = 2;' >"$top/extra/ok.inc"
refused inc_extra 1 "$ZRCUBE" inc_ok.pov $SIZE -F
expect inc_extra "is outside the folders a scene may read"
run inc_extra_ok 0 "$ZRCUBE" inc_ok.pov $SIZE -F --read-path="$top/extra"
run inc_extra_inc 0 "$ZRCUBE" inc_ok.pov $SIZE -F +L"$top/extra"
run readonly_mode 0 "$ZRCUBE" inc_ok.pov $SIZE -F --io-restrictions=read-only
refused readonly_write 1 "$ZRCUBE" fwrite_out.pov $SIZE -F \
  --io-restrictions=read-only
expect readonly_write "outside the folders a scene may write"
run writepath 0 "$ZRCUBE" fwrite_out.pov $SIZE -F --write-path=../outside
[ -f "$top/outside/new.txt" ] || fail "writepath: nothing written"
rm -f "$top/outside/new.txt"
run off 0 "$ZRCUBE" inc_ok.pov $SIZE -F --io-restrictions=off
printf 'IO_Restrictions=none\n' >off.ini
run offini 0 "$ZRCUBE" inc_ok.pov off.ini $SIZE -F
# Switched off, devices are still refused.
refused off_zero 1 "$ZRCUBE" inc_zero.pov $SIZE -F --io-restrictions=none
expect off_zero "'/dev/zero' is a character device, not a regular file"
refused badmode 2 "$ZRCUBE" scene.pov $SIZE --io-restrictions=maybe
expect badmode "zrcube: '--io-restrictions=maybe': the I/O restrictions \
are 'restricted' (or 'on'), 'strict', 'read-only' or 'none' (or 'off')"
refused badpath 1 "$ZRCUBE" scene.pov $SIZE --read-path=no/such/dir
expect badpath "zrcube: --read-path 'no/such/dir': no such directory"

# ---- relative names -----------------------------------------------------

# By default a scene reads what it names by a relative name wherever that
# leads, as POV-Ray 3.7 reads "../matrices.inc" from t-o-k's MoreExamples
# folder; the same file by its absolute name stays refused, and writes
# stay confined (fwrite_out above).
mkdir -p "$top/outside/sub" || exit 99
echo '#declare R = 0.5;' >"$top/outside/r.inc"
cat >"$top/outside/sub/rel.pov" <<'EOF2'
#include "../r.inc"
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
sphere { 0, R pigment { rgb 1 } }
EOF2
run rel_sub 0 "$ZRCUBE" "$top/outside/sub/rel.pov" $SIZE -F
scene rel_dotdot '#include "../outside/r.inc"
#if (!file_exists("../outside/r.inc")) #error "no file" #end
sphere { 0, R pigment { rgb 1 } }'
run rel_dotdot 0 "$ZRCUBE" rel_dotdot.pov $SIZE -F
run rel_link 1 "$ZRCUBE" inc_link.pov $SIZE -F
expect rel_link "link.inc:1:1: error: undefined identifier"
absent rel_link "outside the folders"
scene rel_abs "#include \"$top/outside/r.inc\""
refused rel_abs 1 "$ZRCUBE" rel_abs.pov $SIZE -F
expect rel_abs "is outside the folders a scene may read"
refused rel_strict 1 "$ZRCUBE" rel_dotdot.pov $SIZE -F $STRICT
expect rel_strict "rel_dotdot.pov:1:10: error: cannot read include file: \
'../outside/r.inc' leads to '$top/outside/r.inc', outside"
printf 'IO_Restrictions=strict\n' >strict.ini
refused rel_strict_ini 1 "$ZRCUBE" rel_dotdot.pov strict.ini $SIZE -F
expect rel_strict_ini "outside the folders a scene may read"

# POV-Ray's include files and the fonts its package links into its
# include folder are still read.
scene stock '#include "colors.inc"
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> White }
text { ttf "timrom.ttf" "Az" 0.2, 0 pigment { Red } translate -x }'
run stock 0 "$ZRCUBE" stock.pov $SIZE +Ostock.png
[ -f stock.png ] || fail "stock: no image"

# Under mpirun rank 0 reads the files and applies the rule; the others
# read its copies: the same refusal, once.
if command -v "$MPIRUN" >/dev/null 2>&1; then
  refused mpi_link 1 env ASAN_OPTIONS="$MPI_ASAN" $MPIRUN -n 2 "$ZRCUBE" \
    inc_link.pov $SIZE -F $STRICT
  count=$(grep -c -F "leads to" "$logs/mpi_link.err")
  [ "$count" -eq 1 ] || fail "mpi_link: message printed $count times"
  absent mpi_link "secret-line-of-the-outside"
  run mpi_ok 0 env ASAN_OPTIONS="$MPI_ASAN" $MPIRUN -n 2 "$ZRCUBE" \
    stock.pov $SIZE +Ompi.png
  cmp -s mpi.png stock.png || fail "mpi_ok: image differs from one rank's"
  # Every rank parses the scene, but only rank 0 writes its #fopen
  # files: an appended line appears once, and what rank 0 wrote and read
  # back reaches the others (the sphere's radius), so their parse and
  # picture agree with one rank's.
  cat >mpi_write.pov <<'EOF2'
#fopen L "mpi_log.txt" append
#write (L, "parsed\n")
#fclose L
#fopen W "mpi_data.txt" write
#write (W, "0.75")
#fclose W
#fopen R "mpi_data.txt" read
#read (R, Radius)
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 3, -4> rgb 1 }
sphere { 0, Radius pigment { rgb 1 } }
EOF2
  rm -f mpi_log.txt mpi_data.txt
  run mpi_write1 0 "$ZRCUBE" mpi_write.pov $SIZE +Ompi_write1.png
  rm -f mpi_log.txt mpi_data.txt
  run mpi_write 0 env ASAN_OPTIONS="$MPI_ASAN" $MPIRUN -n 2 "$ZRCUBE" \
    mpi_write.pov $SIZE +Ompi_write.png
  lines=$(grep -c parsed mpi_log.txt 2>/dev/null)
  [ "$lines" = 1 ] || fail "mpi_write: '$lines' lines appended, expected 1"
  cmp -s mpi_write.png mpi_write1.png ||
    fail "mpi_write: image differs from one rank's"
fi

if [ "$failures" -ne 0 ]; then
  echo "test_iopolicy.sh: $failures failure(s)" >&2
  exit 1
fi
echo "test_iopolicy.sh: all cases passed"
exit 0
