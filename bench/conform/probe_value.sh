# bench/conform/probe_value.sh - sourced by shadow_fade_probe.sh and
# fade_power_probe.sh: renders shadow_fade_probe.pov with povray and,
# when $1 names it, zrcube, and prints the light at the image's centre.
# Sets PY, here, scene, zr and a work folder removed on exit.
PY=${PYTHON:-/usr/bin/python3}
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/shadow_fade_probe.pov
zr=${1:-}
[ -n "$zr" ] && zr=$(cd "$(dirname "$zr")" && pwd)/$(basename "$zr")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
value() { # RENDERER DECLARES... -> the light at the image centre
  r=$1
  shift
  decl=""
  for d in "$@"; do decl="$decl Declare=$d"; done
  $r +I"$scene" +Oout.png +W8 +H8 -D -A +WT1 -GA +FN16 File_Gamma=1.0 \
    $decl >/dev/null 2>&1
  $PY -c "import sys; sys.path.insert(0, '$here'); import png16; print('%.4f' % (png16.read('out.png')[4, 4, 0] / 0.5))"
}
row() { # LABEL DECLARES...
  label=$1
  shift
  line="$label povray $(value povray "$@")"
  [ -n "$zr" ] && line="$line zrcube $(value "$zr" "$@")"
  echo "$line"
}
