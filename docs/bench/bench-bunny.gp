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
set xrange [3.14687106:49.0864988]
set xtics (5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 4.1004497,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9661317,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.9942149,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.1926594,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7927971,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.3904541,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.3812069,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.0139024,38.2564636 left font ',8' noenhanced front
set label 'embree_low' at 4.36659057,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 21.2819344,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 15.2546447,36.8708212 left font ',8' noenhanced front
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
set xrange [3.14687106:49.0864988]
set xtics (5, 10, 20)
set yrange [11.9092962:15.0023299]
unset label
set label 'LBVH' at 4.1004497,13.311507 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9661317,14.2403849 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0884958,14.1482617 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.0991262,13.9020188 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3102491,13.970651 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 16.4607494,14.2252616 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.3812069,14.1313295 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.94176888,14.0133011 left font ',8' noenhanced front
set label 'embree_low' at 4.36659057,12.2015513 left font ',8' noenhanced front
set label 'embree_medium' at 21.2819344,14.4669494 left font ',8' noenhanced front
set label 'embree_high' at 21.3191485,14.6370109 left font ',8' noenhanced front
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
set xrange [3.14687106:49.0864988]
set xtics (5, 10, 20)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 4.1004497,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.1400204,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.36530616,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.0688148,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.3048783,37.7160633 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.5601659,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.3812069,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.0139024,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.36659057,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 21.2819344,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 15.2546447,36.1348177 left font ',8' noenhanced front
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
set xrange [3.14687106:49.0864988]
set xtics (5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 4.1004497,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9661317,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.9942149,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.1926594,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7927971,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.3904541,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.3812069,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.0139024,38.2564636 left font ',8' noenhanced front
set label 'embree_low' at 4.36659057,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 21.2819344,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 15.2546447,36.8708212 left font ',8' noenhanced front
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
set xrange [3.14687106:49.0864988]
set xtics (5, 10, 20)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 4.1004497,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.1400204,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.36530616,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.0688148,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.3048783,37.7160633 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.5601659,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.3812069,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.0139024,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.36659057,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 21.2819344,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 15.2546447,36.1348177 left font ',8' noenhanced front
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
set xrange [3.14687106:49.0864988]
set xtics (5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 4.1004497,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9661317,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.9942149,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.1926594,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7927971,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.3904541,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.3812069,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.0139024,38.2564636 left font ',8' noenhanced front
set label 'embree_low' at 4.36659057,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 21.2819344,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 15.2546447,36.8708212 left font ',8' noenhanced front
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
set xrange [3.14687106:49.0864988]
set xtics (5, 10, 20)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 4.1004497,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.1400204,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.36530616,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.0688148,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.3048783,37.7160633 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.5601659,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.3812069,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.0139024,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.36659057,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 21.2819344,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 15.2546447,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
