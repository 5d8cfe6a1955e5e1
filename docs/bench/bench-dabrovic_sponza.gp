# regenerate: gnuplot bench-dabrovic_sponza.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.32277221:54.2608936]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.14672313,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.0687016,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.39217316,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 8.31572789,69.012315 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 14.8978516,68.4182339 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.0565002,71.6782605 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.9452343,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.07183059,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 5.63916882,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 22.1361931,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 14.8966155,77.7503047 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.32277221:54.2608936]
set xtics (5, 10, 20, 50)
set yrange [4.88610375:7.98913508]
unset label
set label 'LBVH' at 3.14672313,5.77230283 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.0687016,7.5002709 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.39217316,7.70201519 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.4429026,7.21539604 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.0219015,6.49740059 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.0565002,6.55583399 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.9452343,6.99769082 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.07183059,7.5082236 left font ',8' noenhanced front
set label 'embree_low' at 5.63916882,5.17930356 left font ',8' noenhanced front
set label 'embree_medium' at 22.1361931,7.35717842 left font ',8' noenhanced front
set label 'embree_high' at 21.6882679,7.48782561 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.32277221:54.2608936]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.14672313,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.0687016,70.8469428 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.4703789,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.3401499,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.0219015,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 24.8495854,72.2198046 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.9452343,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.7573894,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 5.63916882,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 22.1361931,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 14.8966155,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-dabrovic_sponza.png'.outsuffix
set multiplot layout 1,2
set title 'dabrovic_sponza.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.32277221:54.2608936]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.14672313,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.0687016,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.39217316,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 8.31572789,69.012315 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 14.8978516,68.4182339 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.0565002,71.6782605 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.9452343,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.07183059,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 5.63916882,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 22.1361931,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 14.8966155,77.7503047 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dabrovic_sponza.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.32277221:54.2608936]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.14672313,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.0687016,70.8469428 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.4703789,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.3401499,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.0219015,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 24.8495854,72.2198046 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.9452343,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.7573894,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 5.63916882,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 22.1361931,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 14.8966155,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-dabrovic_sponza.svg'.outsuffix
set multiplot layout 1,2
set title 'dabrovic_sponza.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.32277221:54.2608936]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.14672313,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.0687016,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.39217316,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 8.31572789,69.012315 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 14.8978516,68.4182339 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.0565002,71.6782605 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.9452343,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.07183059,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 5.63916882,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 22.1361931,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 14.8966155,77.7503047 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dabrovic_sponza.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.32277221:54.2608936]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.14672313,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 15.0687016,70.8469428 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.4703789,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 12.3401499,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.0219015,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 24.8495854,72.2198046 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.9452343,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.7573894,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 5.63916882,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 22.1361931,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 14.8966155,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
