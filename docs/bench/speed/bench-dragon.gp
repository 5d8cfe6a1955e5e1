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
set xrange [52.1892018:553.547067]
set xtics (100, 200, 500)
set yrange [55.0033068:80.2279756]
unset label
set label 'LBVH' at 65.5230079,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 167.865594,61.4574418 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 230.963338,59.8198288 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 345.643955,60.5199352 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 172.110314,59.4641467 left font ',8' noenhanced front
set label 'embree_low' at 69.2770999,77.248684 left font ',8' noenhanced front
set label 'embree_medium' at 143.788047,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 203.265674,57.38674 left font ',8' noenhanced front
set label 'LBVH/cl' at 81.224713,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 274.094997,61.4574418 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
