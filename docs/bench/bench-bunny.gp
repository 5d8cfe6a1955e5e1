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
set xrange [4.24322787:68.2303493]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 5.54524225,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.1610938,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.735055,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.9492001,38.5221481 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.6574269,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.0172057,38.9873551 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 39.2115811,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 24.3726568,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 7.77762583,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 24.9376514,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.1867949,36.8708212 left font ',8' noenhanced front
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
set xrange [4.24322787:68.2303493]
set xtics (5, 10, 20, 50)
set yrange [4.54817353:5.92070914]
unset label
set label 'LBVH' at 5.54524225,5.07292214 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.1610938,5.34263916 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.5188578,5.20975975 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.6077725,5.57662071 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.8089731,5.75859863 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.0172057,5.4828314 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 39.2115811,5.29373745 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 16.1621907,5.39763771 left font ',8' noenhanced front
set label 'embree_low' at 7.77762583,4.67786193 left font ',8' noenhanced front
set label 'embree_medium' at 24.9376514,5.40949244 left font ',8' noenhanced front
set label 'embree_high' at 16.1867949,5.48223042 left font ',8' noenhanced front
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
set xrange [4.24322787:68.2303493]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 5.54524225,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.3970327,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.735055,37.7568275 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.4722571,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.8089731,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.0172057,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 39.2115811,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 24.1951572,38.2215532 left font ',8' noenhanced front
set label 'embree_low' at 7.77762583,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 24.9376514,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.1867949,36.1348177 left font ',8' noenhanced front
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
set xrange [4.24322787:68.2303493]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 5.54524225,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.1610938,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.735055,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.9492001,38.5221481 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.6574269,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.0172057,38.9873551 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 39.2115811,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 24.3726568,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 7.77762583,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 24.9376514,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.1867949,36.8708212 left font ',8' noenhanced front
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
set xrange [4.24322787:68.2303493]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 5.54524225,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.3970327,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.735055,37.7568275 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.4722571,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.8089731,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.0172057,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 39.2115811,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 24.1951572,38.2215532 left font ',8' noenhanced front
set label 'embree_low' at 7.77762583,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 24.9376514,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.1867949,36.1348177 left font ',8' noenhanced front
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
set xrange [4.24322787:68.2303493]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 5.54524225,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.1610938,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.735055,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.9492001,38.5221481 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.6574269,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.0172057,38.9873551 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 39.2115811,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 24.3726568,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 7.77762583,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 24.9376514,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.1867949,36.8708212 left font ',8' noenhanced front
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
set xrange [4.24322787:68.2303493]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 5.54524225,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.3970327,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.735055,37.7568275 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.4722571,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 20.8089731,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.0172057,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 39.2115811,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 24.1951572,38.2215532 left font ',8' noenhanced front
set label 'embree_low' at 7.77762583,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 24.9376514,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.1867949,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
