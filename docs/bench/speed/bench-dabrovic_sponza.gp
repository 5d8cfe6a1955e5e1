# regenerate: gnuplot bench-dabrovic_sponza.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.52172429:37.5313737]
set xtics (5, 10, 20)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.3660889,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 7.92165232,77.3438007 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 6.40333992,73.4949382 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 9.84146499,74.0727154 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.69063351,71.690965 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.1065074,71.1263555 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 16.9918521,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.5460114,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 5.59075863,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 21.9042709,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 14.9869177,77.7503047 left font ',8' noenhanced front
set label 'LBVH/cl' at 2.58546031,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 7.38798361,68.9828435 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
