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
set xrange [10.3255488:79.8150001]
set xtics (20, 50)
set yrange [30.464722:80.0754387]
unset label
set label 'LBVH' at 12.5744123,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 25.0456086,42.2585195 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 25.0584737,38.3879299 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 29.3010131,40.2171123 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 24.3050626,36.836494 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 47.6597649,35.3352164 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 53.0836158,37.3793614 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 30.2242245,35.1523488 left font ',8' noenhanced front
set label 'embree_low' at 23.7082455,74.2159052 left font ',8' noenhanced front
set label 'embree_medium' at 50.6204121,43.2759982 left font ',8' noenhanced front
set label 'embree_high' at 39.6018359,43.2759982 left font ',8' noenhanced front
set label 'LBVH/cl' at 15.5642561,64.4719989 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 35.0039242,36.836494 left font ',8' noenhanced front
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-conference.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-conference.svg'
replot
unset output
reset
