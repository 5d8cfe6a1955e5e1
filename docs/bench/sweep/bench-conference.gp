# regenerate: gnuplot bench-conference.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-conference.png'
set title 'conference.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [9.30413814:219.445667]
set xtics (10, 20, 50, 100, 200)
set yrange [30.4437167:80.0782519]
unset label
set label 'LBVH' at 12.6162385,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 35.9032543,38.1062147 left font ',8' noenhanced front
set label 'ATRBVH(9,3)' at 27.3631756,34.9885722 left font ',8' noenhanced front
set label 'ATRBVH(9,4)' at 39.8654283,33.5993865 left font ',8' noenhanced front
set label 'ATRBVH(9,6)' at 28.215271,33.5572073 left font ',8' noenhanced front
set label 'ATRBVH(12,2)' at 27.0170944,38.7585187 left font ',8' noenhanced front
set label 'ATRBVH(12,3)' at 56.2069729,33.2795161 left font ',8' noenhanced front
set label 'ATRBVH(12,4)' at 56.8471646,38.1883092 left font ',8' noenhanced front
set label 'ATRBVH(12,6)' at 58.7181678,36.8776845 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 37.1161082,34.3263988 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 40.2566698,36.6049371 left font ',8' noenhanced front
set label 'ATRBVH(16,4)' at 65.5051346,32.7036142 left font ',8' noenhanced front
set label 'ATRBVH(16,6)' at 44.6234381,32.6997183 left font ',8' noenhanced front
set label 'ATRBVH(20,2)' at 41.8300577,37.9877274 left font ',8' noenhanced front
set label 'ATRBVH(20,3)' at 69.1544026,33.951956 left font ',8' noenhanced front
set label 'ATRBVH(20,4)' at 71.4293893,37.6940486 left font ',8' noenhanced front
set label 'ATRBVH(20,6)' at 78.0518564,36.4033147 left font ',8' noenhanced front
set label 'ATRBVH(24,2)' at 74.4935356,38.2520031 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 79.8715751,32.8472235 left font ',8' noenhanced front
set label 'ATRBVH(24,4)' at 82.7731651,34.0729251 left font ',8' noenhanced front
set label 'ATRBVH(24,6)' at 116.838353,35.3404258 left font ',8' noenhanced front
set label 'ATRBVH(32,2)' at 53.2704752,34.3059777 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 89.6950335,37.8889958 left font ',8' noenhanced front
set label 'ATRBVH(32,4)' at 93.7174911,32.7845987 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 93.2444455,36.5924516 left font ',8' noenhanced front
set label 'embree_low' at 24.3130906,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 102.32065,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 67.0452826,43.2759982 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 58.7339803,39.9188028 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-conference.svg'
replot
unset output
reset
