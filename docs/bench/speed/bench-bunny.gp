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
set xrange [2.71398288:44.4989401]
set xtics (5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.99559629,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 8.24449271,39.4272587 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 5.47389044,39.3531597 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 6.25392999,38.4080291 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.69210819,38.1169475 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.0291482,39.0669198 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.3721919,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.1448929,37.9447354 left font ',8' noenhanced front
set label 'embree_low' at 6.27156911,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 25.4741102,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 17.9924851,36.8708212 left font ',8' noenhanced front
set label 'LBVH/cl' at 4.14587002,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 11.3766444,39.3638605 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-bunny.svg'.outsuffix
replot
unset output
reset
