# regenerate: gnuplot bench-conference.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-conference.png'
set title 'conference.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [11.6698675:92.4739527]
set xtics (20, 50)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 14.2455535,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 29.4069497,42.2585195 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 29.4353143,38.3879299 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 33.0649397,40.2171123 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 28.0451054,36.836494 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 53.5246132,35.3352164 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.1991191,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 34.1342604,35.1523488 left font ',8' noenhanced front
set label 'embree_low' at 25.7464023,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 53.7476939,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 41.659576,43.2759982 left font ',8' noenhanced front
set label 'LBVH/cl' at 16.6838673,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 37.1187525,36.836494 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-conference.svg'
replot
unset output
reset
