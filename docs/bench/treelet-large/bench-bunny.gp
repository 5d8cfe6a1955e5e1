# regenerate: gnuplot bench-bunny.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-bunny.png'.outsuffix
set title 'bunny.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [23.111019:189.189975]
set xtics (50, 100)
set yrange [38.284194:39.8100783]
unset label
set label 'ATRBVH(9,3)' at 28.4146429,38.6259329 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 34.9357496,38.4434634 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 44.5385101,38.9873551 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 52.3996707,38.854317 left font ',8' noenhanced front
set label 'ATRBVH(48,3)' at 60.9314033,39.2848487 left font ',8' noenhanced front
set label 'ATRBVH(64,3)' at 74.860921,39.2100686 left font ',8' noenhanced front
set label 'ATRBVH(96,3)' at 101.408209,39.4663187 left font ',8' noenhanced front
set label 'ATRBVH(128,3)' at 124.396133,39.6298558 left font ',8' noenhanced front
set label 'ATRBVH(auto,3)' at 28.3004591,38.4975303 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 30.3545266,38.5681918 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 59.6468034,38.4283721 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-bunny.svg'.outsuffix
replot
unset output
reset
