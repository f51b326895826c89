# gi_error.gp - one chart of bench/gi_error.sh, from a scene's table.
#   gnuplot -e "tsv='cbox.tsv'; png='gi-error-cbox.png'; title='...'" gi_error.gp
# Rows: method, setting, cpu_seconds, rel_rmse; "fail" rows are skipped.
set datafile separator "\t"
set datafile missing "fail"
set terminal pngcairo size 900,640 font "sans,11" noenhanced
set output png
set title title
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key top right box opaque
set logscale xy
set xlabel "CPU seconds (whole command, one thread)"
set ylabel "relative RMSE against the path-traced truth"
pick(m, col) = strcol(1) eq m ? column(col) : NaN
lab(m) = strcol(1) eq m ? strcol(2) : ""
# The q rungs form the ladder's line; "default" and "scene" (the blocks
# POV-Ray users start from) are points of their own.
rung(m, col) = strcol(1) eq m && strcol(2)[1:1] eq "q" ? column(col) : NaN
own(m, col) = strcol(1) eq m && strcol(2)[1:1] ne "q" ? column(col) : NaN
plot \
  tsv skip 1 using (rung("povray", 3)):(rung("povray", 4)) \
    with linespoints lw 2 pt 7 lc rgb "#c03020" \
    title "POV-Ray 3.7 radiosity (q1..q4)", \
  tsv skip 1 using (own("povray", 3)):(own("povray", 4)) \
    with points pt 6 ps 2 lw 2 lc rgb "#c03020" \
    title "POV-Ray: default / the scene's block", \
  tsv skip 1 using (pick("povray", 3)):(pick("povray", 4)):(lab("povray")) \
    with labels offset 0,-1 font ",8" tc rgb "#c03020" notitle, \
  tsv skip 1 using (rung("cache", 3)):(rung("cache", 4)) \
    with linespoints lw 2 pt 5 lc rgb "#2040c0" \
    title "zRcube irradiance cache (same blocks)", \
  tsv skip 1 using (own("cache", 3)):(own("cache", 4)) \
    with points pt 4 ps 2 lw 2 lc rgb "#2040c0" \
    title "zRcube cache: default / the scene's block", \
  tsv skip 1 using (pick("cache", 3)):(pick("cache", 4)):(lab("cache")) \
    with labels offset 0,1 font ",8" tc rgb "#2040c0" notitle, \
  tsv skip 1 using (pick("hier", 3)):(pick("hier", 4)) \
    with linespoints lw 2 pt 9 lc rgb "#209040" title "zRcube hierarchical (BF_eps)", \
  tsv skip 1 using (pick("hier", 3)):(pick("hier", 4)):(lab("hier")) \
    with labels offset 0,1 font ",8" tc rgb "#209040" notitle, \
  tsv skip 1 using (pick("path", 3)):(pick("path", 4)) \
    with linespoints lw 2 pt 11 lc rgb "#806000" title "zRcube path tracer (spp)", \
  tsv skip 1 using (pick("path", 3)):(pick("path", 4)):(lab("path")) \
    with labels offset 0,1 font ",8" tc rgb "#806000" notitle, \
  tsv skip 1 using (pick("off", 3)):(pick("off", 4)) \
    with points pt 13 ps 1.5 lc rgb "black" title "no global illumination"
