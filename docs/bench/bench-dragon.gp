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
set xrange [48.1869613:742.013521]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 62.7108151,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 313.510896,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 230.12608,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 196.884445,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 307.223458,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 357.949228,60.6771969 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 427.043994,59.8781052 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 178.729503,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 83.0188878,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 297.267502,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 213.297041,57.38674 left font ',8' noenhanced front
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
set xrange [48.1869613:742.013521]
set xtics (50, 100, 200, 500)
set yrange [2.57462966:4.23579066]
unset label
set label 'LBVH' at 62.7108151,3.50658722 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.964649,4.03959054 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 230.12608,3.21019198 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 281.325496,3.83094412 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 257.01326,3.06471646 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 355.382859,3.17745283 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 430.127858,3.11773176 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 178.729503,3.11882491 left font ',8' noenhanced front
set label 'embree_low' at 83.0188878,2.73158976 left font ',8' noenhanced front
set label 'embree_medium' at 297.267502,3.36100362 left font ',8' noenhanced front
set label 'embree_high' at 297.625523,3.27102157 left font ',8' noenhanced front
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
set xrange [48.1869613:742.013521]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 62.7108151,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.964649,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 166.113701,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 281.325496,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 216.561694,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 355.382859,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 427.043994,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 180.020184,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 83.0188878,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 297.267502,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 213.297041,47.6984341 left font ',8' noenhanced front
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
set xrange [48.1869613:742.013521]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 62.7108151,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 313.510896,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 230.12608,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 196.884445,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 307.223458,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 357.949228,60.6771969 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 427.043994,59.8781052 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 178.729503,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 83.0188878,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 297.267502,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 213.297041,57.38674 left font ',8' noenhanced front
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
set xrange [48.1869613:742.013521]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 62.7108151,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.964649,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 166.113701,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 281.325496,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 216.561694,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 355.382859,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 427.043994,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 180.020184,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 83.0188878,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 297.267502,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 213.297041,47.6984341 left font ',8' noenhanced front
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
set xrange [48.1869613:742.013521]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 62.7108151,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 313.510896,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 230.12608,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 196.884445,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 307.223458,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 357.949228,60.6771969 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 427.043994,59.8781052 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 178.729503,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 83.0188878,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 297.267502,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 213.297041,57.38674 left font ',8' noenhanced front
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
set xrange [48.1869613:742.013521]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 62.7108151,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.964649,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 166.113701,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 281.325496,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 216.561694,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 355.382859,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 427.043994,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 180.020184,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 83.0188878,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 297.267502,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 213.297041,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
