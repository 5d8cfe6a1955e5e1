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
set xrange [2.1732336:53.1156916]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.95699266,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.6023122,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.7797908,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.5404983,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3108577,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5194925,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.0799951,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.02453995,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.40934544,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 16.6379924,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.0985126,77.7503047 left font ',8' noenhanced front
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
set xrange [2.1732336:53.1156916]
set xtics (5, 10, 20, 50)
set yrange [6.30971332:9.960889]
unset label
set label 'LBVH' at 2.95699266,6.84620354 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.8016732,8.97863947 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.04747224,8.96111172 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.5404983,8.76494071 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.4059867,8.75135165 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.8872797,9.1541185 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.0799951,9.11169928 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.4783872,9.52964778 left font ',8' noenhanced front
set label 'embree_low' at 4.40934544,6.6547063 left font ',8' noenhanced front
set label 'embree_medium' at 10.7525988,9.23305946 left font ',8' noenhanced front
set label 'embree_high' at 11.0985126,8.86681778 left font ',8' noenhanced front
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
set xrange [2.1732336:53.1156916]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 2.95699266,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.6023122,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.8792908,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.5404983,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3108577,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5194925,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.0799951,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.3571173,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.40934544,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 16.6379924,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 11.1922581,64.9849474 left font ',8' noenhanced front
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
set xrange [2.1732336:53.1156916]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.95699266,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.6023122,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.7797908,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.5404983,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3108577,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5194925,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.0799951,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.02453995,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.40934544,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 16.6379924,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.0985126,77.7503047 left font ',8' noenhanced front
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
set xrange [2.1732336:53.1156916]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 2.95699266,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.6023122,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.8792908,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.5404983,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3108577,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5194925,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.0799951,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.3571173,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.40934544,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 16.6379924,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 11.1922581,64.9849474 left font ',8' noenhanced front
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
set xrange [2.1732336:53.1156916]
set xtics (5, 10, 20, 50)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 2.95699266,103.086451 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.6023122,71.3951472 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.7797908,73.0450257 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.5404983,71.7204365 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3108577,67.0641732 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5194925,68.970139 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.0799951,69.0782932 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.02453995,68.7352597 left font ',8' noenhanced front
set label 'embree_low' at 4.40934544,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 16.6379924,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 11.0985126,77.7503047 left font ',8' noenhanced front
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
set xrange [2.1732336:53.1156916]
set xtics (5, 10, 20, 50)
set yrange [61.6488455:110.063549]
unset label
set label 'LBVH' at 2.95699266,104.26217 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 23.6023122,72.0854584 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 11.8792908,72.3902199 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 16.5404983,75.7754539 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.3108577,74.0498997 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 14.5194925,70.9812889 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 28.0799951,70.3405519 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 14.3571173,68.9086397 left font ',8' noenhanced front
set label 'embree_low' at 4.40934544,104.345277 left font ',8' noenhanced front
set label 'embree_medium' at 16.6379924,66.2234631 left font ',8' noenhanced front
set label 'embree_high' at 11.1922581,64.9849474 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
