# bench/scale.gp - the charts of bench/scale.sh (run by scale_model.py
# with dir set to the output folder).
set terminal pngcairo size 720,420 font ",10"
set output dir.'/model.png'
set logscale x 2
set xrange [1:1200]
set yrange [0:105]
set key bottom left
set grid
set xlabel 'ranks (one a node, 10 Gb/s network)'
set ylabel 'parallel efficiency, %'
set title 'zrcube: modelled efficiency (lines) and measured CPU efficiency (points)'
plot dir.'/model.dat' index 0 with linespoints lw 2 title 'ray traced (default.pov 2048x1536 +A)', \
     dir.'/model.dat' index 1 with linespoints lw 2 title 'radiosity (cornell.pov 64x64)', \
     dir.'/model.dat' index 2 with points pt 7 ps 1.5 title 'ray traced, measured', \
     dir.'/model.dat' index 3 with points pt 9 ps 1.5 title 'radiosity, measured'
set output dir.'/efficiency.png'
unset logscale x
set xrange [*:*]
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set xlabel ''
set title 'efficiency per phase on 2 processors (CPU measure; gi: radiosity solve)'
set key below horizontal
set yrange [0:110]
plot dir.'/phases.dat' index 0 using 2:xtic(1) title 'ray: 2 ranks', \
     '' index 0 using 3 title 'ray: 2 threads (work)', \
     '' index 1 using 2 title 'radiosity: 2 ranks', \
     '' index 1 using 3 title 'radiosity: 2 threads (work)'
