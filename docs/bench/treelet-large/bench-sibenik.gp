# regenerate: gnuplot bench-sibenik.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-sibenik.png'.outsuffix
set title 'sibenik.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.3067436:260.756271]
set xtics (50, 100, 200)
set yrange [51.2257569:52.6183478]
unset label
set label 'ATRBVH(9,3)' at 32.81308,52.4538685 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 42.9306052,51.6904608 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 54.2616758,51.6188881 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 61.556492,51.4068427 left font ',8' noenhanced front
set label 'ATRBVH(48,3)' at 79.3390934,51.4595999 left font ',8' noenhanced front
set label 'ATRBVH(64,3)' at 97.2355225,51.6440785 left font ',8' noenhanced front
set label 'ATRBVH(96,3)' at 152.95809,51.443101 left font ',8' noenhanced front
set label 'ATRBVH(128,3)' at 165.034038,51.8549799 left font ',8' noenhanced front
set label 'ATRBVH(auto,3)' at 35.3546534,51.4839913 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 36.6735853,51.3573403 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 74.2366524,52.3325777 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-sibenik.svg'.outsuffix
replot
unset output
reset
