# regenerate: gnuplot bench-dragon.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dragon.png'.outsuffix
set title 'dragon.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [40.5500365:781.217618]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 53.9235881,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 317.828137,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 198.588462,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 266.878242,62.0713194 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 198.438865,59.8198299 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 347.794305,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 433.065891,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 159.227286,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 84.909642,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 298.769735,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 202.032743,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-dragon.png'.outsuffix
set title 'dragon.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [40.5500365:781.217618]
set xtics (50, 100, 200, 500)
set yrange [3.98771944:5.70131105]
unset label
set label 'LBVH' at 53.9235881,5.17568395 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 375.736933,4.98001561 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 200.140516,4.75353433 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 264.80865,4.47492292 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 289.696625,4.64834007 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 350.512466,4.5551226 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 433.065891,4.40808863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 159.227286,4.49207203 left font ',8' noenhanced front
set label 'embree_low' at 84.909642,4.14963361 left font ',8' noenhanced front
set label 'embree_medium' at 298.769735,5.17504573 left font ',8' noenhanced front
set label 'embree_high' at 289.709112,5.49891834 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-dragon.png'.outsuffix
set title 'dragon.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [40.5500365:781.217618]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 53.9235881,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 375.736933,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 139.570817,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 266.878242,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 198.438865,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 347.794305,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 429.707543,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 160.471715,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 84.909642,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 298.769735,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 202.032743,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-dragon.png'.outsuffix
set multiplot layout 1,2
set title 'dragon.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [40.5500365:781.217618]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 53.9235881,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 317.828137,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 198.588462,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 266.878242,62.0713194 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 198.438865,59.8198299 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 347.794305,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 433.065891,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 159.227286,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 84.909642,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 298.769735,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 202.032743,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dragon.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [40.5500365:781.217618]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 53.9235881,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 375.736933,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 139.570817,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 266.878242,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 198.438865,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 347.794305,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 429.707543,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 160.471715,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 84.909642,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 298.769735,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 202.032743,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-dragon.svg'.outsuffix
set multiplot layout 1,2
set title 'dragon.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [40.5500365:781.217618]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 53.9235881,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 317.828137,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 198.588462,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 266.878242,62.0713194 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 198.438865,59.8198299 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 347.794305,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 433.065891,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 159.227286,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 84.909642,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 298.769735,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 202.032743,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dragon.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [40.5500365:781.217618]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 53.9235881,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 375.736933,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 139.570817,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 266.878242,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 198.438865,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 347.794305,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 429.707543,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 160.471715,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 84.909642,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 298.769735,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 202.032743,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
