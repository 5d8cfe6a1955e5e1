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
set xrange [1.83742007:46.5837061]
set xtics (2, 5, 10, 20)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.58774326,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 5.39149889,77.3438007 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 3.92842749,73.4949382 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 6.533384,74.0727154 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.06365741,71.690965 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 10.1419968,72.4804162 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.1066909,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.89986717,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 4.555808,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 24.3526082,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 16.4879287,77.7503047 left font ',8' noenhanced front
set label 'LBVH/cl' at 1.89315907,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 4.40541267,71.690965 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
