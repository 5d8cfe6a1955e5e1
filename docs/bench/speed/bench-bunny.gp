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
set xrange [5.27329865:53.1481206]
set xtics (10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 5.72135753,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 15.3644755,39.738987 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 12.1878323,39.0414315 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 17.3005442,39.3432138 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 15.8082871,38.4286758 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.0305489,38.1317351 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.5261172,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.7224208,39.1916483 left font ',8' noenhanced front
set label 'embree_low' at 7.5986131,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 15.0357596,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 22.1935262,36.8708212 left font ',8' noenhanced front
set label 'LBVH/cl' at 7.30477663,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 24.5345922,38.740404 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-bunny.svg'.outsuffix
replot
unset output
reset
