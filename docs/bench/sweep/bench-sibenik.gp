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
set xrange [1.87428656:127.158313]
set xtics (2, 5, 10, 20, 50, 100)
set yrange [47.9814666:83.2675029]
unset label
set label 'LBVH' at 2.81384584,67.05137 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 7.76349648,53.8820627 left font ',8' noenhanced front
set label 'ATRBVH(9,3)' at 5.16332616,51.5512025 left font ',8' noenhanced front
set label 'ATRBVH(9,4)' at 5.32190164,50.5171087 left font ',8' noenhanced front
set label 'ATRBVH(9,6)' at 9.10324287,50.4843578 left font ',8' noenhanced front
set label 'ATRBVH(12,2)' at 5.09334968,54.3028885 left font ',8' noenhanced front
set label 'ATRBVH(12,3)' at 10.084475,52.9306517 left font ',8' noenhanced front
set label 'ATRBVH(12,4)' at 11.5516518,53.7032844 left font ',8' noenhanced front
set label 'ATRBVH(12,6)' at 10.2752879,50.085967 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 5.95908598,50.2475836 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 6.51229021,53.4601684 left font ',8' noenhanced front
set label 'ATRBVH(16,4)' at 11.8015788,49.7559729 left font ',8' noenhanced front
set label 'ATRBVH(16,6)' at 6.96280172,49.7493609 left font ',8' noenhanced front
set label 'ATRBVH(20,2)' at 11.9466408,50.9677484 left font ',8' noenhanced front
set label 'ATRBVH(20,3)' at 13.624899,52.4126271 left font ',8' noenhanced front
set label 'ATRBVH(20,4)' at 13.9550984,49.5887124 left font ',8' noenhanced front
set label 'ATRBVH(20,6)' at 14.0943373,53.1753268 left font ',8' noenhanced front
set label 'ATRBVH(24,2)' at 14.0498365,53.8039854 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 15.7585124,50.716222 left font ',8' noenhanced front
set label 'ATRBVH(24,4)' at 25.7004791,52.7178515 left font ',8' noenhanced front
set label 'ATRBVH(24,6)' at 17.4483362,49.7575656 left font ',8' noenhanced front
set label 'ATRBVH(32,2)' at 54.839717,51.6742242 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 21.2799223,53.2477992 left font ',8' noenhanced front
set label 'ATRBVH(32,4)' at 22.2284236,51.3315281 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 22.7127281,49.5102482 left font ',8' noenhanced front
set label 'embree_low' at 4.93219101,79.0998609 left font ',8' noenhanced front
set label 'embree_medium' at 12.2025456,55.5830829 left font ',8' noenhanced front
set label 'embree_high' at 21.7450087,55.5830829 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 7.99731303,54.1379097 left font ',8' noenhanced front
plot 'bench-sibenik.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-sibenik.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-sibenik.svg'
replot
unset output
reset
