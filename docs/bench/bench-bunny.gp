# regenerate: gnuplot bench-bunny.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-bunny.png'.outsuffix
set title 'bunny.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.16760882:53.3800745]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.95148748,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.4425043,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.33839407,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.53143977,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 7.39359226,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.7075359,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.9643028,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.69977971,39.1916483 left font ',8' noenhanced front
set label 'embree_low' at 5.21806014,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 28.1772678,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 18.9393243,36.8708212 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-bunny.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-bunny.png'.outsuffix
set title 'bunny.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.16760882:53.3800745]
set xtics (5, 10, 20, 50)
set yrange [9.40995876:13.6738654]
unset label
set label 'LBVH' at 2.95148748,12.5189962 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.4425043,12.9262753 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.40899298,12.4880826 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.53143977,12.698996 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.1380205,12.0574886 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.8320606,13.1702544 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.9643028,12.1057488 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.07772406,12.2923554 left font ',8' noenhanced front
set label 'embree_low' at 5.21806014,9.81284757 left font ',8' noenhanced front
set label 'embree_medium' at 28.1772678,11.0869436 left font ',8' noenhanced front
set label 'embree_high' at 27.983071,10.3992809 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-bunny.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-bunny.png'.outsuffix
set title 'bunny.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.16760882:53.3800745]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 2.95148748,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.4425043,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.69132119,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.45141719,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.1380205,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.8320606,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.9643028,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.22351055,37.6341447 left font ',8' noenhanced front
set label 'embree_low' at 5.21806014,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 28.1772678,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 18.9393243,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-bunny.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-bunny.png'.outsuffix
set multiplot layout 1,2
set title 'bunny.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.16760882:53.3800745]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.95148748,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.4425043,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.33839407,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.53143977,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 7.39359226,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.7075359,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.9643028,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.69977971,39.1916483 left font ',8' noenhanced front
set label 'embree_low' at 5.21806014,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 28.1772678,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 18.9393243,36.8708212 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'bunny.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.16760882:53.3800745]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 2.95148748,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.4425043,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.69132119,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.45141719,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.1380205,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.8320606,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.9643028,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.22351055,37.6341447 left font ',8' noenhanced front
set label 'embree_low' at 5.21806014,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 28.1772678,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 18.9393243,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-bunny.svg'.outsuffix
set multiplot layout 1,2
set title 'bunny.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.16760882:53.3800745]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.95148748,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.4425043,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.33839407,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.53143977,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 7.39359226,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.7075359,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.9643028,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.69977971,39.1916483 left font ',8' noenhanced front
set label 'embree_low' at 5.21806014,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 28.1772678,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 18.9393243,36.8708212 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'bunny.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.16760882:53.3800745]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 2.95148748,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.4425043,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.69132119,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.45141719,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.1380205,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.8320606,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.9643028,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.22351055,37.6341447 left font ',8' noenhanced front
set label 'embree_low' at 5.21806014,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 28.1772678,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 18.9393243,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
