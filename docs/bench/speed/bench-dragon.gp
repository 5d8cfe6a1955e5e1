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
set xrange [27.7792513:761.104285]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 31.2224639,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 87.1984898,63.4134696 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 60.7907645,61.8432232 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 102.953715,62.4957022 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 89.8206748,60.6361749 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 104.024944,59.8198299 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 176.761551,60.5199352 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 135.7007,61.3999923 left font ',8' noenhanced front
set label 'embree_low' at 74.2404168,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 393.301328,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 257.524133,57.38674 left font ',8' noenhanced front
set label 'LBVH/cl' at 41.6129229,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 65.3483859,60.1668795 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
