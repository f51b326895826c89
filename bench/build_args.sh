# build_args.sh - the arguments of the bench scripts run as
# "bench/NAME.sh BUILD_DIR [--quick]"; sourced (with the caller's $1, $2)
# after "set -eu".  Sets quick (0 or 1), here (bench/), top, build,
# zrcube and imgcmp, or prints the usage and exits 2.
usage() {
  echo "usage: bench/$(basename "$0") BUILD_DIR [--quick]" >&2
  exit 2
}
[ $# -ge 1 ] || usage
quick=0
[ $# -ge 2 ] && { [ "$2" = --quick ] || usage; quick=1; }
[ $# -le 2 ] || usage
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/.." && pwd)
build=$(cd "$1" && pwd)
zrcube=$build/bin/zrcube
imgcmp=$build/tests/imgcmp
