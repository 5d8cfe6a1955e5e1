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
set xrange [28.825896:757.401919]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 41.4186909,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 93.1523649,62.7681885 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 62.9342172,62.4885043 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 72.7852966,61.2051399 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 74.8372706,60.1668795 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 118.373076,59.6438441 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 166.631165,60.5199352 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 132.37651,61.3999923 left font ',8' noenhanced front
set label 'embree_low' at 73.4161631,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 394.669178,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 264.369008,57.38674 left font ',8' noenhanced front
set label 'LBVH/cl' at 29.7101547,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 112.528255,62.1027229 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
