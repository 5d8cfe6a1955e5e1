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
set xrange [1.79754903:35.9881372]
set xtics (2, 5, 10, 20)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.55259396,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 5.41527425,77.3438007 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 4.07353459,73.4949382 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 6.56843608,74.0727154 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.20653484,71.690965 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 10.206278,72.4804162 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7422652,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.86349477,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 4.4001389,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 19.7975451,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 13.5975385,77.7503047 left font ',8' noenhanced front
set label 'LBVH/cl' at 1.84804041,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 4.54939539,71.690965 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
