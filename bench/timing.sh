# timing.sh - sourced by the scripts that time whole runs in turn
# (launch.sh, mpi_n2.sh): a scratch folder $tmp removed on exit, $rt
# ("chrt -r 20" when RT=1: the round-robin real-time policy serves the
# runs before other sessions' processes, as an idle machine would), and
#   one KEY CMD...   a run of CMD under $rt, "KEY wall user system
#                    others" appended to $tmp/t (/usr/bin/time); a
#                    failing run prints its stderr and stops the script.
# others: the processor seconds the whole machine was busy during the
# run (/proc/stat: user, nice, system, irq, softirq, steal) less the
# run's own, i.e. what other processes took meanwhile.  Under RT=1 they
# still take some: Linux serves waiting normal processes about 50 ms a
# second on a processor that real-time ones keep busy (its fair
# server), which a run of two ranks on two cores pays and a run of one
# does not (perf sched: both ranks of mpirun -n 2 off the processor
# ~50 ms once a second while other sessions' renders ran, with real-time
# throttling off).
rt=
[ "${RT:-0}" = 1 ] && rt="chrt -r 20"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
busy_ticks() {
  awk '$1 == "cpu" { print $2 + $3 + $4 + $7 + $8 + $9; exit }' /proc/stat
}
one() {
  key=$1
  shift
  b0=$(busy_ticks)
  /usr/bin/time -f "$key %e %U %S" -o "$tmp/one" $rt "$@" \
    >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
  b1=$(busy_ticks)
  awk -v b="$((b1 - b0))" -v hz="$(getconf CLK_TCK)" \
    '{ line = $0; o = b / hz - $3 - $4 } END { printf "%s %.3f\n", line, (o > 0 ? o : 0) }' \
    "$tmp/one" >>"$tmp/t"
}
