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
set xrange [5.17335718:57.8545154]
set xtics (10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 6.5283103,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 31.6156383,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.9590164,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.6156381,69.012315 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.7042216,71.1263555 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.0065208,67.246789 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7459383,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.9126857,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 7.2794063,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 13.6834982,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 20.0691279,77.7503047 left font ',8' noenhanced front
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
set xrange [5.17335718:57.8545154]
set xtics (10, 20, 50)
set yrange [4.38678783:6.29188698]
unset label
set label 'LBVH' at 6.5283103,4.78096704 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 31.6156383,5.86242332 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 13.4673636,5.729237 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 21.2650131,5.66417576 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.7042216,5.82905413 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.7623481,5.69622597 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7459383,5.76886672 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.597548,5.9253881 left font ',8' noenhanced front
set label 'embree_low' at 7.2794063,4.5667972 left font ',8' noenhanced front
set label 'embree_medium' at 19.0286954,6.11561037 left font ',8' noenhanced front
set label 'embree_high' at 20.0691279,6.01624982 left font ',8' noenhanced front
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
set xrange [5.17335718:57.8545154]
set xtics (10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 5.63356291,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 31.6156383,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 18.0734861,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 21.1303297,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.8489368,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.6525222,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7459383,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.597548,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 7.2794063,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 13.6834982,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 19.9420187,64.9849474 left font ',8' noenhanced front
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
set xrange [5.17335718:57.8545154]
set xtics (10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 6.5283103,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 31.6156383,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.9590164,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.6156381,69.012315 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.7042216,71.1263555 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.0065208,67.246789 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7459383,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.9126857,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 7.2794063,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 13.6834982,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 20.0691279,77.7503047 left font ',8' noenhanced front
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
set xrange [5.17335718:57.8545154]
set xtics (10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 5.63356291,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 31.6156383,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 18.0734861,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 21.1303297,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.8489368,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.6525222,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7459383,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.597548,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 7.2794063,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 13.6834982,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 19.9420187,64.9849474 left font ',8' noenhanced front
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
set xrange [5.17335718:57.8545154]
set xtics (10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 6.5283103,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 31.6156383,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 17.9590164,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 15.6156381,69.012315 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.7042216,71.1263555 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 23.0065208,67.246789 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7459383,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.9126857,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 7.2794063,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 13.6834982,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 20.0691279,77.7503047 left font ',8' noenhanced front
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
set xrange [5.17335718:57.8545154]
set xtics (10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 5.63356291,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 31.6156383,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 18.0734861,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 21.1303297,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.8489368,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.6525222,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 35.7459383,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.597548,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 7.2794063,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 13.6834982,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 19.9420187,64.9849474 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
