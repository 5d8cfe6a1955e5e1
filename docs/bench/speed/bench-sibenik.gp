# regenerate: gnuplot bench-sibenik.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-sibenik.png'.outsuffix
set title 'sibenik.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.10738706:52.9712205]
set xtics (5, 10, 20, 50)
set yrange [48.0282379:83.2612389]
unset label
set label 'LBVH' at 2.92665968,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 6.07871236,56.219843 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 4.50349758,53.8367777 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 7.38675091,54.157298 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.94147229,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.5023754,50.753527 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 13.0946868,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 6.27896569,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.18207782,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 27.8353535,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 18.8005408,54.6804169 left font ',8' noenhanced front
set label 'LBVH/cl' at 2.17114326,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 4.89301762,52.9793966 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-sibenik.svg'.outsuffix
replot
unset output
reset
