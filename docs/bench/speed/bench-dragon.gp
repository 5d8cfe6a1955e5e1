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
set xrange [26.0125596:529.903304]
set xtics (50, 100, 200, 500)
set yrange [55.0033108:80.2279369]
unset label
set label 'LBVH' at 28.9325496,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 80.1541568,63.4134696 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 59.4084989,61.8432232 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 100.993184,62.4957022 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 73.2057463,60.8121607 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 94.1461298,59.8198299 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 161.936278,60.5199352 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 125.595711,61.3999923 left font ',8' noenhanced front
set label 'embree_low' at 62.5224564,77.2486504 left font ',8' noenhanced front
set label 'embree_medium' at 290.499873,57.38674 left font ',8' noenhanced front
set label 'embree_high' at 200.263913,57.38674 left font ',8' noenhanced front
set label 'LBVH/cl' at 37.8812676,70.0126652 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 67.3551715,60.1668795 left font ',8' noenhanced front
plot 'bench-dragon.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dragon.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dragon.svg'
replot
unset output
reset
