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
set xrange [13.0871428:228.609808]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 17.2398932,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 84.3978138,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 46.902187,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.710828,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 45.4016911,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 80.5651708,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 110.697674,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 37.006781,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 28.876114,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 129.228567,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 88.903282,43.2759982 left font ',8' noenhanced front
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
set xrange [13.0871428:228.609808]
set xtics (20, 50, 100, 200)
set yrange [7.29799659:13.8982121]
unset label
set label 'LBVH' at 17.2398932,8.30035391 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 84.3978138,10.9153886 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 47.2565675,11.1434943 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.710828,11.8279512 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 65.4559709,12.8454997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 79.9610067,13.2875018 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 110.697674,12.9483438 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 56.4941592,12.0953704 left font ',8' noenhanced front
set label 'embree_low' at 28.876114,7.921639 left font ',8' noenhanced front
set label 'embree_medium' at 129.228567,12.0202651 left font ',8' noenhanced front
set label 'embree_high' at 125.972617,11.4242267 left font ',8' noenhanced front
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
set xrange [13.0871428:228.609808]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 17.2398932,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 84.3978138,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 47.2565675,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.710828,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 64.9651118,44.4315542 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 80.5651708,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 110.697674,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 37.006781,42.0099467 left font ',8' noenhanced front
set label 'embree_low' at 28.876114,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 129.228567,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 88.903282,53.862866 left font ',8' noenhanced front
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
set xrange [13.0871428:228.609808]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 17.2398932,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 84.3978138,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 46.902187,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.710828,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 45.4016911,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 80.5651708,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 110.697674,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 37.006781,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 28.876114,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 129.228567,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 88.903282,43.2759982 left font ',8' noenhanced front
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
set xrange [13.0871428:228.609808]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 17.2398932,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 84.3978138,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 47.2565675,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.710828,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 64.9651118,44.4315542 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 80.5651708,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 110.697674,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 37.006781,42.0099467 left font ',8' noenhanced front
set label 'embree_low' at 28.876114,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 129.228567,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 88.903282,53.862866 left font ',8' noenhanced front
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
set xrange [13.0871428:228.609808]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 17.2398932,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 84.3978138,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 46.902187,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.710828,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 45.4016911,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 80.5651708,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 110.697674,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 37.006781,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 28.876114,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 129.228567,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 88.903282,43.2759982 left font ',8' noenhanced front
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
set xrange [13.0871428:228.609808]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 17.2398932,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 84.3978138,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 47.2565675,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.710828,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 64.9651118,44.4315542 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 80.5651708,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 110.697674,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 37.006781,42.0099467 left font ',8' noenhanced front
set label 'embree_low' at 28.876114,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 129.228567,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 88.903282,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
