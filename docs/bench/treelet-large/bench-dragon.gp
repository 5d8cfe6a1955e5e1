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
set xrange [352.424971:2330.99468]
set xtics (500, 1000, 2000)
set yrange [60.3071535:61.9788704]
unset label
set label 'ATRBVH(9,3)' at 422.784155,61.2004297 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 504.234678,60.465111 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 609.918009,60.6771969 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 718.707035,60.6054722 left font ',8' noenhanced front
set label 'ATRBVH(48,3)' at 858.912507,60.8901047 left font ',8' noenhanced front
set label 'ATRBVH(64,3)' at 1006.26258,61.2954487 left font ',8' noenhanced front
set label 'ATRBVH(96,3)' at 1303.27729,61.5322577 left font ',8' noenhanced front
set label 'ATRBVH(128,3)' at 1599.25502,61.7814235 left font ',8' noenhanced front
set label 'ATRBVH(auto,3)' at 430.618259,60.8337752 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 457.561379,60.7547111 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 644.176382,60.5199352 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
