# regenerate: gnuplot bench-dragon.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dragon.png'.outsuffix
set title 'dragon.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [35.1671011:643.447289]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 38.9667387,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 94.9519561,63.4134696 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 75.2590529,61.8432232 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 114.625547,62.4957022 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 95.6683859,60.8121607 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 110.575316,59.8198299 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.737481,60.5199352 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 148.506885,59.4641489 left font ',8' noenhanced front
set label 'embree_low' at 75.5732005,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 231.65576,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 360.381865,57.38674 left font ',8' noenhanced front
set label 'LBVH/cl' at 50.7008398,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 152.289525,61.4574418 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
