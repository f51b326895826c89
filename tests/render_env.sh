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
