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
set xrange [18.97901:381.729144]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 25.3432852,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.917565,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 94.9050192,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 74.1310969,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 117.469999,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 108.978842,36.6557761 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 209.801126,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 74.6206321,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 31.7509082,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 103.524899,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 70.5046334,43.2759982 left font ',8' noenhanced front
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
set xrange [18.97901:381.729144]
set xtics (20, 50, 100, 200)
set yrange [5.4914882:9.49639177]
unset label
set label 'LBVH' at 25.3432852,6.74763204 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.917565,8.48317349 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 94.9050192,8.60780154 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 74.1310969,8.92789431 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 116.545833,9.02606108 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 159.974457,8.84688636 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 209.801126,9.02337166 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 75.2123466,9.05658456 left font ',8' noenhanced front
set label 'embree_low' at 31.7509082,5.86990429 left font ',8' noenhanced front
set label 'embree_medium' at 103.524899,7.92409807 left font ',8' noenhanced front
set label 'embree_high' at 101.633439,8.14939426 left font ',8' noenhanced front
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
set xrange [18.97901:381.729144]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 25.3432852,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.917565,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 95.6575815,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.5478889,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 117.469999,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 159.974457,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 209.801126,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 75.2123466,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 31.7509082,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 103.524899,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 70.5046334,53.862866 left font ',8' noenhanced front
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
set xrange [18.97901:381.729144]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 25.3432852,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.917565,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 94.9050192,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 74.1310969,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 117.469999,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 108.978842,36.6557761 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 209.801126,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 74.6206321,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 31.7509082,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 103.524899,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 70.5046334,43.2759982 left font ',8' noenhanced front
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
set xrange [18.97901:381.729144]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 25.3432852,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.917565,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 95.6575815,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.5478889,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 117.469999,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 159.974457,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 209.801126,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 75.2123466,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 31.7509082,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 103.524899,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 70.5046334,53.862866 left font ',8' noenhanced front
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
set xrange [18.97901:381.729144]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 25.3432852,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.917565,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 94.9050192,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 74.1310969,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 117.469999,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 108.978842,36.6557761 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 209.801126,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 74.6206321,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 31.7509082,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 103.524899,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 70.5046334,43.2759982 left font ',8' noenhanced front
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
set xrange [18.97901:381.729144]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 25.3432852,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.917565,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 95.6575815,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 73.5478889,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 117.469999,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 159.974457,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 209.801126,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 75.2123466,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 31.7509082,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 103.524899,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 70.5046334,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
