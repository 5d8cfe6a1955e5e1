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
set xrange [5.66260274:67.8807478]
set xtics (10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 8.02139184,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 36.0768778,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 15.7033416,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.8598838,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 29.3207776,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 24.4196755,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 41.3637823,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 17.7992512,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 7.1936758,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.9627531,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 22.92957,54.6804169 left font ',8' noenhanced front
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
set xrange [5.66260274:67.8807478]
set xtics (10, 20, 50)
set yrange [4.42179193:5.98652313]
unset label
set label 'LBVH' at 8.02139184,5.0581494 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 36.3134666,5.61558751 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 21.2533246,5.59284022 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 19.4389435,5.70647674 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 29.3207776,5.70922401 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 24.2605769,5.65697427 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 41.3637823,5.72164118 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 25.7004246,5.77396893 left font ',8' noenhanced front
set label 'embree_low' at 7.1936758,4.56964054 left font ',8' noenhanced front
set label 'embree_medium' at 15.9627531,5.76756955 left font ',8' noenhanced front
set label 'embree_high' at 22.7801797,5.84174036 left font ',8' noenhanced front
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
set xrange [5.66260274:67.8807478]
set xtics (10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 8.02139184,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 36.3134666,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 21.1148554,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 26.8828543,65.6840669 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.2018014,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 33.3322845,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 41.3637823,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 17.7992512,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 7.1936758,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 15.9627531,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 22.92957,68.1161557 left font ',8' noenhanced front
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
set xrange [5.66260274:67.8807478]
set xtics (10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 8.02139184,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 36.0768778,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 15.7033416,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.8598838,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 29.3207776,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 24.4196755,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 41.3637823,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 17.7992512,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 7.1936758,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.9627531,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 22.92957,54.6804169 left font ',8' noenhanced front
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
set xrange [5.66260274:67.8807478]
set xtics (10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 8.02139184,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 36.3134666,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 21.1148554,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 26.8828543,65.6840669 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.2018014,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 33.3322845,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 41.3637823,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 17.7992512,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 7.1936758,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 15.9627531,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 22.92957,68.1161557 left font ',8' noenhanced front
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
set xrange [5.66260274:67.8807478]
set xtics (10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 8.02139184,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 36.0768778,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 15.7033416,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.8598838,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 29.3207776,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 24.4196755,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 41.3637823,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 17.7992512,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 7.1936758,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.9627531,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 22.92957,54.6804169 left font ',8' noenhanced front
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
set xrange [5.66260274:67.8807478]
set xtics (10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 8.02139184,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 36.3134666,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 21.1148554,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 26.8828543,65.6840669 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.2018014,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 33.3322845,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 41.3637823,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 17.7992512,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 7.1936758,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 15.9627531,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 22.92957,68.1161557 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
