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
set xrange [16.6121777:376.959201]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 22.4420886,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 150.818041,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 82.1821125,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 65.1306912,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 105.723343,35.3352164 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 129.257696,33.7714322 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 202.255219,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 64.9957239,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.9203796,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 100.720579,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 68.9655999,43.2759982 left font ',8' noenhanced front
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
set xrange [16.6121777:376.959201]
set xtics (20, 50, 100, 200)
set yrange [3.48195691:6.49030691]
unset label
set label 'LBVH' at 22.4420886,4.11956661 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 150.818041,5.8159602 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 82.8600849,5.86674825 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 64.5977831,6.01632012 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 105.723343,6.10542084 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 157.172496,5.97654264 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 202.255219,6.13498998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 65.5319149,6.14952043 left font ',8' noenhanced front
set label 'embree_low' at 24.9203796,3.76621045 left font ',8' noenhanced front
set label 'embree_medium' at 100.720579,5.28744382 left font ',8' noenhanced front
set label 'embree_high' at 100.061321,5.14145202 left font ',8' noenhanced front
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
set xrange [16.6121777:376.959201]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 22.4420886,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 150.818041,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 82.8600849,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 64.5977831,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 105.723343,42.9033782 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 129.257696,40.8031791 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 202.255219,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 65.5319149,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.9203796,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 100.720579,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 68.9655999,53.862866 left font ',8' noenhanced front
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
set xrange [16.6121777:376.959201]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 22.4420886,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 150.818041,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 82.1821125,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 65.1306912,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 105.723343,35.3352164 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 129.257696,33.7714322 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 202.255219,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 64.9957239,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.9203796,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 100.720579,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 68.9655999,43.2759982 left font ',8' noenhanced front
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
set xrange [16.6121777:376.959201]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 22.4420886,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 150.818041,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 82.8600849,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 64.5977831,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 105.723343,42.9033782 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 129.257696,40.8031791 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 202.255219,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 65.5319149,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.9203796,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 100.720579,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 68.9655999,53.862866 left font ',8' noenhanced front
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
set xrange [16.6121777:376.959201]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 22.4420886,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 150.818041,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 82.1821125,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 65.1306912,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 105.723343,35.3352164 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 129.257696,33.7714322 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 202.255219,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 64.9957239,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.9203796,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 100.720579,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 68.9655999,43.2759982 left font ',8' noenhanced front
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
set xrange [16.6121777:376.959201]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 22.4420886,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 150.818041,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 82.8600849,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 64.5977831,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 105.723343,42.9033782 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 129.257696,40.8031791 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 202.255219,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 65.5319149,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.9203796,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 100.720579,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 68.9655999,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
