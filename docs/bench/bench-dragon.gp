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
set xrange [30.3233527:776.996214]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 41.4475289,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 288.246796,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 192.118243,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 161.237487,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 270.972182,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 333.172442,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.911374,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 142.447515,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 67.427899,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 300.42946,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 201.817335,57.38674 left font ',8' noenhanced front
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
set xrange [30.3233527:776.996214]
set xtics (50, 100, 200, 500)
set yrange [5.21293492:7.61558535]
unset label
set label 'LBVH' at 41.4475289,6.12611666 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 343.365771,6.59948037 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 193.7651,6.53289412 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 244.131533,6.35405076 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 268.669123,6.6984648 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 333.172442,6.40586659 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.911374,6.51852986 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 230.136534,5.98709313 left font ',8' noenhanced front
set label 'embree_low' at 67.427899,5.43995701 left font ',8' noenhanced front
set label 'embree_medium' at 300.42946,6.81271067 left font ',8' noenhanced front
set label 'embree_high' at 299.633478,7.33180774 left font ',8' noenhanced front
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
set xrange [30.3233527:776.996214]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 41.4475289,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 346.309138,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 130.50997,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 246.224254,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 178.964483,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 333.172442,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 403.452934,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 143.66859,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 67.427899,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 300.42946,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 201.817335,47.6984341 left font ',8' noenhanced front
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
set xrange [30.3233527:776.996214]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 41.4475289,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 288.246796,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 192.118243,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 161.237487,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 270.972182,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 333.172442,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.911374,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 142.447515,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 67.427899,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 300.42946,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 201.817335,57.38674 left font ',8' noenhanced front
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
set xrange [30.3233527:776.996214]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 41.4475289,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 346.309138,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 130.50997,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 246.224254,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 178.964483,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 333.172442,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 403.452934,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 143.66859,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 67.427899,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 300.42946,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 201.817335,47.6984341 left font ',8' noenhanced front
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
set xrange [30.3233527:776.996214]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 41.4475289,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 288.246796,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 192.118243,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 161.237487,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 270.972182,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 333.172442,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.911374,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 142.447515,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 67.427899,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 300.42946,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 201.817335,57.38674 left font ',8' noenhanced front
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
set xrange [30.3233527:776.996214]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 41.4475289,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 346.309138,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 130.50997,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 246.224254,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 178.964483,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 333.172442,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 403.452934,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 143.66859,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 67.427899,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 300.42946,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 201.817335,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
