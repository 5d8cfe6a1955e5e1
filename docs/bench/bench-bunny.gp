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
set xrange [2.83718119:67.7533739]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.85177068,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 26.3123616,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.7258096,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.7627141,38.2104198 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7849762,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.8374794,38.9873551 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.9843649,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 23.5354168,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 7.26805735,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 25.1775368,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.7834475,36.8708212 left font ',8' noenhanced front
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
set xrange [2.83718119:67.7533739]
set xtics (5, 10, 20, 50)
set yrange [7.27525631:9.20456639]
unset label
set label 'LBVH' at 3.85177068,8.28505023 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 26.5329941,8.76281929 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.7258096,8.83151512 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.6503003,8.76671692 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.3450969,8.97669512 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.8374794,8.51041737 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.9843649,8.1465144 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 23.5354168,7.81936008 left font ',8' noenhanced front
set label 'embree_low' at 7.26805735,7.45755333 left font ',8' noenhanced front
set label 'embree_medium' at 25.1775368,8.32442264 left font ',8' noenhanced front
set label 'embree_high' at 24.4995725,8.22521137 left font ',8' noenhanced front
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
set xrange [2.83718119:67.7533739]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.85177068,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 26.5329941,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.40287446,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.503531,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.3450969,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.8374794,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.9843649,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 23.3397104,38.2215532 left font ',8' noenhanced front
set label 'embree_low' at 7.26805735,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 25.1775368,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.7834475,36.1348177 left font ',8' noenhanced front
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
set xrange [2.83718119:67.7533739]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.85177068,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 26.3123616,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.7258096,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.7627141,38.2104198 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7849762,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.8374794,38.9873551 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.9843649,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 23.5354168,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 7.26805735,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 25.1775368,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.7834475,36.8708212 left font ',8' noenhanced front
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
set xrange [2.83718119:67.7533739]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.85177068,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 26.5329941,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.40287446,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.503531,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.3450969,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.8374794,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.9843649,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 23.3397104,38.2215532 left font ',8' noenhanced front
set label 'embree_low' at 7.26805735,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 25.1775368,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.7834475,36.1348177 left font ',8' noenhanced front
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
set xrange [2.83718119:67.7533739]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.85177068,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 26.3123616,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.7258096,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.7627141,38.2104198 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7849762,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.8374794,38.9873551 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.9843649,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 23.5354168,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 7.26805735,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 25.1775368,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 16.7834475,36.8708212 left font ',8' noenhanced front
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
set xrange [2.83718119:67.7533739]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.85177068,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 26.5329941,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.40287446,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 17.503531,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.3450969,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.8374794,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.9843649,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 23.3397104,38.2215532 left font ',8' noenhanced front
set label 'embree_low' at 7.26805735,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 25.1775368,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 16.7834475,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
