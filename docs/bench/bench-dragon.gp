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
set xrange [43.3297255:751.789651]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 57.0416972,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 294.92073,59.8746541 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 217.618361,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 185.321554,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 290.286462,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 351.252238,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 425.545738,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 167.841278,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 87.3880315,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 200.212885,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 308.313365,57.38674 left font ',8' noenhanced front
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
set xrange [43.3297255:751.789651]
set xtics (50, 100, 200, 500)
set yrange [2.52832186:3.21916358]
unset label
set label 'LBVH' at 57.0416972,2.66985965 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 404.279494,3.08357329 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 154.866217,2.87361555 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 268.960531,3.03870956 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 288.114715,2.90746991 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 351.252238,2.879053 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 425.545738,3.00987116 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 255.968348,2.84881369 left font ',8' noenhanced front
set label 'embree_low' at 87.3880315,2.59359824 left font ',8' noenhanced front
set label 'embree_medium' at 297.863355,3.1375681 left font ',8' noenhanced front
set label 'embree_high' at 217.767047,3.07245054 left font ',8' noenhanced front
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
set xrange [43.3297255:751.789651]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 57.0416972,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 404.279494,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 154.866217,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 268.960531,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 201.523411,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 291.566611,50.8112415 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 425.545738,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 169.10643,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 87.3880315,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 200.212885,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 308.313365,47.6984341 left font ',8' noenhanced front
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
set xrange [43.3297255:751.789651]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 57.0416972,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 294.92073,59.8746541 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 217.618361,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 185.321554,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 290.286462,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 351.252238,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 425.545738,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 167.841278,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 87.3880315,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 200.212885,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 308.313365,57.38674 left font ',8' noenhanced front
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
set xrange [43.3297255:751.789651]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 57.0416972,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 404.279494,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 154.866217,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 268.960531,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 201.523411,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 291.566611,50.8112415 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 425.545738,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 169.10643,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 87.3880315,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 200.212885,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 308.313365,47.6984341 left font ',8' noenhanced front
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
set xrange [43.3297255:751.789651]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 57.0416972,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 294.92073,59.8746541 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 217.618361,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 185.321554,59.4901949 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 290.286462,61.7556733 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 351.252238,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 425.545738,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 167.841278,60.7547111 left font ',8' noenhanced front
set label 'embree_low' at 87.3880315,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 200.212885,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 308.313365,57.38674 left font ',8' noenhanced front
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
set xrange [43.3297255:751.789651]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 57.0416972,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 404.279494,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 154.866217,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 268.960531,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 201.523411,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 291.566611,50.8112415 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 425.545738,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 169.10643,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 87.3880315,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 200.212885,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 308.313365,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
