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
set xrange [3.72324437:64.6242362]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 8.38025628,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.8386623,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.7178691,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 21.3938983,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.6413906,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 18.3662802,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.577391,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.233439,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.90166689,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 13.0673721,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 24.2560494,54.6804169 left font ',8' noenhanced front
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
set xrange [3.72324437:64.6242362]
set xtics (5, 10, 20, 50)
set yrange [2.83865464:4.04353184]
unset label
set label 'LBVH' at 8.38025628,3.08633193 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.0937647,3.54136687 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.8384322,3.50949691 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 25.7740049,3.70305964 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.6413906,3.87917722 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.4571702,3.80077874 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.577391,3.90122351 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 18.5181863,3.91857884 left font ',8' noenhanced front
set label 'embree_low' at 4.90166689,2.95250131 left font ',8' noenhanced front
set label 'embree_medium' at 19.2963112,3.66539771 left font ',8' noenhanced front
set label 'embree_high' at 24.2560494,3.54955106 left font ',8' noenhanced front
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
set xrange [3.72324437:64.6242362]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 8.38025628,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.0937647,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.6825112,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 25.5811541,66.6016754 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.6413906,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.2592077,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.577391,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.233439,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 4.90166689,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 13.0673721,68.1161557 left font ',8' noenhanced front
set label 'embree_high' at 17.2608323,67.1985472 left font ',8' noenhanced front
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
set xrange [3.72324437:64.6242362]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 8.38025628,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.8386623,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.7178691,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 21.3938983,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.6413906,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 18.3662802,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.577391,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.233439,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.90166689,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 13.0673721,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 24.2560494,54.6804169 left font ',8' noenhanced front
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
set xrange [3.72324437:64.6242362]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 8.38025628,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.0937647,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.6825112,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 25.5811541,66.6016754 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.6413906,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.2592077,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.577391,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.233439,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 4.90166689,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 13.0673721,68.1161557 left font ',8' noenhanced front
set label 'embree_high' at 17.2608323,67.1985472 left font ',8' noenhanced front
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
set xrange [3.72324437:64.6242362]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 8.38025628,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.8386623,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.7178691,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 21.3938983,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.6413906,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 18.3662802,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.577391,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.233439,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.90166689,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 13.0673721,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 24.2560494,54.6804169 left font ',8' noenhanced front
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
set xrange [3.72324437:64.6242362]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 8.38025628,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.0937647,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.6825112,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 25.5811541,66.6016754 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.6413906,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.2592077,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.577391,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.233439,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 4.90166689,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 13.0673721,68.1161557 left font ',8' noenhanced front
set label 'embree_high' at 17.2608323,67.1985472 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
