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
set xrange [36.2460583:325.421245]
set xtics (50, 100, 200)
set yrange [55.0033068:80.2279756]
unset label
set label 'LBVH' at 45.5595851,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 101.683581,62.7681885 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 71.2342049,62.4885043 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 83.6213978,61.2051388 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 110.247356,61.4574418 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 118.037176,60.465111 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 192.2384,60.5199352 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 159.897389,59.4641467 left font ',8' noenhanced front
set label 'embree_low' at 63.1623911,77.248684 left font ',8' noenhanced front
set label 'embree_medium' at 210.066347,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 153.335119,57.38674 left font ',8' noenhanced front
set label 'LBVH/cl' at 36.9889428,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 161.500406,61.4574418 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
