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
set xrange [2.69064691:56.234303]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.60621418,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 27.0585706,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.870736,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.4354982,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 13.3222442,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.6850126,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.6712035,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.2838462,38.2564636 left font ',8' noenhanced front
set label 'embree_low' at 4.36971306,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.997621,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 23.3555484,36.8708212 left font ',8' noenhanced front
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
set xrange [2.69064691:56.234303]
set xtics (5, 10, 20, 50)
set yrange [7.24516502:8.79125665]
unset label
set label 'LBVH' at 3.60621418,8.0854372 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 27.0585706,8.58171313 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.870736,8.515146 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.3977041,8.64479791 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 19.6524607,8.64819859 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.8912994,8.49141349 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.6712035,8.43642613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.2019105,8.58092006 left font ',8' noenhanced front
set label 'embree_low' at 4.36971306,7.39125241 left font ',8' noenhanced front
set label 'embree_medium' at 22.7157111,8.09175493 left font ',8' noenhanced front
set label 'embree_high' at 23.3555484,8.01166612 left font ',8' noenhanced front
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
set xrange [2.69064691:56.234303]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.60621418,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 27.2758891,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.65437966,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.2886148,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 16.2455416,37.7160633 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.8912994,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.6712035,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.2838462,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.36971306,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.997621,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 23.3555484,36.1348177 left font ',8' noenhanced front
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
set xrange [2.69064691:56.234303]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.60621418,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 27.0585706,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.870736,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.4354982,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 13.3222442,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.6850126,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.6712035,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.2838462,38.2564636 left font ',8' noenhanced front
set label 'embree_low' at 4.36971306,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.997621,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 23.3555484,36.8708212 left font ',8' noenhanced front
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
set xrange [2.69064691:56.234303]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.60621418,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 27.2758891,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.65437966,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.2886148,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 16.2455416,37.7160633 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.8912994,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.6712035,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.2838462,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.36971306,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.997621,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 23.3555484,36.1348177 left font ',8' noenhanced front
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
set xrange [2.69064691:56.234303]
set xtics (5, 10, 20, 50)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 3.60621418,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 27.0585706,38.1166438 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.870736,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.4354982,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 13.3222442,37.8200069 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.6850126,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.6712035,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.2838462,38.2564636 left font ',8' noenhanced front
set label 'embree_low' at 4.36971306,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.997621,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 23.3555484,36.8708212 left font ',8' noenhanced front
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
set xrange [2.69064691:56.234303]
set xtics (5, 10, 20, 50)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 3.60621418,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 27.2758891,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.65437966,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.2886148,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 16.2455416,37.7160633 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.8912994,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.6712035,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.2838462,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.36971306,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.997621,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 23.3555484,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
