#!/bin/sh
# defmap_probe.sh - the colour map POV-Ray 3.7 gives each pattern written
# without one.  For each pattern, 300 points: its value (pigment with a
# black-to-white map) and its colour (pigment with no map), printed by
# #debug through function { pigment { } }.  The knots in
# lib/scene/texture.c (default_map_of) fit these lines; patterns whose
# colour equals their value use the grey ramp.  mandel 30 steps by 1/30
# and hides its knots: texture.c says how they were found.  Needs povray.
set -u
command -v povray >/dev/null || { echo "defmap_probe: no povray" >&2; exit 77; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_defmap.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
for pat in agate bozo marble radial wood spotted bumps dents wrinkles \
    ripples waves granite leopard crackle onion quilted "spiral1 2" \
    "spiral2 2" "mandel 30" "julia <0.35,0.2> 30"; do
cat > p.pov <<EOT
#version 3.7;
#declare V = function { pigment { $pat color_map { [0 rgb 0] [1 rgb 1] } } }
#declare C = function { pigment { $pat } }
#declare R = seed(7);
#for (I, 0, 299)
  #declare P = <rand(R) * 4 - 2, rand(R) * 4 - 2, rand(R) * 4 - 2>;
  #debug concat("$pat", " ", str(V(P.x, P.y, P.z).red, 0, 6), " ",
                vstr(3, C(P.x, P.y, P.z), " ", 0, 6), "\n")
#end
EOT
povray +Ip.pov -F +W8 +H8 -D 2>&1 | grep "^$pat " | sort -k2 -n
done
