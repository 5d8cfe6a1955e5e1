# regenerate: gnuplot bench-conference.gp (in this folder)
set terminal pngcairo size 900,600 font 'sans,10'
set output 'pareto-conference.png'
set title "conference.ply: build time against SAH (lower left is better)" noenhanced
set xlabel 'build time, ms (median; log scale)'
set ylabel 'SAH cost (collapsed, max leaf as run)'
set logscale x
set grid
set key top right
plot 'bench-conference.dat' index 2 using 2:3 with steps lw 1 lc rgb '#999999' title 'Pareto front', \
  '' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh', \
  '' index 0 using 2:3:5 with labels offset 0.6,0.6 left font ',8' noenhanced notitle, \
  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree (rtcBuildBVH)', \
  '' index 1 using 2:3:5 with labels offset 0.6,-0.6 left font ',8' noenhanced notitle
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'pareto-conference.svg'
replot
unset output
reset
set terminal pngcairo size 900,600 font 'sans,10'
set output 'rays-conference.png'
set title "conference.ply: ray throughput (our traverser, primary+AO+diffuse) against build time" noenhanced
set xlabel 'build time, ms (median; log scale)'
set ylabel 'Mrays/s, all threads'
set logscale x
set grid
set key bottom right
plot 'bench-conference.dat' index 0 using 2:4 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'atrbvh', \
  '' index 0 using 2:4:5 with labels offset 0.6,0.6 left font ',8' noenhanced notitle, \
  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Embree tree, our traverser', \
  '' index 1 using 2:4:5 with labels offset 0.6,-0.6 left font ',8' noenhanced notitle
set terminal svg size 900,600 dynamic font 'sans,10'
set output 'rays-conference.svg'
replot
unset output
