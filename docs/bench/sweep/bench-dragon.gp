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
set xrange [28.6032168:523.925752]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 37.8520903,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 112.16649,62.1027229 left font ',8' noenhanced front
set label 'ATRBVH(9,3)' at 79.8719569,61.2004297 left font ',8' noenhanced front
set label 'ATRBVH(9,4)' at 85.7024943,59.8470727 left font ',8' noenhanced front
set label 'ATRBVH(9,6)' at 82.5304295,62.4240217 left font ',8' noenhanced front
set label 'ATRBVH(12,2)' at 78.5578245,60.4778783 left font ',8' noenhanced front
set label 'ATRBVH(12,3)' at 129.054303,59.5781328 left font ',8' noenhanced front
set label 'ATRBVH(12,4)' at 126.175997,61.4699721 left font ',8' noenhanced front
set label 'ATRBVH(12,6)' at 88.9004973,59.5274865 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 133.987562,62.0713194 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 137.670979,59.1745487 left font ',8' noenhanced front
set label 'ATRBVH(16,4)' at 96.5137895,59.0800428 left font ',8' noenhanced front
set label 'ATRBVH(16,6)' at 143.736968,59.6961581 left font ',8' noenhanced front
set label 'ATRBVH(20,2)' at 156.04643,62.2802411 left font ',8' noenhanced front
set label 'ATRBVH(20,3)' at 152.009591,61.4482957 left font ',8' noenhanced front
set label 'ATRBVH(20,4)' at 158.486223,60.0655343 left font ',8' noenhanced front
set label 'ATRBVH(20,6)' at 161.983968,59.1464961 left font ',8' noenhanced front
set label 'ATRBVH(24,2)' at 109.355651,60.2507729 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 174.693479,61.3224781 left font ',8' noenhanced front
set label 'ATRBVH(24,4)' at 180.86428,61.9233826 left font ',8' noenhanced front
set label 'ATRBVH(24,6)' at 182.769441,59.3347057 left font ',8' noenhanced front
set label 'ATRBVH(32,2)' at 204.642964,60.2326374 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 221.687586,61.2507533 left font ',8' noenhanced front
set label 'ATRBVH(32,4)' at 232.946133,59.2468832 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 233.591341,60.5233863 left font ',8' noenhanced front
set label 'embree_low' at 63.7592512,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 193.067933,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 293.375796,57.38674 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 164.63491,60.5199352 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dragon.svg'
replot
unset output
reset
