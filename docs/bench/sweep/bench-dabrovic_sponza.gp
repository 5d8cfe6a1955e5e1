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
set xrange [1.89428568:35.4229074]
set xtics (2, 5, 10, 20)
set yrange [63.4220826:116.707083]
unset label
set label 'LBVH' at 2.51180577,103.086451 left font ',8' noenhanced front
set label 'ATRBVH(9,2)' at 6.6832377,73.0540696 left font ',8' noenhanced front
set label 'ATRBVH(9,3)' at 5.23665277,68.873401 left font ',8' noenhanced front
set label 'ATRBVH(9,4)' at 7.62695132,67.0789358 left font ',8' noenhanced front
set label 'ATRBVH(9,6)' at 5.43058849,67.016087 left font ',8' noenhanced front
set label 'ATRBVH(12,2)' at 5.20421141,70.7347215 left font ',8' noenhanced front
set label 'ATRBVH(12,3)' at 8.50244379,72.4930597 left font ',8' noenhanced front
set label 'ATRBVH(12,4)' at 8.84255251,66.4539628 left font ',8' noenhanced front
set label 'ATRBVH(12,6)' at 8.96134148,71.7046329 left font ',8' noenhanced front
set label 'ATRBVH(16,2)' at 6.16585176,71.7294804 left font ',8' noenhanced front
set label 'ATRBVH(16,3)' at 11.4588292,72.498504 left font ',8' noenhanced front
set label 'ATRBVH(16,4)' at 6.95601083,68.2987995 left font ',8' noenhanced front
set label 'ATRBVH(16,6)' at 11.3792528,66.9206092 left font ',8' noenhanced front
set label 'ATRBVH(20,2)' at 10.1468835,70.8992903 left font ',8' noenhanced front
set label 'ATRBVH(20,3)' at 11.4221376,66.1098992 left font ',8' noenhanced front
set label 'ATRBVH(20,4)' at 12.6490296,71.3214572 left font ',8' noenhanced front
set label 'ATRBVH(20,6)' at 12.2512482,69.8399618 left font ',8' noenhanced front
set label 'ATRBVH(24,2)' at 9.91612739,68.1022205 left font ',8' noenhanced front
set label 'ATRBVH(24,3)' at 13.9514552,67.6070343 left font ',8' noenhanced front
set label 'ATRBVH(24,4)' at 14.0844691,65.7740298 left font ',8' noenhanced front
set label 'ATRBVH(24,6)' at 14.395537,71.1830951 left font ',8' noenhanced front
set label 'ATRBVH(32,2)' at 15.9640006,72.6589037 left font ',8' noenhanced front
set label 'ATRBVH(32,3)' at 18.0440747,66.6957217 left font ',8' noenhanced front
set label 'ATRBVH(32,4)' at 18.8282959,70.4662788 left font ',8' noenhanced front
set label 'ATRBVH(32,6)' at 19.7536398,69.0782932 left font ',8' noenhanced front
set label 'embree_low' at 4.32396486,110.413579 left font ',8' noenhanced front
set label 'embree_medium' at 11.3404381,77.7503047 left font ',8' noenhanced front
set label 'embree_high' at 17.4143078,77.7503047 left font ',8' noenhanced front
set label 'TRBVH(7,3)' at 8.11938387,70.0410864 left font ',8' noenhanced front
plot 'bench-dabrovic_sponza.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front (no other point is both faster and lower)', \
  'bench-dabrovic_sponza.dat' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)'
set terminal svg size 900,600 dynamic font 'sans,10'
set output outdir.'pareto-dabrovic_sponza.svg'
replot
unset output
reset
