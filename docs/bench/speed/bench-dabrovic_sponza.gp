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
set xrange [1.93988351:19.6704087]
set xtics (2, 5, 10)
set yrange [63.7338549:116.665389]
unset label
set label 'LBVH' at 2.42497088,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(7,1)' at 5.26923081,77.3438024 left font ',8' noenhanced front
set label 'ATRBVH(9,1)' at 4.08573796,73.4949364 left font ',8' noenhanced front
set label 'ATRBVH(6,2)' at 6.37350833,74.0727154 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 5.31145773,71.690965 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 7.92003041,71.1263572 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 12.3932099,70.0410864 left font ',8' noenhanced front
set label 'ATRBVH(auto,4)' at 9.3671859,67.3811972 left font ',8' noenhanced front
set label 'embree_low' at 4.31853325,110.413633 left font ',8' noenhanced front
set label 'embree_medium' at 9.64967801,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 6.97691642,77.7503047 left font ',8' noenhanced front
set label 'LBVH/cl' at 3.01808305,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)/cl' at 5.18560317,68.98284 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dabrovic_sponza.svg'
replot
unset output
reset
