# regenerate: gnuplot bench-conference.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-conference.png'
set title 'conference.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [9.48179209:194.472879]
set xtics (10, 20, 50, 100)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 12.6852049,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.9488551,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 39.7048634,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 47.3993423,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 37.0410981,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 73.7175534,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 94.5623731,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 28.8684542,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.976754,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 67.6072107,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 106.467988,43.2759982 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-conference.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'rays-conference.png'
set title 'conference.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [9.48179209:194.472879]
set xtics (10, 20, 50, 100)
set yrange [7.13156126:14.2637526]
unset label
set label 'LBVH' at 12.6852049,8.97016181 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.9488551,11.9287345 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 40.0217666,11.5642553 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 47.0240214,12.2169321 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 36.7477966,13.248814 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 73.1338378,13.0635443 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 94.5623731,13.4213678 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 45.1291115,12.9077018 left font ',8' noenhanced front
set label 'embree_low' at 24.976754,7.80546911 left font ',8' noenhanced front
set label 'embree_medium' at 102.136345,11.0448273 left font ',8' noenhanced front
set label 'embree_high' at 106.467988,11.2750438 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'rays-conference.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'cost-conference.png'
set title 'conference.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [9.48179209:194.472879]
set xtics (10, 20, 50, 100)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 12.6852049,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.9488551,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 40.0217666,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 47.3993423,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 36.7477966,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 73.7175534,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 94.5623731,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 28.8684542,42.0099467 left font ',8' noenhanced front
set label 'embree_low' at 24.976754,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 67.6072107,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 106.467988,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'cost-conference.svg'
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output outdir.'trade-conference.png'
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
set xrange [9.48179209:194.472879]
set xtics (10, 20, 50, 100)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 12.6852049,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.9488551,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 39.7048634,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 47.3993423,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 37.0410981,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 73.7175534,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 94.5623731,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 28.8684542,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.976754,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 67.6072107,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 106.467988,43.2759982 left font ',8' noenhanced front
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
set xrange [9.48179209:194.472879]
set xtics (10, 20, 50, 100)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 12.6852049,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.9488551,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 40.0217666,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 47.3993423,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 36.7477966,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 73.7175534,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 94.5623731,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 28.8684542,42.0099467 left font ',8' noenhanced front
set label 'embree_low' at 24.976754,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 67.6072107,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 106.467988,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output outdir.'trade-conference.svg'
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
set xrange [9.48179209:194.472879]
set xtics (10, 20, 50, 100)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 12.6852049,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.9488551,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 39.7048634,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 47.3993423,33.0578968 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 37.0410981,34.0661051 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 73.7175534,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 94.5623731,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 28.8684542,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.976754,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 67.6072107,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 106.467988,43.2759982 left font ',8' noenhanced front
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
set xrange [9.48179209:194.472879]
set xtics (10, 20, 50, 100)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 12.6852049,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 61.9488551,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 40.0217666,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 47.3993423,40.4559897 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 36.7477966,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 73.7175534,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 94.5623731,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 28.8684542,42.0099467 left font ',8' noenhanced front
set label 'embree_low' at 24.976754,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 67.6072107,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 106.467988,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
