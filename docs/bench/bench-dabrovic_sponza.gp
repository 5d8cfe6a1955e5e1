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
set xrange [2.85690752:54.2037835]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.7935276,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.5588575,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.9624988,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.3834859,67.6582542 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9445242,72.4804162 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.0986664,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.1395806,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.1845228,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.57147932,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 17.0904347,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.9412494,77.7503047 left font ',8' noenhanced front
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
set xrange [2.85690752:54.2037835]
set xtics (5, 10, 20, 50)
set yrange [2.80105276:4.24836426]
unset label
set label 'LBVH' at 3.7935276,2.97300057 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.7497985,3.93065745 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.12686805,3.76574641 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.3834859,3.7552604 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9445242,3.81184291 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 15.7310192,3.88573573 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.1395806,3.88012953 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.1845228,3.86861158 left font ',8' noenhanced front
set label 'embree_low' at 4.57147932,2.9378066 left font ',8' noenhanced front
set label 'embree_medium' at 17.0904347,4.07742196 left font ',8' noenhanced front
set label 'embree_high' at 16.9596438,4.02488087 left font ',8' noenhanced front
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
set xrange [2.85690752:54.2037835]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.7935276,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.5588575,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0632801,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.2570897,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9445242,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 15.7310192,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.1395806,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.6173155,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.57147932,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 17.0904347,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 12.0340906,64.9849474 left font ',8' noenhanced front
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
set xrange [2.85690752:54.2037835]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.7935276,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.5588575,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.9624988,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.3834859,67.6582542 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9445242,72.4804162 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.0986664,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.1395806,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.1845228,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.57147932,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 17.0904347,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.9412494,77.7503047 left font ',8' noenhanced front
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
set xrange [2.85690752:54.2037835]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.7935276,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.5588575,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0632801,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.2570897,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9445242,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 15.7310192,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.1395806,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.6173155,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.57147932,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 17.0904347,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 12.0340906,64.9849474 left font ',8' noenhanced front
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
set xrange [2.85690752:54.2037835]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.7935276,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.5588575,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.9624988,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.3834859,67.6582542 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9445242,72.4804162 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.0986664,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.1395806,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 10.1845228,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.57147932,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 17.0904347,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.9412494,77.7503047 left font ',8' noenhanced front
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
set xrange [2.85690752:54.2037835]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.7935276,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.5588575,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.0632801,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.2570897,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9445242,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 15.7310192,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 30.1395806,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.6173155,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.57147932,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 17.0904347,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 12.0340906,64.9849474 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
