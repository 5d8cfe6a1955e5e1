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
set xrange [14.0707133:123.834188]
set xtics (20, 50, 100)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 15.1933847,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 36.159939,42.2585195 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 42.1230066,39.6570412 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 31.8735741,38.948001 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 32.5885079,36.836494 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 66.3503652,35.3352164 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 80.256146,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 40.7279058,35.1523488 left font ',8' noenhanced front
set label 'embree_low' at 33.0392042,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 49.2145074,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 72.0036658,43.2759982 left font ',8' noenhanced front
set label 'LBVH/cl' at 18.1839349,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 52.4148782,38.1056054 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'.outsuffix
replot
unset output
reset
