# scale.gp - the chart of bench/radiosity_scale.sh, from its table.
#   gnuplot -e "tsv='scale.tsv'; png='scale.png'" scale.gp
# Rows: scene, size, solve_cpu, total_cpu, links, elements,
# links_per_surface, links_per_element, rss_kb, rss_off_kb.
set datafile separator "\t"
set datafile missing "fail"
set terminal pngcairo size 1500,480 font "sans,11" noenhanced
set output png
set multiplot layout 1,3 title "hierarchical radiosity as the scene grows (closed room, one thread, default BF_eps)"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key top left box opaque
set logscale xy
pick(k, col) = strcol(1) eq k ? column(col) : NaN
set xlabel "mesh faces / surfaces in the scene"
set ylabel "solve CPU seconds"
plot \
  tsv skip 1 using (pick("mesh", 2)):(pick("mesh", 3)) \
    with linespoints lw 2 pt 7 lc rgb "#c03020" title "one mesh of N faces", \
  tsv skip 1 using (pick("boxes", 2)):(pick("boxes", 3)) \
    with linespoints lw 2 pt 5 lc rgb "#2040c0" title "N surfaces (boxes)", \
  60 with lines dt 2 lc rgb "#808080" title "target for 100k faces: 60 s"
set ylabel "links"
set key top left box opaque
# Guides: links growing as the surfaces (slope 1) and as their pairs
# (N^2 / 2, what linking every two input surfaces makes).
plot \
  tsv skip 1 using (pick("mesh", 2)):(pick("mesh", 5)) \
    with linespoints lw 2 pt 7 lc rgb "#c03020" title "one mesh of N faces", \
  tsv skip 1 using (pick("boxes", 2)):(pick("boxes", 5)) \
    with linespoints lw 2 pt 5 lc rgb "#2040c0" title "N surfaces (boxes)", \
  [100:100000] 1000 * x with lines dt 2 lc rgb "#808080" title "1000 N (linear)", \
  [100:100000] x * x / 2 with lines dt 3 lc rgb "#808080" title "N^2 / 2 (every pair)"
set ylabel "links per surface (a mesh's faces count as surfaces)"
set key bottom left box opaque
plot \
  tsv skip 1 using (pick("mesh", 2)):(pick("mesh", 7)) \
    with linespoints lw 2 pt 7 lc rgb "#c03020" title "one mesh of N faces", \
  tsv skip 1 using (pick("boxes", 2)):(pick("boxes", 7)) \
    with linespoints lw 2 pt 5 lc rgb "#2040c0" title "N surfaces (boxes)", \
  tsv skip 1 using (pick("mesh", 2)):(pick("mesh", 8)) \
    with linespoints lw 1 dt 3 pt 6 lc rgb "#c03020" title "mesh: links per element", \
  tsv skip 1 using (pick("boxes", 2)):(pick("boxes", 8)) \
    with linespoints lw 1 dt 3 pt 4 lc rgb "#2040c0" title "boxes: links per element"
unset multiplot
