# regenerate: gnuplot bench-conference.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-conference.png'.outsuffix
set title 'conference.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [12.0273213:393.136985]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 16.8297495,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 140.475642,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 76.7113117,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 59.6432631,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 100.289292,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 148.060983,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.127689,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.0378303,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.6571459,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 98.9082258,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 65.0759112,43.2759982 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-conference.png'.outsuffix
set title 'conference.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [12.0273213:393.136985]
set xtics (20, 50, 100, 200)
set yrange [7.94247106:14.6375472]
unset label
set label 'LBVH' at 16.8297495,9.97049961 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 140.475642,13.3527635 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.418474,13.1187166 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 59.0984647,13.4113688 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 79.8769863,13.6444873 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.708552,13.8497198 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.127689,13.5641371 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.0378303,13.8467901 left font ',8' noenhanced front
set label 'embree_low' at 24.6571459,8.57507668 left font ',8' noenhanced front
set label 'embree_medium' at 98.9082258,12.622712 left font ',8' noenhanced front
set label 'embree_high' at 98.6165256,12.4205053 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-conference.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-conference.png'.outsuffix
set title 'conference.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [12.0273213:393.136985]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 16.8297495,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 140.475642,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.418474,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 59.0984647,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 100.289292,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 148.060983,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.127689,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.5820698,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.6571459,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 98.9082258,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 65.0759112,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-conference.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-conference.png'.outsuffix
set multiplot layout 1,2
set title 'conference.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [12.0273213:393.136985]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 16.8297495,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 140.475642,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 76.7113117,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 59.6432631,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 100.289292,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 148.060983,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.127689,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.0378303,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.6571459,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 98.9082258,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 65.0759112,43.2759982 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'conference.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [12.0273213:393.136985]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 16.8297495,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 140.475642,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.418474,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 59.0984647,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 100.289292,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 148.060983,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.127689,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.5820698,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.6571459,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 98.9082258,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 65.0759112,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-conference.svg'.outsuffix
set multiplot layout 1,2
set title 'conference.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [12.0273213:393.136985]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 16.8297495,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 140.475642,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 76.7113117,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 59.6432631,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 100.289292,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 148.060983,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.127689,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.0378303,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.6571459,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 98.9082258,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 65.0759112,43.2759982 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'conference.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [12.0273213:393.136985]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 16.8297495,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 140.475642,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.418474,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 59.0984647,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 100.289292,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 148.060983,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.127689,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.5820698,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.6571459,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 98.9082258,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 65.0759112,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
