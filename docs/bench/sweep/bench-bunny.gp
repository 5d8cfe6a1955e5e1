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
set xrange [1.71936215:106.326169]
set xtics (2, 5, 10, 20, 50, 100)
set yrange [35.7194127:47.9051528]
unset label
set label 'LBVH' at 2.55832061,43.368649 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 4.00627173,38.740404 left font ',8' noenhanced front
set label 'ATRBVH(9,3)' at 4.37136542,38.3142046 left font ',8' noenhanced front
set label 'ATRBVH(9,4)' at 7.25921742,37.9892616 left font ',8' noenhanced front
set label 'ATRBVH(9,6)' at 4.55325652,39.235127 left font ',8' noenhanced front
set label 'ATRBVH(12,2)' at 7.69832875,39.2877392 left font ',8' noenhanced front
set label 'ATRBVH(12,3)' at 6.82365892,38.9921462 left font ',8' noenhanced front
set label 'ATRBVH(12,4)' at 4.98779687,37.9549379 left font ',8' noenhanced front
set label 'ATRBVH(12,6)' at 46.7105189,38.5783483 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 10.0797475,37.8986916 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 10.8524406,38.4434634 left font ',8' noenhanced front
set label 'ATRBVH(16,4)' at 10.4885964,38.1225319 left font ',8' noenhanced front
set label 'ATRBVH(16,6)' at 30.0036108,38.1197302 left font ',8' noenhanced front
set label 'ATRBVH(20,2)' at 9.78944903,39.3060151 left font ',8' noenhanced front
set label 'ATRBVH(20,3)' at 6.14278579,38.307629 left font ',8' noenhanced front
set label 'ATRBVH(20,4)' at 10.5832378,38.6123035 left font ',8' noenhanced front
set label 'ATRBVH(20,6)' at 10.592269,38.9240318 left font ',8' noenhanced front
set label 'ATRBVH(24,2)' at 11.3429123,39.6612472 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 6.95368935,39.6108116 left font ',8' noenhanced front
set label 'ATRBVH(24,4)' at 12.1386563,39.4486948 left font ',8' noenhanced front
set label 'ATRBVH(24,6)' at 12.5975391,38.2012481 left font ',8' noenhanced front
set label 'ATRBVH(32,2)' at 16.9194615,39.2755244 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 16.6189618,38.5425887 left font ',8' noenhanced front
set label 'ATRBVH(32,4)' at 18.640671,38.8461473 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 18.80652,38.1101018 left font ',8' noenhanced front
set label 'embree_low' at 5.08124385,46.4658922 left font ',8' noenhanced front
set label 'embree_medium' at 22.6507318,36.8708212 left font ',8' noenhanced front
set label 'embree_high' at 13.556729,36.8708212 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 6.58847523,37.8049156 left font ',8' noenhanced front
plot 'bench-bunny.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-bunny.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-bunny.svg'
replot
unset output
reset
