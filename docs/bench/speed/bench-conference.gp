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
set xrange [13.570712:108.420251]
set xtics (20, 50, 100)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 16.579006,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 33.8971758,42.2585195 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 36.2284643,38.3879299 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 41.6746232,40.2171123 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 34.2067445,36.836494 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 62.6727916,35.3352164 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 71.635343,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 40.5780009,35.1523488 left font ',8' noenhanced front
set label 'embree_low' at 34.6527082,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 50.2813017,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 69.4324433,43.2759982 left font ',8' noenhanced front
set label 'LBVH/cl' at 22.7532932,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 51.691944,38.1056054 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'.outsuffix
replot
unset output
reset
