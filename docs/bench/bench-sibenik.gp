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
set xrange [2.46516206:66.1125793]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 3.38434258,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 25.5756123,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.16885028,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 14.8492062,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.1851872,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.0643916,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3097073,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.3364454,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.95374965,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 19.5417159,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 13.1496502,54.6804169 left font ',8' noenhanced front
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
set xrange [2.46516206:66.1125793]
set xtics (5, 10, 20, 50)
set yrange [6.46136458:9.01264424]
unset label
set label 'LBVH' at 3.38434258,7.54459565 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 25.7979436,8.38449836 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.5706235,8.35875276 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.980607,8.671034 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.0112277,8.66666756 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.9884627,8.52882129 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3097073,8.711312 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.3364454,8.554068 left font ',8' noenhanced front
set label 'embree_low' at 4.95374965,6.70243037 left font ',8' noenhanced front
set label 'embree_medium' at 12.3625768,8.47294293 left font ',8' noenhanced front
set label 'embree_high' at 19.4625222,8.4807073 left font ',8' noenhanced front
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
set xrange [2.46516206:66.1125793]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 3.38434258,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 25.7979436,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.5706235,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.980607,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.0112277,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.7644894,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3097073,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.3364454,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 4.95374965,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 19.5417159,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 19.4625222,69.0337643 left font ',8' noenhanced front
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
set xrange [2.46516206:66.1125793]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 3.38434258,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 25.5756123,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.16885028,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 14.8492062,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.1851872,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.0643916,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3097073,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.3364454,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.95374965,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 19.5417159,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 13.1496502,54.6804169 left font ',8' noenhanced front
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
set xrange [2.46516206:66.1125793]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 3.38434258,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 25.7979436,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.5706235,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.980607,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.0112277,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.7644894,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3097073,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.3364454,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 4.95374965,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 19.5417159,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 19.4625222,69.0337643 left font ',8' noenhanced front
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
set xrange [2.46516206:66.1125793]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 3.38434258,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 25.5756123,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.16885028,52.9793966 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 14.8492062,53.2017634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.1851872,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.0643916,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3097073,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.3364454,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 4.95374965,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 19.5417159,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 13.1496502,54.6804169 left font ',8' noenhanced front
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
set xrange [2.46516206:66.1125793]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 3.38434258,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 25.7979436,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.5706235,69.7282285 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.980607,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.0112277,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.7644894,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3097073,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.3364454,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 4.95374965,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 19.5417159,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 19.4625222,69.0337643 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
