# regenerate: gnuplot bench-dabrovic_sponza.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [22.76138:223.56001]
set xtics (50, 100, 200)
set yrange [68.5551102:70.4616925]
unset label
set label 'ATRBVH(9,3)' at 28.3658488,70.2365056 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 36.4077241,69.7722947 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 45.2810135,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 54.1704478,69.421931 left font ',8' noenhanced front
set label 'ATRBVH(48,3)' at 69.902329,69.0959753 left font ',8' noenhanced front
set label 'ATRBVH(64,3)' at 86.4055094,68.990262 left font ',8' noenhanced front
set label 'ATRBVH(96,3)' at 111.656635,69.1383325 left font ',8' noenhanced front
set label 'ATRBVH(128,3)' at 141.750641,68.7581278 left font ',8' noenhanced front
set label 'ATRBVH(auto,3)' at 28.8959338,68.8039745 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 30.6311193,68.7352597 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 46.860498,70.0410864 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
