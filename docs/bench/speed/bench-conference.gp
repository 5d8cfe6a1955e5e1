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
set xrange [16.1177891:188.443784]
set xtics (20, 50, 100)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 17.5791464,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 42.0703929,42.2585195 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 45.8801559,38.3879299 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 59.242011,40.2171123 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 42.0549152,36.836494 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 82.8222166,35.3352164 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 91.7127663,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 51.471322,35.1523488 left font ',8' noenhanced front
set label 'embree_low' at 27.2215978,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 78.6197314,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 115.403782,43.2759982 left font ',8' noenhanced front
set label 'LBVH/cl' at 21.7956775,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 57.1277325,38.4517267 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'.outsuffix
replot
unset output
reset
