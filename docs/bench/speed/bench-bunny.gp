# regenerate: gnuplot bench-bunny.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-bunny.png'
set title 'bunny.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.29351273:17.2484612]
set xtics (5, 10)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.78565301,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 5.38410359,39.738987 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 4.31231283,39.0414315 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 6.02209625,39.3432138 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.26120399,38.4286758 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 7.40384627,38.1317351 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 10.7749895,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.03856935,38.8799201 left font ',8' noenhanced front
set label 'embree_low' at 4.65071494,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 11.494032,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 9.02069237,36.8708212 left font ',8' noenhanced front
set label 'LBVH/cl' at 3.32368284,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 5.05542925,38.1169475 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-bunny.svg'
replot
unset output
reset
