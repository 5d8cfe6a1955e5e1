set terminal pngcairo size 900,600 font 'sans,10'
set output 'scaling.png'
set title 'Build time against triangle count (log-log)'
set xlabel 'triangles'
set ylabel 'build time, ms'
set logscale xy
set grid
set key top left
set format x '10^{%L}'
plot 'scaling.dat' index 0 using 1:2 with linespoints lw 2 title 'builtin:sphere LBVH: N^{0.98}', \
  'scaling.dat' index 1 using 1:2 with linespoints lw 2 title 'builtin:sphere ATRBVH(9,2): N^{1.06}', \
  'scaling.dat' index 2 using 1:2 with linespoints lw 2 title 'bunny.ply LBVH: N^{1.00}', \
  'scaling.dat' index 3 using 1:2 with linespoints lw 2 title 'bunny.ply ATRBVH(9,2): N^{0.93}'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'scaling.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'scaling-stages.png'
set title 'Build time per stage, bunny.ply ATRBVH(9,2): N^{0.93} (log-log)'
set xlabel 'triangles'
set ylabel 'ms'
set logscale xy
set grid
set key top left
set format x '10^{%L}'
plot 'scaling.dat' index 3 using 1:3 with linespoints title 'bounds', \
  'scaling.dat' index 3 using 1:4 with linespoints title 'morton', \
  'scaling.dat' index 3 using 1:5 with linespoints title 'sort', \
  'scaling.dat' index 3 using 1:6 with linespoints title 'hierarchy', \
  'scaling.dat' index 3 using 1:7 with linespoints title 'refit', \
  'scaling.dat' index 3 using 1:8 with linespoints title 'optimise', \
  'scaling.dat' index 3 using 1:9 with linespoints title 'collapse', \
  'scaling.dat' index 3 using 1:10 with linespoints title 'layout'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'scaling-stages.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'scaling-memory.png'
set title 'Peak library memory during the build, bytes per triangle'
set xlabel 'triangles'
set ylabel 'bytes per triangle'
set logscale x
set grid
set key top right
set yrange [0:*]
set format x '10^{%L}'
plot 'scaling.dat' index 0 using 1:11 with linespoints lw 2 title 'builtin:sphere LBVH: N^{0.98}', \
  'scaling.dat' index 1 using 1:11 with linespoints lw 2 title 'builtin:sphere ATRBVH(9,2): N^{1.06}', \
  'scaling.dat' index 2 using 1:11 with linespoints lw 2 title 'bunny.ply LBVH: N^{1.00}', \
  'scaling.dat' index 3 using 1:11 with linespoints lw 2 title 'bunny.ply ATRBVH(9,2): N^{0.93}'
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'scaling-memory.svg'
replot
unset output
