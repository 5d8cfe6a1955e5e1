# SAH against the split budget for the three rules (docs/splitting.md's
# measurements; gnuplot split.gp from this folder).  Budget 0 is the
# unsplit tree, the first point of every line.
set terminal pngcairo size 1200,420 font ",10" noenhanced
set offsets 0, 0, 0.5, 0.5
set output 'split.png'
set multiplot layout 1,3
embree(s) = s eq "conference" ? 40.2 : s eq "dabrovic_sponza" ? 66.1 : 51.0
do for [s in "conference dabrovic_sponza sibenik"] {
  set title s." (dashed: Embree HIGH + splits)"
  set xlabel "split budget (extra references / triangles)"
  set ylabel "SAH (collapsed, max leaf 8)"
  set key top left font ",8"
  plot for [c in "9,2 16,3 32,6"] \
         "< grep -E '^".s." ATRBVH\\(".c."\\) (none|priority)' split.dat" \
         using 4:6 with linespoints lt (c eq "9,2" ? 1 : c eq "16,3" ? 2 : 3) \
         title "priority ATRBVH(".c.")", \
       for [c in "9,2 16,3 32,6"] \
         "< grep -E '^".s." ATRBVH\\(".c."\\) (none|tree)' split.dat" \
         using 4:6 with linespoints lt (c eq "9,2" ? 1 : c eq "16,3" ? 2 : 3) \
         dashtype 3 pt 6 title "tree ATRBVH(".c.")", \
       for [c in "9,2 16,3 32,6"] \
         "< grep -E '^".s." ATRBVH\\(".c."\\) (none|sah)' split.dat" \
         using 4:6 with linespoints lt (c eq "9,2" ? 1 : c eq "16,3" ? 2 : 3) \
         lw 2 pt 7 title "sah ATRBVH(".c.")", \
       embree(s) with lines lt 0 dashtype 2 lw 2 title "Embree HIGH + splits"
}
unset multiplot

# Build time against the split budget, the SAH rule (the default): the
# whole build's median ms at 2 threads, split pre-process included, from
# one quiet `atrbvh bench` run (split-time.dat, 1 December 07:33 UTC, load
# 0.1-0.6; raw bench-budget-2026-12-01.*); budget 0 the unsplit build.
set output 'split-time.png'
set multiplot layout 1,3
do for [s in "conference dabrovic_sponza sibenik"] {
  set title s." (sah rule; unsplit at 0)"
  set xlabel "split budget (extra references / triangles)"
  set ylabel "build ms (2 threads)"
  set key top left font ",8"
  plot for [c in "LBVH ATRBVH(9,2) ATRBVH(16,3) ATRBVH(32,6)"] \
         "< awk '$1==\"".s."\" && $2==\"".c."\"' split-time.dat" \
         using 3:6 with linespoints lw 2 pt 7 title c
}
unset multiplot
