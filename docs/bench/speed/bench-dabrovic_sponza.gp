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
set xrange [3.89522519:54.1289635]
set xtics (5, 10, 20, 50)
set yrange [63.7338549:116.665389]
unset label
set label 'LBVH' at 4.27437732,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.4497075,71.690965 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.0879021,71.495647 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.0263081,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 20.4777844,67.3811972 left font ',8' noenhanced front
set label 'embree_low' at 6.05597432,110.413633 left font ',8' noenhanced front
set label 'embree_medium' at 14.2580336,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 10.3693679,77.7503047 left font ',8' noenhanced front
set label 'LBVH/cl' at 5.22062298,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 19.3363687,73.0450275 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
