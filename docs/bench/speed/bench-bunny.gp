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
set xrange [3.86583566:48.6281801]
set xtics (5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 4.22724104,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 12.6418335,39.738987 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 9.63556858,39.0414315 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 14.6180318,39.3432138 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.9425427,38.343659 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.1775226,38.4434634 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.3488329,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 19.0433231,38.8799201 left font ',8' noenhanced front
set label 'embree_low' at 8.13429034,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 24.2826394,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 17.1217611,36.8708212 left font ',8' noenhanced front
set label 'LBVH/cl' at 5.06375341,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 10.9807727,38.1169475 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-bunny.svg'.outsuffix
replot
unset output
reset
