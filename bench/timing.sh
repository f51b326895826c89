# timing.sh - sourced by the scripts that time whole runs in turn
# (launch.sh, mpi_n2.sh): a scratch folder $tmp removed on exit, $rt
# ("chrt -r 20" when RT=1: the round-robin real-time policy serves the
# runs before other sessions' processes, as an idle machine would), and
#   one KEY CMD...   a run of CMD under $rt, "KEY wall user system"
#                    appended to $tmp/t (/usr/bin/time); a failing run
#                    prints its stderr and stops the script.
rt=
[ "${RT:-0}" = 1 ] && rt="chrt -r 20"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
one() {
  key=$1
  shift
  /usr/bin/time -f "$key %e %U %S" -a -o "$tmp/t" $rt "$@" \
    >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
}
