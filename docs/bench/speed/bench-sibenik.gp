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
set xrange [2.11626634:20.1235821]
set xtics (5, 10, 20)
set yrange [48.0282344:83.2612717]
unset label
set label 'LBVH' at 2.62913444,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 5.58454724,56.2198439 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 4.48255256,53.8367768 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 6.74538589,54.157298 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.50186237,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.3444833,50.7535261 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.8422238,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.02553564,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.51536562,79.0998893 left font ',8' noenhanced front
set label 'embree_medium' at 10.4043316,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 7.86093691,55.5817271 left font ',8' noenhanced front
set label 'LBVH/cl' at 3.08766641,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 5.40316783,52.9793966 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-sibenik.svg'
replot
unset output
reset
