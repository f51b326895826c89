# charts.gp - the charts of bench/radiosity.sh, from its table.
#   gnuplot -e "tsv='radiosity.tsv'; outdir='out'; zr=1" charts.gp
# Rows are method, setting, seconds, rel_rmse, elements, links; a method's
# rows form one ladder.  Rows with "fail" or "-" in a plotted column are
# skipped (they are not numbers).  zr=0 skips the zRcube-only chart.
set datafile separator "\t"
set datafile missing "-"
set terminal pngcairo size 900,640 font "sans,11" noenhanced
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key top right box opaque

pick(m, col) = strcol(1) eq m ? column(col) : NaN
lab(m) = strcol(1) eq m ? strcol(2) : ""

set output outdir."/radiosity-error-time.png"
set title "Emissive Cornell box, 256x256, one thread: error against time"
set xlabel "wall-clock seconds (whole command)"
set ylabel "relative RMSE against the path-traced truth"
set logscale xy
plot \
  tsv skip 1 using (pick("povray", 3)):(pick("povray", 4)) \
    with linespoints lw 2 pt 7 lc rgb "#c03020" title "POV-Ray 3.7 radiosity", \
  tsv skip 1 using (pick("povray", 3)):(pick("povray", 4)):(lab("povray")) \
    with labels offset 0,-1 font ",8" tc rgb "#c03020" notitle, \
  tsv skip 1 using (pick("zr-bf", 3)):(pick("zr-bf", 4)) \
    with linespoints lw 2 pt 5 lc rgb "#2040c0" \
    title "zRcube hierarchical (BF_eps ladder)", \
  tsv skip 1 using (pick("zr-bf", 3)):(pick("zr-bf", 4)):(lab("zr-bf")) \
    with labels offset 0,1 font ",8" tc rgb "#2040c0" notitle, \
  tsv skip 1 using (pick("zr-unif", 3)):(pick("zr-unif", 4)) \
    with linespoints lw 2 pt 9 lc rgb "#209040" \
    title "zRcube uniform N x N (no refinement)", \
  tsv skip 1 using (pick("zr-unif", 3)):(pick("zr-unif", 4)):(lab("zr-unif")) \
    with labels offset 0,1 font ",8" tc rgb "#209040" notitle, \
  tsv skip 1 using (pick("none", 3)):(pick("none", 4)) \
    with points pt 13 ps 1.5 lc rgb "black" title "no global illumination"

if (zr) {
  set output outdir."/radiosity-elements.png"
  set title "zRcube hierarchical radiosity: mesh size against BF_eps"
  set xlabel "BF_eps (finer to the right)"
  set xrange [*:*] reverse
  set ylabel "count"
  set logscale xy
  set key top right
  plot \
    tsv skip 1 using (strcol(1) eq "zr-bf" ? $2 : NaN):(pick("zr-bf", 5)) \
      with linespoints lw 2 pt 5 title "elements", \
    tsv skip 1 using (strcol(1) eq "zr-bf" ? $2 : NaN):(pick("zr-bf", 6)) \
      with linespoints lw 2 pt 7 title "links"
}
