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
set xrange [3.33419257:65.8027084]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 9.0949692,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.8607421,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.3761397,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.2963156,38.2104198 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3869453,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 30.7861492,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.3025618,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.569208,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 4.44413467,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.1206833,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 22.1590571,36.8708212 left font ',8' noenhanced front
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
set xrange [3.33419257:65.8027084]
set xtics (5, 10, 20, 50)
set yrange [4.60181927:6.20497503]
unset label
set label 'LBVH' at 9.0949692,4.75329855 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1196644,5.09254991 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.536691,4.98012249 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.1689146,5.17568429 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 25.4612277,5.24502042 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 31.028725,5.02849679 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.3025618,5.1709385 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 16.4287137,5.7005049 left font ',8' noenhanced front
set label 'embree_low' at 4.44413467,4.92639571 left font ',8' noenhanced front
set label 'embree_medium' at 21.2207152,5.96175031 left font ',8' noenhanced front
set label 'embree_high' at 22.1590571,6.01562592 left font ',8' noenhanced front
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
set xrange [3.33419257:65.8027084]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 9.0949692,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1196644,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.124673,37.6863385 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.6775586,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 25.6618464,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 31.028725,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.3025618,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.569208,37.9630935 left font ',8' noenhanced front
set label 'embree_low' at 4.44413467,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.1206833,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 22.1590571,36.1348177 left font ',8' noenhanced front
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
set xrange [3.33419257:65.8027084]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 9.0949692,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.8607421,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.3761397,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.2963156,38.2104198 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3869453,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 30.7861492,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.3025618,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.569208,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 4.44413467,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.1206833,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 22.1590571,36.8708212 left font ',8' noenhanced front
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
set xrange [3.33419257:65.8027084]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 9.0949692,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1196644,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.124673,37.6863385 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.6775586,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 25.6618464,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 31.028725,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.3025618,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.569208,37.9630935 left font ',8' noenhanced front
set label 'embree_low' at 4.44413467,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.1206833,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 22.1590571,36.1348177 left font ',8' noenhanced front
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
set xrange [3.33419257:65.8027084]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 9.0949692,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 32.8607421,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.3761397,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.2963156,38.2104198 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3869453,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 30.7861492,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.3025618,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.569208,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 4.44413467,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.1206833,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 22.1590571,36.8708212 left font ',8' noenhanced front
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
set xrange [3.33419257:65.8027084]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 9.0949692,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1196644,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.124673,37.6863385 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.6775586,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 25.6618464,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 31.028725,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 36.3025618,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.569208,37.9630935 left font ',8' noenhanced front
set label 'embree_low' at 4.44413467,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.1206833,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 22.1590571,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
