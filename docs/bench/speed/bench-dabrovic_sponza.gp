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
set xrange [3.1427491:34.3063009]
set xtics (5, 10, 20)
set yrange [63.7338549:116.665389]
unset label
set label 'LBVH' at 3.95663792,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 9.29165128,75.98974 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 6.75200692,74.8489989 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 10.5363572,74.0727154 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.78552548,71.690965 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.8497039,72.4804197 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 21.2989122,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.3651672,67.3811972 left font ',8' noenhanced front
set label 'embree_low' at 6.57295549,110.413633 left font ',8' noenhanced front
set label 'embree_medium' at 15.7819448,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.3901696,77.7503047 left font ',8' noenhanced front
set label 'LBVH/cl' at 5.012626,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 15.6020903,74.39909 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
