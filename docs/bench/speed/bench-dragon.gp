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
set xrange [30.6794297:263.106164]
set xtics (50, 100, 200)
set yrange [55.0033068:80.2279756]
unset label
set label 'LBVH' at 37.7370871,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 77.5601448,63.4134707 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 65.7794743,61.8432221 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 93.6085474,62.4957033 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 90.48896,60.6361735 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 108.282838,59.8198288 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 163.465801,60.5199352 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 123.84792,61.3999933 left font ',8' noenhanced front
set label 'embree_low' at 64.3917254,77.248684 left font ',8' noenhanced front
set label 'embree_medium' at 171.099163,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 131.915914,57.38674 left font ',8' noenhanced front
set label 'LBVH/cl' at 43.8148205,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 74.1284216,60.1668773 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dragon.svg'
replot
unset output
reset
