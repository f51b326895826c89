#!/bin/sh
# bench/realworld/fetch.sh [DIR]: build issue 16's "other real-world scenes"
# set from Debian's archive into DIR (default /work/realworld), laid out like
# ../shared/corpus so that its compare.py can render and compare it:
#   DIR/scenes/GROUP/...          the scenes (GROUP = package or generator)
#   DIR/povray37-160x120.tsv      scene, POV-Ray exit code, wall seconds
#   DIR/ref/NAME.png              POV-Ray 3.7's render of each scene
#   DIR/SOURCES.tsv               group, Debian package, version, licence
# Two kinds of scenes:
#   1. .pov files that Debian packages ship (found with
#      `apt-file search -x '\.pov$'`; povray-examples, the stock scenes, left
#      out), unpacked with `apt-get download` + `dpkg-deb -x` (no install).
#   2. scenes written by programs that export POV-Ray as their users run
#      them: PyMOL (cmd.get_povray), Open Babel (-opov), VTK
#      (vtkPOVExporter), Voro++ (-y), Jmol (write POVRAY).
# Needs root for apt-get; nothing is written in the repository.
# References: 160x120, no AA, one thread, as ../shared/corpus/README.md.
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
DIR=${1:-/work/realworld}
mkdir -p "$DIR" && DIR=$(cd "$DIR" && pwd)
TIMEOUT=${TIMEOUT:-25}
DATA_PKGS="voro++-examples blender-data freecad-common wx3.2-examples
polymake-common lincity inkscape libsyntax-highlight-engine-kate-perl"
GEN_PKGS="pymol openbabel python3-vtk9 voro++ voro++-dev jmol xvfb xauth g++"

mkdir -p "$DIR/debs" "$DIR/x" "$DIR/scenes" "$DIR/ref"
cd "$DIR"

# -- packages ---------------------------------------------------------------
missing=
for p in $GEN_PKGS; do
    dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
    apt-get install -y --no-install-recommends $missing
fi
(cd debs && for p in $DATA_PKGS; do
    ls "${p}"_*.deb >/dev/null 2>&1 || apt-get download "$p"
done)
: > SOURCES.tsv
printf '# group\tpackage\tversion\tlicence (from the package copyright file)\n' >> SOURCES.tsv
licence() { # the first License: field of a copyright file, else its name
    f=$1
    if [ -f "$f" ]; then
        l=$(grep -m1 '^License:' "$f" | sed 's/^License: *//')
        [ -n "$l" ] && { echo "$l"; return; }
        echo "see $f"
    else
        echo unknown
    fi
}
for deb in debs/*.deb; do
    p=$(dpkg-deb -f "$deb" Package)
    v=$(dpkg-deb -f "$deb" Version)
    rm -rf "x/$p"; mkdir -p "x/$p"
    dpkg-deb -x "$deb" "x/$p"
    printf '%s\t%s\t%s\t%s\n' "$p" "$p" "$v" \
        "$(licence "x/$p/usr/share/doc/$p/copyright")" >> SOURCES.tsv
done

# -- 1. shipped scenes: copy each .pov's directory (its includes and data) --
for p in $(ls x); do
    find "x/$p" -iname '*.pov' | sort | while read -r f; do
        d=$(dirname "$f")
        rel=${d#x/$p/}
        mkdir -p "scenes/$p/$rel"
        cp -a "$d/." "scenes/$p/$rel/"
    done
done
# Voro++'s examples: compile and run each program (from its own directory,
# with the packing files it reads) so that its scene's includes exist.
for d in scenes/voro++-examples/usr/share/doc/voro++-examples/*/; do
    (cd "$d" && for g in *.gz; do [ -f "$g" ] && gunzip -kf "$g"; done
     for cc in *.cc; do
         b=${cc%.cc}
         g++ -O1 -o "$b" "$cc" -I/usr/include/voro++ -lvoro++ 2>/dev/null \
             && timeout 60 "./$b" >/dev/null 2>&1 || true
         rm -f "$b"
     done) || true
done

# -- 2. scenes written by exporters -----------------------------------------
rm -rf scenes/gen-pymol scenes/gen-vtk scenes/gen-obabel scenes/gen-voro scenes/gen-jmol
mkdir -p scenes/gen-pymol scenes/gen-vtk scenes/gen-obabel scenes/gen-voro scenes/gen-jmol
timeout 300 /usr/bin/python3 "$HERE/gen_pymol.py" scenes/gen-pymol
timeout 300 xvfb-run -a /usr/bin/python3 "$HERE/gen_vtk.py" scenes/gen-vtk
# Open Babel: SMILES -> 3D coordinates -> POV-Ray (its scenes include
# babel_povray3.inc, which the openbabel package installs in povray's path;
# a copy beside the scenes keeps them self-contained).
cp /usr/share/openbabel/*/babel_povray3.inc scenes/gen-obabel/ 2>/dev/null \
    || cp /usr/share/povray/include/babel_povray3.inc scenes/gen-obabel/
while read -r name smiles opts; do
    timeout 60 obabel -:"$smiles" --gen3d -h -opov \
        -O "scenes/gen-obabel/$name.pov" $opts >/dev/null 2>&1 || true
done <<'SMILES'
ethanol CCO
benzene c1ccccc1
caffeine Cn1cnc2c1c(=O)n(c(=O)n2C)C
aspirin CC(=O)Oc1ccccc1C(=O)O
glucose OC[C@H]1OC(O)[C@H](O)[C@@H](O)[C@@H]1O
naphthalene_bas c1ccc2ccccc2c1 -xm BAS
ibuprofen_sph CC(C)Cc1ccc(cc1)C(C)C(=O)O -xm SPF
adamantane_cst C1C2CC3CC1CC(C2)C3 -xm CST
nicotine CN1CCC[C@H]1c2cccnc2 -xt
SMILES
# Voro++'s command line: random packings -> particles and cells (-y).
/usr/bin/python3 - <<'PY'
import random
rng = random.Random(16)
for n, name in ((40, 'pack40'), (120, 'pack120')):
    with open(f'scenes/gen-voro/{name}', 'w') as fh:
        for i in range(n):
            fh.write(f'{i} {rng.uniform(0, 1):.6f} {rng.uniform(0, 1):.6f} {rng.uniform(0, 1):.6f}\n')
PY
for pk in pack40 pack120; do
    (cd scenes/gen-voro && voro++ -y 0 1 0 1 0 1 "$pk" >/dev/null 2>&1 || true)
    cat > "scenes/gen-voro/$pk.pov" <<POV
// Scene around voro++ -y output (${pk}_p.pov particles, ${pk}_v.pov cells),
// in the style of voro++-examples/basic/import.pov.
#version 3.6;
camera { location <2.2,-2.6,2.0> sky z right -0.24*x*image_width/image_height
         up 0.24*z look_at <0.5,0.5,0.45> angle 40 }
background { rgb 1 }
light_source { <-8,-20,30> color rgb <0.77,0.75,0.75> }
light_source { <25,-12,12> color rgb <0.38,0.40,0.40> }
#declare r = 0.006;
#declare s = 0.02;
union { #include "${pk}_p.pov" pigment { rgb 0.95 } finish { reflection 0.1 specular 0.3 ambient 0.42 } }
union { #include "${pk}_v.pov" pigment { rgb <1,0.4,0.45> } finish { specular 0.5 ambient 0.42 } }
POV
done
# Jmol (the desktop program under Xvfb; JmolData.jar writes no POV-Ray):
# PyMOL-built molecules saved as PDB, a Jmol style each, write POVRAY.
/usr/bin/python3 - <<'PY'
from pymol import cmd
for name, how, arg in (('trp', 'fragment', 'trp'), ('phe', 'fragment', 'phe'),
                       ('benzene', 'fragment', 'benzene'),
                       ('helix', 'fab', 'AAAAKAAAAKAAAAKA'),
                       ('sheet', 'fab', 'VKVKVKVKVK')):
    cmd.reinitialize()
    if how == 'fragment':
        cmd.fragment(arg, name)
    else:
        cmd.fab(arg, name, ss=1 if name == 'helix' else 3)
    cmd.save(f'scenes/gen-jmol/{name}.pdb')
PY
while read -r out pdb style; do
    timeout 120 xvfb-run -a java -jar /usr/share/jmol/Jmol.jar -g 640x480 -o -x \
        -j "load $DIR/scenes/gen-jmol/$pdb.pdb; $style write POVRAY \"$DIR/scenes/gen-jmol/$out.pov\"" \
        >/dev/null 2>&1 || true
done <<'JMOL'
trp_default trp
trp_spacefill trp spacefill on; color cpk;
phe_wire_white phe background white; wireframe 0.05; spacefill off;
benzene_sticks benzene wireframe 0.2; spacefill 0.2;
helix_cartoon helix cartoon only; color structure;
helix_trace helix trace only; color amino;
sheet_rockets sheet rockets only; color group;
helix_ribbons_axes helix ribbons only; color chain; axes on;
trp_dots trp dots on; spacefill off;
phe_labels phe spacefill 25%; label %a; color label white;
JMOL
rm -f scenes/gen-jmol/*.pdb scenes/gen-jmol/*.ini

# -- references ------------------------------------------------------------
# Scenes tried: every .pov with a camera, or that is not #included by a
# sibling (a template with no camera still renders with POV-Ray's default).
INC=/usr/share/povray-3.7/include
: > povray37-160x120.tsv
find scenes -iname '*.pov' | sort | while read -r f; do
    d=$(dirname "$f"); b=$(basename "$f")
    if grep -qsl "\"$b\"" "$d"/*.pov "$d"/*.inc 2>/dev/null \
       && ! grep -qs 'camera' "$f"; then
        continue    # an include file of another scene
    fi
    rel=${f#scenes/}
    name=$(printf '%s' "$rel" | sed 's/\.[pP][oO][vV]$//; s|/|_|g')
    t0=$(date +%s.%N)
    (cd "$d" && timeout "$TIMEOUT" povray +I"$b" +O"$DIR/ref/$name.png" \
        +W160 +H120 -D -A +WT1 -GA +L"$INC" >/dev/null 2>&1) && rc=0 || rc=$?
    t1=$(date +%s.%N)
    [ "$rc" = 0 ] || rm -f "ref/$name.png"
    printf '%s\t%s\t%.2f\n' "$rel" "$rc" "$(echo "$t1 - $t0" | bc)" >> povray37-160x120.tsv
done
echo "scenes tried: $(wc -l < povray37-160x120.tsv)," \
     "rendered by POV-Ray: $(awk -F'\t' '$2==0' povray37-160x120.tsv | wc -l)"
