# regenerate: gnuplot bench-conference.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-conference.png'.outsuffix
set title 'conference.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [9.92035034:269.837256]
set xtics (10, 20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 11.1471156,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 30.2151161,42.2585195 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 30.6743568,38.3879299 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 36.4395378,40.2171123 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 26.0168894,36.836494 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 53.8804492,35.3352164 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.5429335,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 30.2217262,35.1523488 left font ',8' noenhanced front
set label 'embree_low' at 25.3355308,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 139.640403,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 91.0660587,43.2759982 left font ',8' noenhanced front
set label 'LBVH/cl' at 14.6707182,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 41.6702006,36.836494 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'.outsuffix
replot
unset output
reset
