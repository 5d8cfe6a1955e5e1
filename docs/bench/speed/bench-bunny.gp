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
set xrange [2.01423061:56.4206863]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.26566069,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 6.38431283,39.4272587 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 3.97674037,39.3531597 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 4.30170357,38.7197574 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 4.88516827,38.1169475 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 8.23908348,38.0467183 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.9867905,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.26737791,38.8799201 left font ',8' noenhanced front
set label 'embree_low' at 4.55080469,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 28.8067844,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 19.3400854,36.8708212 left font ',8' noenhanced front
set label 'LBVH/cl' at 2.80662005,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 5.99574442,38.343659 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-bunny.svg'.outsuffix
replot
unset output
reset
