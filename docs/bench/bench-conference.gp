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
set xrange [25.032601:497.466167]
set xtics (50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 41.3080749,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 169.445098,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 101.207386,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 131.210884,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 86.3743255,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.082525,35.3866648 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 274.067718,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 103.704872,36.4214601 left font ',8' noenhanced front
set label 'embree_low' at 33.3881217,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 101.459581,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 68.696007,43.2759982 left font ',8' noenhanced front
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
set xrange [25.032601:497.466167]
set xtics (50, 100, 200)
set yrange [3.23211451:6.38426747]
unset label
set label 'LBVH' at 41.3080749,3.80117431 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 169.445098,5.35718308 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 102.006695,5.14701281 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 89.5219533,5.6075238 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 85.6975097,5.49261339 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.082525,5.57961438 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 274.067718,5.33068514 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 160.098829,6.01196594 left font ',8' noenhanced front
set label 'embree_low' at 33.3881217,3.52995574 left font ',8' noenhanced front
set label 'embree_medium' at 100.664559,5.02923116 left font ',8' noenhanced front
set label 'embree_high' at 98.8812459,5.29874342 left font ',8' noenhanced front
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
set xrange [25.032601:497.466167]
set xtics (50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 41.3080749,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 169.445098,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 102.006695,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 88.8204731,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 85.6975097,42.9033782 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.082525,42.7481303 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 274.067718,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 158.844319,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 33.3881217,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 101.459581,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 68.696007,53.862866 left font ',8' noenhanced front
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
set xrange [25.032601:497.466167]
set xtics (50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 41.3080749,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 169.445098,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 101.207386,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 131.210884,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 86.3743255,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.082525,35.3866648 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 274.067718,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 103.704872,36.4214601 left font ',8' noenhanced front
set label 'embree_low' at 33.3881217,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 101.459581,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 68.696007,43.2759982 left font ',8' noenhanced front
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
set xrange [25.032601:497.466167]
set xtics (50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 41.3080749,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 169.445098,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 102.006695,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 88.8204731,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 85.6975097,42.9033782 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.082525,42.7481303 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 274.067718,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 158.844319,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 33.3881217,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 101.459581,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 68.696007,53.862866 left font ',8' noenhanced front
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
set xrange [25.032601:497.466167]
set xtics (50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 41.3080749,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 169.445098,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 101.207386,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 131.210884,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 86.3743255,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.082525,35.3866648 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 274.067718,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 103.704872,36.4214601 left font ',8' noenhanced front
set label 'embree_low' at 33.3881217,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 101.459581,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 68.696007,43.2759982 left font ',8' noenhanced front
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
set xrange [25.032601:497.466167]
set xtics (50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 41.3080749,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 169.445098,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 102.006695,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 88.8204731,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 85.6975097,42.9033782 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.082525,42.7481303 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 274.067718,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 158.844319,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 33.3881217,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 101.459581,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 68.696007,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
