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
set xrange [4.81803082:58.8297241]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 6.13161414,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1260115,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.8956688,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.5210096,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.8442122,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.0107194,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7170588,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.0895633,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 6.58303657,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 18.9284731,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 13.3453975,77.7503047 left font ',8' noenhanced front
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
set xrange [4.81803082:58.8297241]
set xtics (5, 10, 20, 50)
set yrange [4.39827932:6.30818591]
unset label
set label 'LBVH' at 6.0913704,4.66065275 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.3448645,5.84877743 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.8956688,5.69810817 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.3531402,5.88641614 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.6811517,5.74838758 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 22.3831808,5.89449435 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7170588,5.909632 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.0895633,5.82595933 left font ',8' noenhanced front
set label 'embree_low' at 6.58303657,4.57874294 left font ',8' noenhanced front
set label 'embree_medium' at 18.9284731,6.08260639 left font ',8' noenhanced front
set label 'embree_high' at 18.1025873,5.99002605 left font ',8' noenhanced front
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
set xrange [4.81803082:58.8297241]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 5.26292595,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1260115,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 18.0138998,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.5210096,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.8442122,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.0107194,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7170588,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 21.8473069,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 6.58303657,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 18.8042395,64.9849474 left font ',8' noenhanced front
set label 'embree_high' at 13.3453975,66.2234631 left font ',8' noenhanced front
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
set xrange [4.81803082:58.8297241]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 6.13161414,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1260115,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.8956688,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.5210096,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.8442122,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.0107194,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7170588,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.0895633,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 6.58303657,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 18.9284731,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 13.3453975,77.7503047 left font ',8' noenhanced front
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
set xrange [4.81803082:58.8297241]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 5.26292595,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1260115,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 18.0138998,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.5210096,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.8442122,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.0107194,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7170588,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 21.8473069,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 6.58303657,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 18.8042395,64.9849474 left font ',8' noenhanced front
set label 'embree_high' at 13.3453975,66.2234631 left font ',8' noenhanced front
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
set xrange [4.81803082:58.8297241]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 6.13161414,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1260115,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.8956688,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.5210096,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.8442122,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.0107194,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7170588,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.0895633,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 6.58303657,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 18.9284731,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 13.3453975,77.7503047 left font ',8' noenhanced front
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
set xrange [4.81803082:58.8297241]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 5.26292595,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.1260115,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 18.0138998,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 22.5210096,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 24.8442122,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.0107194,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7170588,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 21.8473069,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 6.58303657,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 18.8042395,64.9849474 left font ',8' noenhanced front
set label 'embree_high' at 13.3453975,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
