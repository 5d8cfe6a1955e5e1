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
set xrange [2.14955813:21.8073156]
set xtics (5, 10, 20)
set yrange [48.0282344:83.2612717]
unset label
set label 'LBVH' at 2.68720509,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 5.84085085,56.2198439 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 4.6645303,53.8367768 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 7.13027458,54.157298 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 6.03625931,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.074194,50.7535261 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 13.7381957,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.44120878,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.80091249,79.0998893 left font ',8' noenhanced front
set label 'embree_medium' at 11.2558922,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 9.82543118,55.827539 left font ',8' noenhanced front
set label 'LBVH/cl' at 3.34649576,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 8.08383361,52.9793966 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-sibenik.svg'
replot
unset output
reset
