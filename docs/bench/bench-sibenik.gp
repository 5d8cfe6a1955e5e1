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
set xrange [3.20020668:62.1273975]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 4.2587864,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.5305633,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 10.2629308,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 19.3494568,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.0716844,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 18.4302896,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3876225,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7359829,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.1121232,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 20.4078718,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 14.1139782,54.6804169 left font ',8' noenhanced front
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
set xrange [3.20020668:62.1273975]
set xtics (5, 10, 20, 50)
set yrange [2.82649484:4.0514234]
unset label
set label 'LBVH' at 4.2587864,3.21786349 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.7619567,3.78688905 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 10.2629308,3.7773617 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 19.5010739,3.84202941 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.0716844,3.89145477 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.9323361,3.74149799 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3876225,3.90015121 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 18.0565048,3.93808218 left font ',8' noenhanced front
set label 'embree_low' at 5.1121232,2.94223612 left font ',8' noenhanced front
set label 'embree_medium' at 13.504544,3.72499718 left font ',8' noenhanced front
set label 'embree_high' at 20.10042,3.71873006 left font ',8' noenhanced front
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
set xrange [3.20020668:62.1273975]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 4.2587864,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.7619567,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.6159514,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 13.2411867,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.9078561,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.7229424,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3876225,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7359829,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.1121232,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 20.4078718,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 20.10042,69.0337643 left font ',8' noenhanced front
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
set xrange [3.20020668:62.1273975]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 4.2587864,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.5305633,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 10.2629308,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 19.3494568,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.0716844,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 18.4302896,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3876225,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7359829,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.1121232,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 20.4078718,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 14.1139782,54.6804169 left font ',8' noenhanced front
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
set xrange [3.20020668:62.1273975]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 4.2587864,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.7619567,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.6159514,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 13.2411867,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.9078561,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.7229424,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3876225,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7359829,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.1121232,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 20.4078718,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 20.10042,69.0337643 left font ',8' noenhanced front
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
set xrange [3.20020668:62.1273975]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 4.2587864,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.5305633,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 10.2629308,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 19.3494568,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.0716844,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 18.4302896,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3876225,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7359829,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.1121232,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 20.4078718,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 14.1139782,54.6804169 left font ',8' noenhanced front
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
set xrange [3.20020668:62.1273975]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 4.2587864,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 29.7619567,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.6159514,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 13.2411867,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.9078561,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.7229424,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3876225,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7359829,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.1121232,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 20.4078718,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 20.10042,69.0337643 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
