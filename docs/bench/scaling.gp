# regenerate: gnuplot scaling.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'scaling.png'
set xlabel 'triangles'
set grid
set logscale x
set format x '10^%L'
set title 'Build time against triangle count (log-log; each line a base scene and configuration)'
set ylabel 'build time, ms (median)'
set logscale y
set key top left
plot 'scaling.dat' index 0 using 1:2 with linespoints lw 2 title 'builtin:sphere LBVH: ~N^0.99 from 1e5' noenhanced, \
  'scaling.dat' index 1 using 1:2 with linespoints lw 2 title 'builtin:sphere ATRBVH(9,2): ~N^0.96 from 1e5' noenhanced, \
  'scaling.dat' index 2 using 1:2 with linespoints lw 2 title 'bunny.ply LBVH: ~N^0.94 from 1e5' noenhanced, \
  'scaling.dat' index 3 using 1:2 with linespoints lw 2 title 'bunny.ply ATRBVH(9,2): ~N^0.99 from 1e5' noenhanced
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'scaling.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'scaling-stages-builtin_sphere-LBVH.png'
set xlabel 'triangles'
set grid
set logscale x
set format x '10^%L'
set title 'Build time of each stage against triangle count (log-log): builtin:sphere, LBVH' noenhanced
set ylabel 'stage time, ms (median)'
set logscale y
set key top left
plot 'scaling.dat' index 0 using 1:($3 > 0 ? $3 : NaN) with linespoints title 'bounds' noenhanced, \
  'scaling.dat' index 0 using 1:($4 > 0 ? $4 : NaN) with linespoints title 'morton' noenhanced, \
  'scaling.dat' index 0 using 1:($5 > 0 ? $5 : NaN) with linespoints title 'sort' noenhanced, \
  'scaling.dat' index 0 using 1:($6 > 0 ? $6 : NaN) with linespoints title 'hierarchy' noenhanced, \
  'scaling.dat' index 0 using 1:($7 > 0 ? $7 : NaN) with linespoints title 'refit' noenhanced, \
  'scaling.dat' index 0 using 1:($8 > 0 ? $8 : NaN) with linespoints title 'optimise' noenhanced, \
  'scaling.dat' index 0 using 1:($9 > 0 ? $9 : NaN) with linespoints title 'collapse' noenhanced, \
  'scaling.dat' index 0 using 1:($10 > 0 ? $10 : NaN) with linespoints title 'layout' noenhanced
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'scaling-stages-builtin_sphere-LBVH.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'scaling-stages-builtin_sphere-ATRBVH_9_2_.png'
set xlabel 'triangles'
set grid
set logscale x
set format x '10^%L'
set title 'Build time of each stage against triangle count (log-log): builtin:sphere, ATRBVH(9,2)' noenhanced
set ylabel 'stage time, ms (median)'
set logscale y
set key top left
plot 'scaling.dat' index 1 using 1:($3 > 0 ? $3 : NaN) with linespoints title 'bounds' noenhanced, \
  'scaling.dat' index 1 using 1:($4 > 0 ? $4 : NaN) with linespoints title 'morton' noenhanced, \
  'scaling.dat' index 1 using 1:($5 > 0 ? $5 : NaN) with linespoints title 'sort' noenhanced, \
  'scaling.dat' index 1 using 1:($6 > 0 ? $6 : NaN) with linespoints title 'hierarchy' noenhanced, \
  'scaling.dat' index 1 using 1:($7 > 0 ? $7 : NaN) with linespoints title 'refit' noenhanced, \
  'scaling.dat' index 1 using 1:($8 > 0 ? $8 : NaN) with linespoints title 'optimise' noenhanced, \
  'scaling.dat' index 1 using 1:($9 > 0 ? $9 : NaN) with linespoints title 'collapse' noenhanced, \
  'scaling.dat' index 1 using 1:($10 > 0 ? $10 : NaN) with linespoints title 'layout' noenhanced
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'scaling-stages-builtin_sphere-ATRBVH_9_2_.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'scaling-stages-bunny-LBVH.png'
set xlabel 'triangles'
set grid
set logscale x
set format x '10^%L'
set title 'Build time of each stage against triangle count (log-log): ../shared/scenes/bunny.ply, LBVH' noenhanced
set ylabel 'stage time, ms (median)'
set logscale y
set key top left
plot 'scaling.dat' index 2 using 1:($3 > 0 ? $3 : NaN) with linespoints title 'bounds' noenhanced, \
  'scaling.dat' index 2 using 1:($4 > 0 ? $4 : NaN) with linespoints title 'morton' noenhanced, \
  'scaling.dat' index 2 using 1:($5 > 0 ? $5 : NaN) with linespoints title 'sort' noenhanced, \
  'scaling.dat' index 2 using 1:($6 > 0 ? $6 : NaN) with linespoints title 'hierarchy' noenhanced, \
  'scaling.dat' index 2 using 1:($7 > 0 ? $7 : NaN) with linespoints title 'refit' noenhanced, \
  'scaling.dat' index 2 using 1:($8 > 0 ? $8 : NaN) with linespoints title 'optimise' noenhanced, \
  'scaling.dat' index 2 using 1:($9 > 0 ? $9 : NaN) with linespoints title 'collapse' noenhanced, \
  'scaling.dat' index 2 using 1:($10 > 0 ? $10 : NaN) with linespoints title 'layout' noenhanced
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'scaling-stages-bunny-LBVH.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'scaling-stages-bunny-ATRBVH_9_2_.png'
set xlabel 'triangles'
set grid
set logscale x
set format x '10^%L'
set title 'Build time of each stage against triangle count (log-log): ../shared/scenes/bunny.ply, ATRBVH(9,2)' noenhanced
set ylabel 'stage time, ms (median)'
set logscale y
set key top left
plot 'scaling.dat' index 3 using 1:($3 > 0 ? $3 : NaN) with linespoints title 'bounds' noenhanced, \
  'scaling.dat' index 3 using 1:($4 > 0 ? $4 : NaN) with linespoints title 'morton' noenhanced, \
  'scaling.dat' index 3 using 1:($5 > 0 ? $5 : NaN) with linespoints title 'sort' noenhanced, \
  'scaling.dat' index 3 using 1:($6 > 0 ? $6 : NaN) with linespoints title 'hierarchy' noenhanced, \
  'scaling.dat' index 3 using 1:($7 > 0 ? $7 : NaN) with linespoints title 'refit' noenhanced, \
  'scaling.dat' index 3 using 1:($8 > 0 ? $8 : NaN) with linespoints title 'optimise' noenhanced, \
  'scaling.dat' index 3 using 1:($9 > 0 ? $9 : NaN) with linespoints title 'collapse' noenhanced, \
  'scaling.dat' index 3 using 1:($10 > 0 ? $10 : NaN) with linespoints title 'layout' noenhanced
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'scaling-stages-bunny-ATRBVH_9_2_.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'scaling-memory.png'
set xlabel 'triangles'
set grid
set logscale x
set format x '10^%L'
set title 'Peak library memory during the build, bytes per triangle (each line a base scene and configuration)'
set ylabel 'bytes per triangle'
set yrange [0:*]
set key top right
plot 'scaling.dat' index 0 using 1:11 with linespoints lw 2 title 'builtin:sphere LBVH: ~N^0.99 from 1e5' noenhanced, \
  'scaling.dat' index 1 using 1:11 with linespoints lw 2 title 'builtin:sphere ATRBVH(9,2): ~N^0.96 from 1e5' noenhanced, \
  'scaling.dat' index 2 using 1:11 with linespoints lw 2 title 'bunny.ply LBVH: ~N^0.94 from 1e5' noenhanced, \
  'scaling.dat' index 3 using 1:11 with linespoints lw 2 title 'bunny.ply ATRBVH(9,2): ~N^0.99 from 1e5' noenhanced
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'scaling-memory.svg'
replot
unset output
reset
