# regenerate: gnuplot bench-conference.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-conference.png'.outsuffix
set title 'conference.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [137.405943:1194.97089]
set xtics (200, 500, 1000)
set yrange [34.8851072:37.7134134]
unset label
set label 'ATRBVH(9,3)' at 169.243213,36.2582928 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 205.547839,35.3352164 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 456.010609,35.3866648 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 277.166609,35.3495545 left font ',8' noenhanced front
set label 'ATRBVH(48,3)' at 353.754006,35.5766103 left font ',8' noenhanced front
set label 'ATRBVH(64,3)' at 591.485272,35.2557702 left font ',8' noenhanced front
set label 'ATRBVH(96,3)' at 610.312506,35.5255568 left font ',8' noenhanced front
set label 'ATRBVH(128,3)' at 776.294699,35.4286235 left font ',8' noenhanced front
set label 'ATRBVH(auto,3)' at 195.436144,35.2108521 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 190.752011,35.0799967 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 234.730567,37.3793614 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'.outsuffix
replot
unset output
reset
