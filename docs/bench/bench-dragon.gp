# regenerate: gnuplot bench-dragon.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-dragon.png'
set title 'dragon.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.1656215:552.818928]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 35.1058425,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 141.200422,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 114.473473,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 84.6080982,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 93.5821151,59.1745487 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 175.994019,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 232.15361,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 81.9068379,62.0452734 left font ',8' noenhanced front
set label 'embree_low' at 66.0676855,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 300.479947,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 207.467905,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dragon.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'rays-dragon.png'
set title 'dragon.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.1656215:552.818928]
set xtics (50, 100, 200, 500)
set yrange [5.04639514:6.74714621]
unset label
set label 'LBVH' at 35.1058425,6.11838024 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 167.801066,6.43839948 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 79.5735208,6.33507385 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 124.983739,6.35422476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 93.5821151,6.4311689 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.412559,6.5462701 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 232.15361,6.27902882 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 128.605273,6.27296823 left font ',8' noenhanced front
set label 'embree_low' at 66.0676855,5.20709603 left font ',8' noenhanced front
set label 'embree_medium' at 300.479947,5.62539899 left font ',8' noenhanced front
set label 'embree_high' at 300.86638,5.75218538 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'rays-dragon.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'cost-dragon.png'
set title 'dragon.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.1656215:552.818928]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 35.1058425,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 167.801066,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 79.5735208,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 124.983739,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 94.3364021,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.412559,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 232.15361,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 82.5670203,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 66.0676855,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 300.479947,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 207.467905,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'cost-dragon.svg'
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output outdir.'trade-dragon.png'
set multiplot layout 1,2
set title 'dragon.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.1656215:552.818928]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 35.1058425,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 141.200422,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 114.473473,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 84.6080982,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 93.5821151,59.1745487 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 175.994019,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 232.15361,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 81.9068379,62.0452734 left font ',8' noenhanced front
set label 'embree_low' at 66.0676855,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 300.479947,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 207.467905,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dragon.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.1656215:552.818928]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 35.1058425,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 167.801066,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 79.5735208,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 124.983739,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 94.3364021,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.412559,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 232.15361,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 82.5670203,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 66.0676855,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 300.479947,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 207.467905,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output outdir.'trade-dragon.svg'
set multiplot layout 1,2
set title 'dragon.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.1656215:552.818928]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 35.1058425,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 141.200422,59.6986683 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 114.473473,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 84.6080982,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 93.5821151,59.1745487 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 175.994019,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 232.15361,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 81.9068379,62.0452734 left font ',8' noenhanced front
set label 'embree_low' at 66.0676855,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 300.479947,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 207.467905,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'dragon.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.1656215:552.818928]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 35.1058425,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 167.801066,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 79.5735208,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 124.983739,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 94.3364021,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.412559,52.2859771 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 232.15361,51.3500074 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 82.5670203,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 66.0676855,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 300.479947,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 207.467905,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
