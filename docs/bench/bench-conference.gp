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
set xrange [12.1915094:393.836101]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 17.0401418,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 148.107251,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.2294705,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.080105,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 102.143288,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.731177,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.938662,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.2247099,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.553879,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 98.8956165,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 64.6919559,43.2759982 left font ',8' noenhanced front
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
set xrange [12.1915094:393.836101]
set xtics (20, 50, 100, 200)
set yrange [6.19981329:11.8310337]
unset label
set label 'LBVH' at 17.0401418,7.87182348 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 146.758947,10.5941038 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.2294705,10.5677532 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 90.5844294,10.8433407 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 102.143288,11.1260411 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.731177,11.2145411 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.938662,10.8555616 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.2247099,11.1659289 left font ',8' noenhanced front
set label 'embree_low' at 24.553879,6.73189711 left font ',8' noenhanced front
set label 'embree_medium' at 98.8956165,10.0560063 left font ',8' noenhanced front
set label 'embree_high' at 97.8970777,9.88941492 left font ',8' noenhanced front
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
set xrange [12.1915094:393.836101]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 17.0401418,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 148.107251,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.9389927,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 57.5513693,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 102.143288,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.731177,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.938662,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.7688189,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.553879,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 98.8956165,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 64.6919559,53.862866 left font ',8' noenhanced front
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
set xrange [12.1915094:393.836101]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 17.0401418,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 148.107251,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.2294705,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.080105,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 102.143288,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.731177,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.938662,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.2247099,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.553879,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 98.8956165,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 64.6919559,43.2759982 left font ',8' noenhanced front
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
set xrange [12.1915094:393.836101]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 17.0401418,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 148.107251,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.9389927,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 57.5513693,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 102.143288,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.731177,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.938662,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.7688189,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.553879,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 98.8956165,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 64.6919559,53.862866 left font ',8' noenhanced front
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
set xrange [12.1915094:393.836101]
set xtics (20, 50, 100, 200)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 17.0401418,64.4719989 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 148.107251,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.2294705,38.1056054 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 58.080105,34.3270082 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 102.143288,32.7969937 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.731177,32.8484421 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.938662,35.3227309 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.2247099,32.614126 left font ',8' noenhanced front
set label 'embree_low' at 24.553879,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 98.8956165,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 64.6919559,43.2759982 left font ',8' noenhanced front
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
set xrange [12.1915094:393.836101]
set xtics (20, 50, 100, 200)
set yrange [36.3654314:96.1032186]
unset label
set label 'LBVH' at 17.0401418,81.0882218 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 148.107251,45.8398031 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 77.9389927,45.9114409 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 57.5513693,43.5123416 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 102.143288,39.8470263 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 146.731177,39.6917784 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 196.938662,42.4925613 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 59.7688189,40.4817708 left font ',8' noenhanced front
set label 'embree_low' at 24.553879,89.0475745 left font ',8' noenhanced front
set label 'embree_medium' at 98.8956165,53.862866 left font ',8' noenhanced front
set label 'embree_high' at 64.6919559,53.862866 left font ',8' noenhanced front
plot 'bench-conference.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
