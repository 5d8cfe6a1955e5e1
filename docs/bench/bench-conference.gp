# regenerate: gnuplot bench-conference.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-conference.png'.outsuffix
set title 'conference.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [20.1211311:380.759959]
set xtics (50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 26.7109998,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.828878,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 97.9432753,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.7777239,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 126.605662,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 143.57701,35.3866648 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 211.828861,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 77.1926844,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 31.9082658,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 105.106922,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 73.4764424,43.2759982 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-conference.png'.outsuffix
set title 'conference.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [20.1211311:380.759959]
set xtics (50, 100, 200)
set yrange [5.52039021:9.31839106]
unset label
set label 'LBVH' at 26.7109998,7.15887103 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.828878,7.65802108 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 98.7040894,8.307469 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.2090429,8.86980829 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 126.605662,8.85084112 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 143.57701,8.43387371 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 211.828861,8.36541951 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 118.325142,8.56969022 left font ',8' noenhanced front
set label 'embree_low' at 31.9082658,5.87925643 left font ',8' noenhanced front
set label 'embree_medium' at 105.106922,8.06799339 left font ',8' noenhanced front
set label 'embree_high' at 104.322943,7.93066507 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-conference.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-conference.png'.outsuffix
set title 'conference.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [20.1211311:380.759959]
set xtics (50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 26.7109998,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.828878,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 98.7040894,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.2090429,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 126.605662,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 143.57701,42.7481303 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 211.828861,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 77.7923099,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 31.9082658,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 105.106922,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 73.4764424,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-conference.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-conference.png'.outsuffix
set multiplot layout 1,2
set title 'conference.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [20.1211311:380.759959]
set xtics (50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 26.7109998,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.828878,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 97.9432753,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.7777239,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 126.605662,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 143.57701,35.3866648 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 211.828861,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 77.1926844,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 31.9082658,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 105.106922,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 73.4764424,43.2759982 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'conference.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [20.1211311:380.759959]
set xtics (50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 26.7109998,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.828878,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 98.7040894,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.2090429,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 126.605662,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 143.57701,42.7481303 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 211.828861,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 77.7923099,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 31.9082658,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 105.106922,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 73.4764424,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-conference.svg'.outsuffix
set multiplot layout 1,2
set title 'conference.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [20.1211311:380.759959]
set xtics (50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 26.7109998,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.828878,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 97.9432753,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.7777239,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 126.605662,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 143.57701,35.3866648 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 211.828861,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 77.1926844,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 31.9082658,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 105.106922,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 73.4764424,43.2759982 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'conference.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [20.1211311:380.759959]
set xtics (50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 26.7109998,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 175.828878,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 98.7040894,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.2090429,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 126.605662,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 143.57701,42.7481303 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 211.828861,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 77.7923099,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 31.9082658,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 105.106922,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 73.4764424,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
