# regenerate: gnuplot bench-bunny.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-bunny.png'
set title 'bunny.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [1.87283768:44.048939]
set xtics (2, 5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.53884835,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7778579,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.76323492,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.31065222,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 6.07865074,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 12.7674329,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 17.1229816,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.842529,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 4.69540987,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.8153918,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 23.4658493,36.8708212 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-bunny.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'rays-bunny.png'
set title 'bunny.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [1.87283768:44.048939]
set xtics (2, 5, 10, 20)
set yrange [10.0033452:14.8889786]
unset label
set label 'LBVH' at 2.53884835,11.51327 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7778579,13.0975328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.82801716,13.1574699 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.31065222,12.6258061 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 9.02812388,12.454919 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 12.8739739,12.7796936 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 17.1229816,13.0341511 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.842529,12.9686182 left font ',8' noenhanced front
set label 'embree_low' at 4.69540987,10.4649798 left font ',8' noenhanced front
set label 'embree_medium' at 22.9948919,13.5218903 left font ',8' noenhanced front
set label 'embree_high' at 23.4658493,14.3119353 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'rays-bunny.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'cost-bunny.png'
set title 'bunny.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [1.87283768:44.048939]
set xtics (2, 5, 10, 20)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 2.53884835,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7778579,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.32786489,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.23360016,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 9.10346129,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 12.8739739,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 17.1229816,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.89128343,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.69540987,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.8153918,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 23.4658493,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'cost-bunny.svg'
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output outdir.'trade-bunny.png'
set multiplot layout 1,2
set title 'bunny.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [1.87283768:44.048939]
set xtics (2, 5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.53884835,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7778579,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.76323492,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.31065222,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 6.07865074,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 12.7674329,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 17.1229816,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.842529,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 4.69540987,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.8153918,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 23.4658493,36.8708212 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'bunny.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [1.87283768:44.048939]
set xtics (2, 5, 10, 20)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 2.53884835,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7778579,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.32786489,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.23360016,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 9.10346129,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 12.8739739,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 17.1229816,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.89128343,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.69540987,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.8153918,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 23.4658493,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output outdir.'trade-bunny.svg'
set multiplot layout 1,2
set title 'bunny.ply: SAH cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [1.87283768:44.048939]
set xtics (2, 5, 10, 20)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.53884835,43.368649 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7778579,38.4283721 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.76323492,39.0521322 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.31065222,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 6.07865074,38.1317351 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 12.7674329,39.2990834 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 17.1229816,38.7335583 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.842529,38.5681918 left font ',8' noenhanced front
set label 'embree_low' at 4.69540987,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 14.8153918,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 23.4658493,36.8708212 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set title 'bunny.ply: exact ray cost against build time' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [1.87283768:44.048939]
set xtics (2, 5, 10, 20)
set yrange [35.1801633:45.2835894]
unset label
set label 'LBVH' at 2.53884835,41.3520993 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.7778579,37.8644328 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.32786489,38.0152873 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 9.23360016,38.3842886 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 9.10346129,37.5280925 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 12.8739739,39.67856 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 17.1229816,38.8250365 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 5.89128343,37.7046337 left font ',8' noenhanced front
set label 'embree_low' at 4.69540987,44.0902713 left font ',8' noenhanced front
set label 'embree_medium' at 14.8153918,36.1348177 left font ',8' noenhanced front
set label 'embree_high' at 23.4658493,36.1348177 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
