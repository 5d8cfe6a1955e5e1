# regenerate: gnuplot bench-sibenik.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-sibenik.png'.outsuffix
set title 'sibenik.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.98594076:59.3832164]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 6.75412527,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.6506277,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.2727618,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.9449745,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9666998,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 27.1241656,53.4242201 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3072579,50.4129143 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7846255,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.17084111,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 22.3181758,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 18.9517334,55.8292646 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-sibenik.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-sibenik.png'.outsuffix
set title 'sibenik.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.98594076:59.3832164]
set xtics (5, 10, 20, 50)
set yrange [4.18772864:6.33988763]
unset label
set label 'LBVH' at 6.75412527,4.89446874 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.6506277,5.86501571 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.3745815,5.90216647 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.9449745,5.98254369 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.2786209,6.12487377 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 27.1241656,5.92613083 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.5520007,6.01779877 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7846255,6.08569562 left font ',8' noenhanced front
set label 'embree_low' at 5.17084111,4.39108225 left font ',8' noenhanced front
set label 'embree_medium' at 22.3181758,5.51738118 left font ',8' noenhanced front
set label 'embree_high' at 22.3417623,5.70755516 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-sibenik.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-sibenik.png'.outsuffix
set title 'sibenik.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.98594076:59.3832164]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 6.75412527,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.6506277,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.3745815,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 13.4108561,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.2786209,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.9320365,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.5520007,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7846255,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.17084111,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 22.3181758,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 16.0760907,69.9513728 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-sibenik.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-sibenik.png'.outsuffix
set multiplot layout 1,2
set title 'sibenik.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.98594076:59.3832164]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 6.75412527,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.6506277,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.2727618,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.9449745,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9666998,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 27.1241656,53.4242201 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3072579,50.4129143 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7846255,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.17084111,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 22.3181758,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 18.9517334,55.8292646 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'sibenik.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.98594076:59.3832164]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 6.75412527,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.6506277,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.3745815,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 13.4108561,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.2786209,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.9320365,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.5520007,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7846255,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.17084111,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 22.3181758,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 16.0760907,69.9513728 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-sibenik.svg'.outsuffix
set multiplot layout 1,2
set title 'sibenik.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.98594076:59.3832164]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 6.75412527,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.6506277,52.3325777 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.2727618,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 18.9449745,52.9555818 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 17.9666998,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 27.1241656,53.4242201 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.3072579,50.4129143 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7846255,51.3573403 left font ',8' noenhanced front
set label 'embree_low' at 5.17084111,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 22.3181758,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 18.9517334,55.8292646 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'sibenik.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.98594076:59.3832164]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 6.75412527,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 34.6506277,67.7362841 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 14.3745815,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 13.4108561,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 21.2786209,66.0015618 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 26.9320365,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 34.5520007,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.7846255,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.17084111,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 22.3181758,69.9513728 left font ',8' noenhanced front
set label 'embree_high' at 16.0760907,69.9513728 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
