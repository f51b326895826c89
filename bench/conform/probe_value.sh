# bench/conform/probe_value.sh - sourced by shadow_fade_probe.sh,
# fade_power_probe.sh and interior_fade_negative.sh: renders $scene
# (default shadow_fade_probe.pov; a caller may set it first) with povray
# and, when $1 names it, zrcube, and prints the linear light at the
# image's centre.  Sets PY, here, scene, zr and a work folder removed on
# exit.
PY=${PYTHON:-/usr/bin/python3}
here=$(cd "$(dirname "$0")" && pwd)
scene=${scene:-$here/shadow_fade_probe.pov}
zr=${1:-}
[ -n "$zr" ] && zr=$(cd "$(dirname "$zr")" && pwd)/$(basename "$zr")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
render() { # RENDERER DECLARES... -> out.png, 8x8, 16 bits, linear
  r=$1
  shift
  decl=""
  for d in "$@"; do decl="$decl Declare=$d"; done
  # shellcheck disable=SC2086
  "$r" +I"$scene" +Oout.png +W8 +H8 -D -A +WT1 -GA +FN16 File_Gamma=1.0 \
    $decl >/dev/null 2>&1
}
centre() { # RENDERER DECLARES... -> the centre pixel's r g b, linear
  render "$@"
  $PY -c "import sys; sys.path.insert(0, '$here'); import png16; a = png16.read('out.png'); print(' '.join('%.4f' % a[4, 4, c] for c in range(3)))"
}
value() { # RENDERER DECLARES... -> the light at the image centre
  # (the red channel over the probe light's 0.5)
  render "$@"
  $PY -c "import sys; sys.path.insert(0, '$here'); import png16; print('%.4f' % (png16.read('out.png')[4, 4, 0] / 0.5))"
}
row() { # LABEL DECLARES...
  label=$1
  shift
  line="$label povray $(value povray "$@")"
  [ -n "$zr" ] && line="$line zrcube $(value "$zr" "$@")"
  echo "$line"
}
