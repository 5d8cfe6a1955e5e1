# regenerate: gnuplot bench-dabrovic_sponza.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.09698516:61.0377691]
set xtics (10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 7.80782025,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.914936,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 19.8773234,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7519545,70.3663757 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.8182133,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 29.7114967,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 37.201553,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.3362698,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 6.47448512,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 20.12124,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 14.5225078,77.7503047 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.09698516:61.0377691]
set xtics (10, 20, 50)
set yrange [2.60374318:3.97543412]
unset label
set label 'LBVH' at 7.80782025,2.82275409 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.1372548,3.65646621 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.7847828,3.58950657 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7519545,3.55303157 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 16.6101908,3.65843727 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 25.2669154,3.6990235 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 37.201553,3.75149737 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 21.9965649,3.77301297 left font ',8' noenhanced front
set label 'embree_low' at 6.47448512,2.73335178 left font ',8' noenhanced front
set label 'embree_medium' at 20.12124,3.81342338 left font ',8' noenhanced front
set label 'embree_high' at 14.5225078,3.76962587 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-dabrovic_sponza.png'.outsuffix
set title 'dabrovic_sponza.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.09698516:61.0377691]
set xtics (10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 7.80782025,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.914936,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.0076231,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7519545,74.5369382 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 16.502017,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 21.4872048,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 37.201553,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.1407566,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 5.62596454,105.921569 left font ',8' noenhanced front
set label 'embree_medium' at 19.9902004,64.9849474 left font ',8' noenhanced front
set label 'embree_high' at 14.5225078,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-dabrovic_sponza.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-dabrovic_sponza.png'.outsuffix
set multiplot layout 1,2
set title 'dabrovic_sponza.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.09698516:61.0377691]
set xtics (10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 7.80782025,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.914936,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 19.8773234,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7519545,70.3663757 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.8182133,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 29.7114967,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 37.201553,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.3362698,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 6.47448512,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 20.12124,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 14.5225078,77.7503047 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dabrovic_sponza.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.09698516:61.0377691]
set xtics (10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 7.80782025,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.914936,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.0076231,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7519545,74.5369382 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 16.502017,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 21.4872048,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 37.201553,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.1407566,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 5.62596454,105.921569 left font ',8' noenhanced front
set label 'embree_medium' at 19.9902004,64.9849474 left font ',8' noenhanced front
set label 'embree_high' at 14.5225078,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-dabrovic_sponza.svg'.outsuffix
set multiplot layout 1,2
set title 'dabrovic_sponza.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.09698516:61.0377691]
set xtics (10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 7.80782025,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.914936,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 19.8773234,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7519545,70.3663757 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 22.8182133,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 29.7114967,66.2620175 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 37.201553,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 15.3362698,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 6.47448512,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 20.12124,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 14.5225078,77.7503047 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dabrovic_sponza.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [5.09698516:61.0377691]
set xtics (10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 7.80782025,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 33.914936,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 20.0076231,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 23.7519545,74.5369382 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 16.502017,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 21.4872048,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 37.201553,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 22.1407566,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 5.62596454,105.921569 left font ',8' noenhanced front
set label 'embree_medium' at 19.9902004,64.9849474 left font ',8' noenhanced front
set label 'embree_high' at 14.5225078,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
