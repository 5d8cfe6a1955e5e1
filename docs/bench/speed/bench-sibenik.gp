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
set xrange [2.85383988:26.579801]
set xtics (5, 10, 20)
set yrange [48.0282344:83.2612717]
unset label
set label 'LBVH' at 3.0877081,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 7.3177498,56.2198439 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 5.86933095,53.8367768 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 8.83351986,54.157298 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.35732198,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.3026119,50.7535261 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0327221,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.43678324,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.99058996,79.0998893 left font ',8' noenhanced front
set label 'embree_medium' at 10.9500656,55.5817271 left font ',8' noenhanced front
set label 'embree_high' at 15.2386364,54.6804169 left font ',8' noenhanced front
set label 'LBVH/cl' at 3.75222065,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 10.3333906,52.9793966 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-sibenik.svg'.outsuffix
replot
unset output
reset
