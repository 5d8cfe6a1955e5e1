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
set xrange [2.3645525:73.2309843]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.29154903,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.984612,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.1435707,38.740404 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7541569,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.8550953,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 29.8996267,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.9285485,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 13.0242404,39.1916483 left font ',8' noenhanced front
set label 'embree_low' at 6.88545463,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 24.3892649,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.0913118,36.8708212 left font ',8' noenhanced front
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
set xrange [2.3645525:73.2309843]
set xtics (5, 10, 20, 50)
set yrange [8.4738772:11.9544023]
unset label
set label 'LBVH' at 3.29154903,10.7165825 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.984612,11.5433167 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.1435707,11.3330828 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7541569,9.75437125 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.3741483,10.2128568 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 30.1709724,9.52869427 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.9285485,10.1016442 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 13.0242404,10.1202295 left font ',8' noenhanced front
set label 'embree_low' at 6.88545463,8.80274571 left font ',8' noenhanced front
set label 'embree_medium' at 24.3892649,10.5322412 left font ',8' noenhanced front
set label 'embree_high' at 16.237344,10.2777145 left font ',8' noenhanced front
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
set xrange [2.3645525:73.2309843]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.29154903,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.984612,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.1435707,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.5405214,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.5953491,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 30.1709724,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.9285485,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 13.1424383,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 6.88545463,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 24.3892649,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.0913118,36.1348177 left font ',8' noenhanced front
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
set xrange [2.3645525:73.2309843]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.29154903,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.984612,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.1435707,38.740404 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7541569,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.8550953,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 29.8996267,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.9285485,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 13.0242404,39.1916483 left font ',8' noenhanced front
set label 'embree_low' at 6.88545463,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 24.3892649,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.0913118,36.8708212 left font ',8' noenhanced front
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
set xrange [2.3645525:73.2309843]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.29154903,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.984612,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.1435707,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.5405214,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.5953491,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 30.1709724,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.9285485,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 13.1424383,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 6.88545463,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 24.3892649,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.0913118,36.1348177 left font ',8' noenhanced front
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
set xrange [2.3645525:73.2309843]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.29154903,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.984612,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.1435707,38.740404 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7541569,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.8550953,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 29.8996267,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.9285485,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 13.0242404,39.1916483 left font ',8' noenhanced front
set label 'embree_low' at 6.88545463,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 24.3892649,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.0913118,36.8708212 left font ',8' noenhanced front
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
set xrange [2.3645525:73.2309843]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.29154903,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.984612,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.1435707,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.5405214,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.5953491,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 30.1709724,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.9285485,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 13.1424383,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 6.88545463,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 24.3892649,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.0913118,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
