#!/bin/sh
# bench/realworld/run.sh [ZRCUBE [DIR]]: render issue 16's "other real-world
# scenes" (made by fetch.sh in DIR, default /work/realworld) with zRcube and
# compare them with POV-Ray 3.7's references, using the corpus's own
# ../shared/corpus/compare.py (160x120, -D, no AA, +WT1, SSIM after a 2x2
# box filter, >= 0.95 a match).  Prints one line per scene with its Debian
# package, version and licence, then the figures the issue asks for:
# parse % (zRcube exit 0 among the scenes POV-Ray renders) and match %.
# Extra arguments for compare.py go in COMPARE_ARGS (e.g. --only gen-vtk).
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
ZR=$(realpath "${1:-$HERE/../../build/bin/zrcube}")
DIR=$(realpath "${2:-/work/realworld}")
COMPARE=${COMPARE:-$HERE/../../../shared/corpus/compare.py}
[ -f "$COMPARE" ] || COMPARE=/work/shared/corpus/compare.py
TIMEOUT=${TIMEOUT:-60}
[ -f "$DIR/povray37-160x120.tsv" ] || { echo "run.sh: no $DIR/povray37-160x120.tsv (run fetch.sh first)" >&2; exit 2; }

OUT=${OUT:-$DIR/out-zrcube}
mkdir -p "$OUT"
raw=$OUT/compare.tsv    # compare.py's own table, kept beside the images
nice /usr/bin/python3 "$COMPARE" --corpus "$DIR" --out "$OUT" \
    --timeout "$TIMEOUT" ${COMPARE_ARGS:-} \
    --renderer "$ZR +I{scene} +O{out} +W160 +H120 -D +WT1" > "$raw"

awk -F'\t' -v OFS='\t' -v sources="$DIR/SOURCES.tsv" -v tried="$DIR/povray37-160x120.tsv" '
BEGIN {
    while ((getline l < sources) > 0) {
        if (l ~ /^#/) continue
        split(l, f, "\t"); pkg[f[1]] = f[2] " " f[3]; lic[f[1]] = f[4]
    }
    pkg["gen-pymol"] = "pymol (cmd.get_povray)"; lic["gen-pymol"] = "generated"
    pkg["gen-vtk"] = "python3-vtk9 (vtkPOVExporter)"; lic["gen-vtk"] = "generated"
    pkg["gen-obabel"] = "openbabel (-opov)"; lic["gen-obabel"] = "generated"
    pkg["gen-voro"] = "voro++ (-y)"; lic["gen-voro"] = "generated"
    pkg["gen-jmol"] = "jmol (write POVRAY)"; lic["gen-jmol"] = "generated"
    while ((getline l < tried) > 0) {
        split(l, f, "\t"); n_tried++
        if (f[2] == 0) n_pov++
        else { split(f[1], g, "/"); refused[f[1]] = f[2] }
    }
    print "# scene", "package and version (or generator)", "licence", "zrcube_exit", "ssim", "zrcube_s", "povray_s", "zrcube_last_stderr"
}
/^#/ { next }
{
    split($1, g, "/")
    print $1, pkg[g[1]], lic[g[1]], $2, $4, $3, $5, $6
    n++; if ($2 == 0 && $4 != "-") ok++; if ($4 != "-" && $4 >= 0.95) nmatch++
}
END {
    for (s in refused) {
        split(s, g, "/")
        print s, pkg[g[1]], lic[g[1]], "povray:" refused[s], "-", "-", "-", "POV-Ray itself fails or times out (not counted)"
    }
    printf "# summary\ttried=%d\tpovray_renders=%d\tzrcube_parses=%d (%.0f%%)\tmatch=%d (%.0f%%)\n",
        n_tried, n_pov, ok, n ? 100 * ok / n : 0, nmatch, n ? 100 * nmatch / n : 0
}' "$raw"
