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
set xrange [51.182709:681.023782]
set xtics (100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 72.3771683,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 315.414039,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 202.335367,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 180.786561,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 277.918718,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 241.590122,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.44355,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 161.743299,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 65.6785368,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 289.893502,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 205.61413,57.38674 left font ',8' noenhanced front
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
set xrange [51.182709:681.023782]
set xtics (100, 200, 500)
set yrange [2.0314518:2.99229843]
unset label
set label 'LBVH' at 72.3771683,2.44858787 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.155598,2.57240112 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 202.335367,2.57486586 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 253.444466,2.6270601 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 277.918718,2.65865813 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 338.684907,2.5387112 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.44355,2.64131704 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 161.743299,2.65292825 left font ',8' noenhanced front
set label 'embree_low' at 65.6785368,2.12224046 left font ',8' noenhanced front
set label 'embree_medium' at 289.893502,2.78519518 left font ',8' noenhanced front
set label 'embree_high' at 281.843638,2.87881261 left font ',8' noenhanced front
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
set xrange [51.182709:681.023782]
set xtics (100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 72.3771683,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.155598,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 148.619063,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 253.444466,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 199.599351,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 338.684907,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.44355,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 162.848699,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 65.6785368,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 289.893502,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 205.61413,47.6984341 left font ',8' noenhanced front
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
set xrange [51.182709:681.023782]
set xtics (100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 72.3771683,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 315.414039,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 202.335367,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 180.786561,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 277.918718,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 241.590122,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.44355,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 161.743299,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 65.6785368,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 289.893502,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 205.61413,57.38674 left font ',8' noenhanced front
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
set xrange [51.182709:681.023782]
set xtics (100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 72.3771683,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.155598,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 148.619063,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 253.444466,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 199.599351,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 338.684907,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.44355,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 162.848699,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 65.6785368,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 289.893502,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 205.61413,47.6984341 left font ',8' noenhanced front
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
set xrange [51.182709:681.023782]
set xtics (100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 72.3771683,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 315.414039,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 202.335367,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 180.786561,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 277.918718,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 241.590122,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.44355,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 161.743299,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 65.6785368,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 289.893502,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 205.61413,57.38674 left font ',8' noenhanced front
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
set xrange [51.182709:681.023782]
set xtics (100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 72.3771683,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 365.155598,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 148.619063,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 253.444466,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 199.599351,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 338.684907,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 406.44355,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 162.848699,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 65.6785368,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 289.893502,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 205.61413,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
