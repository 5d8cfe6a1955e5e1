# regenerate: gnuplot bench-dabrovic_sponza.gp (in this folder)
if (!exists('outdir')) outdir = ''
set terminal pngcairo size 900,600 font 'sans,10'
set output outdir.'pareto-dabrovic_sponza.png'
set title 'dabrovic_sponza.ply: build time against SAH cost, each configuration once (lower left is better)' noenhanced
set xlabel 'build time, ms (median of the timed runs; log scale)'
set ylabel 'SAH cost of the tree (collapsed, leaf limit as run)'
set grid
set key below horizontal
set lmargin 10
set rmargin 4
set tmargin 3
set logscale x
set xrange [3.99664766:27.7708708]
set xtics (5, 10, 20)
set yrange [63.7338614:116.665327]
unset label
set label 'LBVH' at 5.07820487,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 9.41072843,77.3438007 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 8.2263126,73.4949382 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 11.3049558,74.0727154 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 12.1148584,71.690965 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 15.2060023,69.7722947 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 11.0881009,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 11.0038877,67.3811989 left font ',8' noenhanced front
set label 'embree_low' at 5.46822019,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 14.1658234,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 18.8666346,77.7503047 left font ',8' noenhanced front
set label 'LBVH/cl' at 4.06891138,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 8.39416497,71.690965 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dabrovic_sponza.svg'
replot
unset output
reset
