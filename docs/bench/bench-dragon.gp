# regenerate: gnuplot bench-dragon.gp (in this folder)
if (!exists('outsuffix')) outsuffix = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-dragon.png'.outsuffix
set title 'dragon.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.7371264:666.403723]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 36.448372,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 174.490214,61.8104975 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 108.618805,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 87.1682529,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 128.351574,59.6438441 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.970613,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 240.312128,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 84.1336923,59.4641489 left font ',8' noenhanced front
set label 'embree_low' at 75.9572851,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 350.92575,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 219.081321,57.38674 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-dragon.png'.outsuffix
set title 'dragon.ply: ray throughput of each tree through our traverser against its build time (upper left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'Mrays/s, primary + AO + diffuse, all threads'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.7371264:666.403723]
set xtics (50, 100, 200, 500)
set yrange [4.42280876:6.41607859]
unset label
set label 'LBVH' at 36.448372,5.77322838 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 174.490214,6.16051624 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 109.541919,6.18065302 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 130.407842,6.01733491 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 158.324895,6.10559279 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.970613,5.84267585 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 240.312128,5.08895911 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 135.370207,5.70533813 left font ',8' noenhanced front
set label 'embree_low' at 75.9572851,4.61114922 left font ',8' noenhanced front
set label 'embree_medium' at 350.92575,6.13508421 left font ',8' noenhanced front
set label 'embree_high' at 321.438192,6.04269773 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'cost-dragon.png'.outsuffix
set title 'dragon.ply: exact ray cost (boxes and triangles tested per ray) against build time (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'ray cost: ci x boxes + ct x triangles tested per ray (exact)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [26.7371264:666.403723]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 36.448372,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 174.490214,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 74.0308772,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 131.516133,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 104.936969,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.470848,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 238.287009,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 84.8487154,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 75.9572851,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 350.92575,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 219.081321,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'cost-dragon.svg'.outsuffix
replot
unset output
reset
set terminal pngcairo size 1800,600 font 'sans,10'
set output 'trade-dragon.png'.outsuffix
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
set xrange [26.7371264:666.403723]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 36.448372,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 174.490214,61.8104975 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 108.618805,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 87.1682529,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 128.351574,59.6438441 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.970613,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 240.312128,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 84.1336923,59.4641489 left font ',8' noenhanced front
set label 'embree_low' at 75.9572851,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 350.92575,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 219.081321,57.38674 left font ',8' noenhanced front
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
set xrange [26.7371264:666.403723]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 36.448372,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 174.490214,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 74.0308772,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 131.516133,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 104.936969,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.470848,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 238.287009,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 84.8487154,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 75.9572851,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 350.92575,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 219.081321,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
set terminal svg size 1800,600 dynamic font 'sans,10'
set output 'trade-dragon.svg'.outsuffix
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
set xrange [26.7371264:666.403723]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 36.448372,70.0126652 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 174.490214,61.8104975 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 108.618805,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 87.1682529,60.135476 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 128.351574,59.6438441 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 177.970613,59.3866347 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 240.312128,60.5233863 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 84.1336923,59.4641489 left font ',8' noenhanced front
set label 'embree_low' at 75.9572851,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 350.92575,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 219.081321,57.38674 left font ',8' noenhanced front
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
set xrange [26.7371264:666.403723]
set xtics (50, 100, 200, 500)
set yrange [46.0340343:63.6489318]
unset label
set label 'LBVH' at 36.448372,56.5806094 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 174.490214,50.3496993 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 74.0308772,51.3385083 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 131.516133,52.2072513 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 104.936969,50.6183954 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 176.470848,50.9341362 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 238.287009,51.800621 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 84.8487154,51.9117243 left font ',8' noenhanced front
set label 'embree_low' at 75.9572851,61.5684321 left font ',8' noenhanced front
set label 'embree_medium' at 350.92575,47.6984341 left font ',8' noenhanced front
set label 'embree_high' at 219.081321,47.6984341 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 0 using 2:5 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:5 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser'
unset multiplot
unset output
reset
