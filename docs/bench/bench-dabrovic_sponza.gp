# regenerate: gnuplot bench-dabrovic_sponza.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-dabrovic_sponza.png'
set title 'dabrovic_sponza.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.0155103:40.1988963]
set xtics (5, 10, 20)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.68919595,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.9510918,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.03536369,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.69017604,73.0744972 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 8.9753854,68.0489447 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5567016,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.1306953,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.64254901,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.47442157,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 17.6550812,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 12.2063472,77.7503047 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dabrovic_sponza.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'rays-dabrovic_sponza.png'
set title 'dabrovic_sponza.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.0155103:40.1988963]
set xtics (5, 10, 20)
set yrange [6.40666644:9.43919545]
unset label
set label 'LBVH' at 2.68919595,6.69984519 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.045593,8.88095516 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.09099462,8.8171328 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.69017604,8.42283634 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 10.91149,7.89155518 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5567016,7.98788524 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.1306953,8.03858615 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.78442266,9.01826657 left font ',8' noenhanced front
set label 'embree_low' at 4.47442157,6.69320461 left font ',8' noenhanced front
set label 'embree_medium' at 17.6550812,9.06932001 left font ',8' noenhanced front
set label 'embree_high' at 12.3028668,9.15859905 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'rays-dabrovic_sponza.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'cost-dabrovic_sponza.png'
set title 'dabrovic_sponza.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.0155103:40.1988963]
set xtics (5, 10, 20)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 2.68919595,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 8.58503879,70.8469428 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.09099462,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.61415377,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 10.91149,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5567016,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.1306953,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.78442266,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 4.47442157,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 17.6550812,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 12.2063472,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'cost-dabrovic_sponza.svg'
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output outdir.'trade-dabrovic_sponza.png'
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
set xrange [2.0155103:40.1988963]
set xtics (5, 10, 20)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.68919595,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.9510918,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.03536369,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.69017604,73.0744972 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 8.9753854,68.0489447 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5567016,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.1306953,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.64254901,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.47442157,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 17.6550812,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 12.2063472,77.7503047 left font ',8' noenhanced front
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
set xrange [2.0155103:40.1988963]
set xtics (5, 10, 20)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 2.68919595,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 8.58503879,70.8469428 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.09099462,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.61415377,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 10.91149,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5567016,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.1306953,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.78442266,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 4.47442157,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 17.6550812,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 12.2063472,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output outdir.'trade-dabrovic_sponza.svg'
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
set xrange [2.0155103:40.1988963]
set xtics (5, 10, 20)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.68919595,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.9510918,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.03536369,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.69017604,73.0744972 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 8.9753854,68.0489447 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5567016,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.1306953,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.64254901,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.47442157,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 17.6550812,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 12.2063472,77.7503047 left font ',8' noenhanced front
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
set xrange [2.0155103:40.1988963]
set xtics (5, 10, 20)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 2.68919595,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 8.58503879,70.8469428 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.09099462,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.61415377,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 10.91149,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5567016,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.1306953,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 8.78442266,67.6701241 left font ',8' noenhanced front
set label 'embree_low' at 4.47442157,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 17.6550812,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 12.2063472,66.2234631 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
