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
set xrange [2.75753821:59.1000753]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 3.70483321,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0627245,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.04929311,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.56152397,51.1502497 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7712583,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.5567236,51.6188881 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 32.0729888,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.86004334,49.5520082 left font ',8' noenhanced front
set label 'embree_low' at 5.70790995,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.8442159,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 24.8201348,54.6804169 left font ',8' noenhanced front
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
set xrange [2.75753821:59.1000753]
set xtics (5, 10, 20, 50)
set yrange [5.27470537:8.62756334]
unset label
set label 'LBVH' at 3.70483321,5.59151085 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0627245,6.51013155 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.12257541,6.97106137 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 11.1904031,7.17578768 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.5992347,7.02761851 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.5567236,6.68404521 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 32.0729888,6.96530605 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 12.3675214,8.23155649 left font ',8' noenhanced front
set label 'embree_low' at 5.70790995,5.95438158 left font ',8' noenhanced front
set label 'embree_medium' at 24.2755579,7.39343536 left font ',8' noenhanced front
set label 'embree_high' at 24.6207529,7.13015537 left font ',8' noenhanced front
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
set xrange [2.75753821:59.1000753]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 3.70483321,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0627245,66.8186756 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.12257541,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.50078171,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7712583,65.7513049 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 13.2147727,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 32.0729888,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.86004334,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.70790995,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 19.6119142,69.2840211 left font ',8' noenhanced front
set label 'embree_high' at 24.8201348,68.1161557 left font ',8' noenhanced front
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
set xrange [2.75753821:59.1000753]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 3.70483321,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0627245,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.04929311,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.56152397,51.1502497 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7712583,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.5567236,51.6188881 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 32.0729888,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.86004334,49.5520082 left font ',8' noenhanced front
set label 'embree_low' at 5.70790995,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.8442159,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 24.8201348,54.6804169 left font ',8' noenhanced front
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
set xrange [2.75753821:59.1000753]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 3.70483321,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0627245,66.8186756 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.12257541,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.50078171,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7712583,65.7513049 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 13.2147727,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 32.0729888,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.86004334,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.70790995,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 19.6119142,69.2840211 left font ',8' noenhanced front
set label 'embree_high' at 24.8201348,68.1161557 left font ',8' noenhanced front
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
set xrange [2.75753821:59.1000753]
set xtics (5, 10, 20, 50)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 3.70483321,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0627245,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.04929311,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.56152397,51.1502497 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7712583,50.5059887 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 19.5567236,51.6188881 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 32.0729888,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.86004334,49.5520082 left font ',8' noenhanced front
set label 'embree_low' at 5.70790995,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 15.8442159,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 24.8201348,54.6804169 left font ',8' noenhanced front
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
set xrange [2.75753821:59.1000753]
set xtics (5, 10, 20, 50)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 3.70483321,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 17.0627245,66.8186756 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 9.12257541,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.50078171,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.7712583,65.7513049 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 13.2147727,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 32.0729888,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.86004334,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 5.70790995,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 19.6119142,69.2840211 left font ',8' noenhanced front
set label 'embree_high' at 24.8201348,68.1161557 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
