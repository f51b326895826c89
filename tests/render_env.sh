# render_env.sh - the common start of the test scripts that render with
# zrcube and compare pictures; sourced after "set -u":
#
#   . "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
#
# Sets srcdir, builddir, zrcube and imgcmp (exit 99 when a tool is not
# built), makes a work folder that is removed at exit and enters it.
# With ZR_NEEDS_POVRAY=1 set before, a machine without povray skips the
# test (exit 77).  Environment: ZR_SRCDIR, ZR_BUILDDIR (make check).
srcdir=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
builddir=${ZR_BUILDDIR:-$srcdir/build}
zrcube=$builddir/bin/zrcube
imgcmp=$builddir/tests/imgcmp
if [ "${ZR_NEEDS_POVRAY:-0}" = 1 ] && ! command -v povray >/dev/null 2>&1; then
  echo "no povray: skipped"
  exit 77
fi
for tool in "$zrcube" "$imgcmp"; do
  [ -x "$tool" ] || { echo "$(basename "$0"): $tool is not built" >&2; exit 99; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_$(basename "$0" .sh).XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work" || exit 99

# pixel_case SCENE TAG DECLARE ROW,COL=R,G,B...: renders SCENE at 16x12
# (pixel_w x pixel_h when the test sets them) with Declare=DECLARE into
# zTAG.png and checks the given pixels (povray's recorded values) with
# tests/pixel_check.py, each channel within 2 levels; with povray
# installed its own render is compared too.
pixel_case() {
  pc_scene=$1 pc_tag=$2 pc_declare=$3
  shift 3
  pc_size="+W${pixel_w:-16} +H${pixel_h:-12}"
  timeout 60 "$zrcube" +I"$pc_scene" +Oz$pc_tag.png $pc_size -D +WT1 \
    Declare=$pc_declare </dev/null >z$pc_tag.log 2>&1 ||
    { cat z$pc_tag.log >&2; return 1; }
  pc_ref=""
  if command -v povray >/dev/null 2>&1 &&
     timeout 60 povray +I"$pc_scene" +Op$pc_tag.png $pc_size -D -A +WT1 \
       -GA Declare=$pc_declare </dev/null >p$pc_tag.log 2>&1; then
    pc_ref="--ref p$pc_tag.png"
  fi
  /usr/bin/python3 "$srcdir/tests/pixel_check.py" z$pc_tag.png "$@" $pc_ref
}

# pixel_cases SCENE VAR "CASES" ["ROW,COL ROW,COL..."]: pixel_case for each case
# C of CASES, rendered with Declare=VAR=C and checked against the pixels
# in the variable recorded_C: "R,G,B R,G,B..." at the given ROW,COL
# places (row from the top, 0..11; column 0..15), or "ROW,COL=R,G,B ..."
# words when no places are given.  Prints "case C:"
# before each; returns 1 when any case fails.
pixel_cases() {
  pcs_scene=$1 pcs_var=$2 pcs_cases=$3 pcs_px=${4:-}
  pcs_fail=0
  for pcs_c in $pcs_cases; do
    eval "pcs_values=\$recorded_$pcs_c"
    [ -n "$pcs_px" ] && pcs_values=$(pixel_args "$pcs_px" "$pcs_values")
    echo "case $pcs_c:"
    pixel_case "$pcs_scene" "$pcs_c" "$pcs_var=$pcs_c" $pcs_values ||
      pcs_fail=1
  done
  return $pcs_fail
}

# pixel_args "ROW,COL ..." "R,G,B R,G,B...": the ROW,COL=R,G,B words that
# pixel_case takes, pairing the two lists in order.
pixel_args() {
  pa_at=$1
  set -- $2
  pa_out=""
  for pa_p in $pa_at; do pa_out="$pa_out $pa_p=$1"; shift; done
  echo $pa_out
}
