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
set xrange [5.40881875:68.6396455]
set xtics (10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 7.25716256,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 41.3537079,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0415984,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.642311,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.0016236,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.1131652,52.5215541 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.4002119,50.4129143 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.286917,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 6.90909355,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.8797676,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 22.8615087,54.6804169 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-sibenik.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-sibenik.png'.outsuffix
set title 'sibenik.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.40881875:68.6396455]
set xtics (10, 20, 50)
set yrange [4.57796175:7.34308085]
unset label
set label 'LBVH' at 7.25716256,5.67607193 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 41.3537079,6.79441391 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.9546877,6.84698377 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.7475621,7.01150781 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.0681114,7.01649198 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.1131652,6.81161654 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.6309969,6.94132414 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 16.4351291,6.70916481 left font ',8' noenhanced front
set label 'embree_low' at 6.90909355,4.83923285 left font ',8' noenhanced front
set label 'embree_medium' at 22.6182576,6.4303341 left font ',8' noenhanced front
set label 'embree_high' at 16.774727,6.81628252 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-sibenik.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-sibenik.png'.outsuffix
set title 'sibenik.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.40881875:68.6396455]
set xtics (10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 7.25716256,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 41.3537079,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0415984,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.7475621,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.9343752,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.2883539,67.9802521 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.6309969,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.286917,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 6.90909355,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 18.9518515,69.2840211 left font ',8' noenhanced front
set label 'embree_high' at 16.774727,68.1161557 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-sibenik.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-sibenik.png'.outsuffix
set multiplot layout 1,2
set title 'sibenik.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.40881875:68.6396455]
set xtics (10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 7.25716256,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 41.3537079,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0415984,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.642311,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.0016236,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.1131652,52.5215541 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.4002119,50.4129143 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.286917,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 6.90909355,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.8797676,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 22.8615087,54.6804169 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'sibenik.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.40881875:68.6396455]
set xtics (10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 7.25716256,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 41.3537079,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0415984,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.7475621,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.9343752,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.2883539,67.9802521 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.6309969,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.286917,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 6.90909355,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 18.9518515,69.2840211 left font ',8' noenhanced front
set label 'embree_high' at 16.774727,68.1161557 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-sibenik.svg'.outsuffix
set multiplot layout 1,2
set title 'sibenik.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.40881875:68.6396455]
set xtics (10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 7.25716256,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 41.3537079,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0415984,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.642311,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.0016236,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.1131652,52.5215541 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.4002119,50.4129143 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.286917,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 6.90909355,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.8797676,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 22.8615087,54.6804169 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'sibenik.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.40881875:68.6396455]
set xtics (10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 7.25716256,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 41.3537079,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0415984,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.7475621,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.9343752,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.2883539,67.9802521 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.6309969,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.286917,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 6.90909355,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 18.9518515,69.2840211 left font ',8' noenhanced front
set label 'embree_high' at 16.774727,68.1161557 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
