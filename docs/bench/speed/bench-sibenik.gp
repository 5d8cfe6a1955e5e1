# regenerate: gnuplot bench-sibenik.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-sibenik.png'
set title 'sibenik.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [4.71491565:33.9405633]
set xtics (5, 10, 20)
set yrange [48.0282379:83.2612389]
unset label
set label 'LBVH' at 5.05512261,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 11.0765158,56.219843 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 9.08722565,53.8367777 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 13.0510797,54.157298 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.4334162,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.2655843,50.753527 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 18.6514056,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.4909852,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 6.88173432,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 22.8961525,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 17.8353482,54.6804169 left font ',8' noenhanced front
set label 'LBVH/cl' at 6.23155264,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 8.89072528,52.0780873 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-sibenik.svg'
replot
unset output
reset
