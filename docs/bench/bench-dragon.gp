# regenerate: gnuplot bench-dragon.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dragon.png'.outsuffix
set title 'dragon.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [48.2773387:769.391759]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 86.5588788,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 314.546827,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 207.469937,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 181.386833,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 287.062102,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 242.459254,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 442.952818,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 171.464435,59.4641489 left font ',8' noenhanced front
set label 'embree_low' at 63.0367686,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 298.023164,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 213.29023,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-dragon.png'.outsuffix
set title 'dragon.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [48.2773387:769.391759]
set xtics (50, 100, 200, 500)
set yrange [1.81626909:3.2562443]
unset label
set label 'LBVH' at 86.5588788,2.65410065 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 367.888382,3.08616849 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 208.987061,3.05910585 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 258.456184,2.76179885 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 287.062102,2.82841568 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 348.003936,2.97270842 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 442.952818,2.91974324 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 171.464435,2.97015938 left font ',8' noenhanced front
set label 'embree_low' at 63.0367686,1.95232974 left font ',8' noenhanced front
set label 'embree_medium' at 298.023164,2.53311503 left font ',8' noenhanced front
set label 'embree_high' at 298.864563,2.34626609 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-dragon.png'.outsuffix
set title 'dragon.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [48.2773387:769.391759]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 86.5588788,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 367.888382,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 149.147486,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 258.456184,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 201.462719,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 348.003936,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 442.952818,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 172.718268,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 63.0367686,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 298.023164,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 213.29023,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-dragon.png'.outsuffix
set multiplot layout 1,2
set title 'dragon.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [48.2773387:769.391759]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 86.5588788,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 314.546827,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 207.469937,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 181.386833,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 287.062102,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 242.459254,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 442.952818,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 171.464435,59.4641489 left font ',8' noenhanced front
set label 'embree_low' at 63.0367686,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 298.023164,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 213.29023,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dragon.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [48.2773387:769.391759]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 86.5588788,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 367.888382,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 149.147486,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 258.456184,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 201.462719,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 348.003936,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 442.952818,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 172.718268,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 63.0367686,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 298.023164,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 213.29023,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-dragon.svg'.outsuffix
set multiplot layout 1,2
set title 'dragon.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [48.2773387:769.391759]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 86.5588788,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 314.546827,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 207.469937,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 181.386833,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 287.062102,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 242.459254,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 442.952818,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 171.464435,59.4641489 left font ',8' noenhanced front
set label 'embree_low' at 63.0367686,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 298.023164,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 213.29023,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dragon.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [48.2773387:769.391759]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 86.5588788,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 367.888382,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 149.147486,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 258.456184,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 201.462719,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 348.003936,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 442.952818,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 172.718268,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 63.0367686,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 298.023164,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 213.29023,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
