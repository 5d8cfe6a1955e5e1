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
set xrange [2.24666153:52.4688559]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.04353533,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9236809,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.5400725,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.3345242,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3583019,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5250077,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 27.9907754,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.05354368,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.37543107,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 16.9649368,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.2413224,77.7503047 left font ',8' noenhanced front
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
set xrange [2.24666153:52.4688559]
set xtics (5, 10, 20, 50)
set yrange [5.03432133:7.70309698]
unset label
set label 'LBVH' at 3.04353533,5.35348547 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 24.1228691,6.9536644 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.92656732,7.09076111 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.3345242,6.9736583 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3583019,7.21192056 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 21.733162,7.06606206 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 27.9907754,7.15915014 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.4275446,7.38788725 left font ',8' noenhanced front
set label 'embree_low' at 4.37543107,5.2864891 left font ',8' noenhanced front
set label 'embree_medium' at 16.8248534,7.28990817 left font ',8' noenhanced front
set label 'embree_high' at 11.2413224,7.20741483 left font ',8' noenhanced front
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
set xrange [2.24666153:52.4688559]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.04353533,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9236809,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.636155,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.3345242,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3583019,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5250077,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 27.9907754,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.3084131,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.37543107,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 16.9649368,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 11.3349175,64.9849474 left font ',8' noenhanced front
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
set xrange [2.24666153:52.4688559]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.04353533,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9236809,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.5400725,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.3345242,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3583019,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5250077,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 27.9907754,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.05354368,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.37543107,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 16.9649368,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.2413224,77.7503047 left font ',8' noenhanced front
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
set xrange [2.24666153:52.4688559]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.04353533,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9236809,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.636155,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.3345242,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3583019,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5250077,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 27.9907754,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.3084131,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.37543107,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 16.9649368,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 11.3349175,64.9849474 left font ',8' noenhanced front
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
set xrange [2.24666153:52.4688559]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 3.04353533,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9236809,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.5400725,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.3345242,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3583019,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5250077,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 27.9907754,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.05354368,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.37543107,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 16.9649368,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.2413224,77.7503047 left font ',8' noenhanced front
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
set xrange [2.24666153:52.4688559]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 3.04353533,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.9236809,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.636155,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.3345242,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 18.3583019,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5250077,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 27.9907754,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.3084131,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.37543107,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 16.9649368,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 11.3349175,64.9849474 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
