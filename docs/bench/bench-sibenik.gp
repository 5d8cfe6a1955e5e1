# regenerate: gnuplot bench-sibenik.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-sibenik.png'
set title 'sibenik.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.10987345:44.6460211]
set xtics (5, 10, 20)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 2.83119473,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 14.5344755,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.68890327,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.39488408,51.1502497 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.8197509,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.5619916,49.813556 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 24.2906426,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.56053459,49.5520082 left font ',8' noenhanced front
set label 'embree_low' at 6.00949616,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 21.9119676,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 14.3950187,54.6804169 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-sibenik.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'rays-sibenik.png'
set title 'sibenik.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.10987345:44.6460211]
set xtics (5, 10, 20)
set yrange [5.89808349:8.90546537]
unset label
set label 'LBVH' at 2.83119473,7.2691414 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 14.6516856,8.18700938 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.75897305,8.30876146 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.33572671,8.45161258 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.8197509,8.49263721 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.4214997,8.28003158 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 24.2906426,8.55026279 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.56053459,8.58475039 left font ',8' noenhanced front
set label 'embree_low' at 6.00949616,6.18224556 left font ',8' noenhanced front
set label 'embree_medium' at 21.9119676,7.87002618 left font ',8' noenhanced front
set label 'embree_high' at 20.8793587,8.38090379 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'rays-sibenik.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'cost-sibenik.png'
set title 'sibenik.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [2.10987345:44.6460211]
set xtics (5, 10, 20)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 2.83119473,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 14.5344755,66.8186756 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.75897305,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.33572671,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.8197509,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 11.886279,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 24.2906426,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.56053459,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 6.00949616,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 21.9119676,68.1161557 left font ',8' noenhanced front
set label 'embree_high' at 17.3366305,69.2840211 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'cost-sibenik.svg'
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output outdir.'trade-sibenik.png'
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
set xrange [2.10987345:44.6460211]
set xtics (5, 10, 20)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 2.83119473,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 14.5344755,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.68890327,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.39488408,51.1502497 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.8197509,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.5619916,49.813556 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 24.2906426,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.56053459,49.5520082 left font ',8' noenhanced front
set label 'embree_low' at 6.00949616,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 21.9119676,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 14.3950187,54.6804169 left font ',8' noenhanced front
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
set xrange [2.10987345:44.6460211]
set xtics (5, 10, 20)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 2.83119473,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 14.5344755,66.8186756 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.75897305,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.33572671,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.8197509,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 11.886279,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 24.2906426,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.56053459,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 6.00949616,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 21.9119676,68.1161557 left font ',8' noenhanced front
set label 'embree_high' at 17.3366305,69.2840211 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output outdir.'trade-sibenik.svg'
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
set xrange [2.10987345:44.6460211]
set xtics (5, 10, 20)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 2.83119473,67.05137 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 14.5344755,53.2352437 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.68890327,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.39488408,51.1502497 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.8197509,49.8495043 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 17.5619916,49.813556 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 24.2906426,51.3155803 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.56053459,49.5520082 left font ',8' noenhanced front
set label 'embree_low' at 6.00949616,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 21.9119676,54.6804169 left font ',8' noenhanced front
set label 'embree_high' at 14.3950187,54.6804169 left font ',8' noenhanced front
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
set xrange [2.10987345:44.6460211]
set xtics (5, 10, 20)
set yrange [62.1382942:98.008445]
unset label
set label 'LBVH' at 2.83119473,82.6306345 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 14.5344755,66.8186756 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 8.75897305,68.81062 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 7.33572671,67.5192839 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 12.8197509,65.0839533 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 11.886279,68.8978606 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 24.2906426,65.5275998 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 7.56053459,66.3071656 left font ',8' noenhanced front
set label 'embree_low' at 6.00949616,93.771813 left font ',8' noenhanced front
set label 'embree_medium' at 21.9119676,68.1161557 left font ',8' noenhanced front
set label 'embree_high' at 17.3366305,69.2840211 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
