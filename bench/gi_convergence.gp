# gi_convergence.gp - the path tracer's error against samples per pixel
# (bench/gi_error.sh), with the 1/sqrt(spp) line through its first point.
#   gnuplot -e "tsv='path-convergence.tsv'; png='path-convergence.png'" gi_convergence.gp
set datafile separator "\t"
set datafile missing "fail"
set terminal pngcairo size 900,640 font "sans,11" noenhanced
set output png
set title "Path tracer on the emissive Cornell box, 256x256, against ../shared/reference (4096 spp)"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key top right box opaque
set logscale xy
set xlabel "samples per pixel"
set ylabel "relative RMSE against the shared ground truth"
stats tsv skip 1 using 2:4 nooutput
first_spp = STATS_min_x
first_err = STATS_max_y
plot \
  tsv skip 1 using 2:4 with linespoints lw 2 pt 7 lc rgb "#806000" \
    title "zRcube --gi=path", \
  first_err * sqrt(first_spp / x) with lines dt 2 lc rgb "black" \
    title "1/sqrt(spp) from the first point"
