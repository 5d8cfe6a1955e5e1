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
set xrange [4.30761191:39.0252063]
set xtics (5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 4.65606644,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 11.574093,39.738987 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 9.32052059,39.0414315 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 13.5180167,39.3432138 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.4147082,38.4286758 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.7324895,38.1317351 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.3128656,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 17.5985254,38.8799201 left font ',8' noenhanced front
set label 'embree_low' at 8.48935542,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 25.1450575,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 19.2245953,36.8708212 left font ',8' noenhanced front
set label 'LBVH/cl' at 5.42954681,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 11.3299709,38.1169475 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-bunny.svg'.outsuffix
replot
unset output
reset
