# SAH and build time against the split budget (docs/splitting.md's
# measurements; gnuplot split.gp from this folder).
set terminal pngcairo size 1200,420 font ",10" noenhanced
set offsets 0, 0, 0.5, 0.5
set output 'split.png'
set multiplot layout 1,3
embree(s) = s eq "conference" ? 40.2 : s eq "dabrovic_sponza" ? 66.1 : 51.0
do for [s in "conference dabrovic_sponza sibenik"] {
  set title s." (dashed: Embree HIGH + splits)"
  set xlabel "split budget (extra references / triangles)"
  set ylabel "SAH (collapsed, max leaf 8)"
  set key top left
  plot "< grep '^".s." ATRBVH(9,2)' split.dat" using 3:5 with linespoints title "ATRBVH(9,2)", \
       "< grep '^".s." ATRBVH(16,3)' split.dat" using 3:5 with linespoints title "ATRBVH(16,3)", \
       embree(s) with lines dashtype 2 title "Embree HIGH + splits"
}
unset multiplot
