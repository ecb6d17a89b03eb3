# `facet sweeps` sub-pixel precision chart (app/accuracy/sweep_subpixel.cpp writes the CSV).
# Set with -e: datafile, outfile, title.
# Columns: scene, bits, width, height, triangles, covered, differ, ambiguous, differ_pct, cracks,
# layers_changed, rmse, over2lsb_pct, median_ms, min_ms, max_ms.

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1400, 1000 noenhanced font "sans,10"
} else {
    set terminal png size 1400, 1000 noenhanced
}
set output outfile
set datafile separator ","
set datafile missing "nan"

# Scenes the CSV lacks (no shared data) plot nothing.
scenes = "sphere fan bunny spot"
colors = "#1f77b4 #ff7f0e #2ca02c #d62728"
pick(col, s) = (strcol(1) eq word(scenes, s)) ? column(col) : NaN
set multiplot layout 2, 2 title title font ",12"
set grid
set xrange [1.5:8.5]
set xtics 2, 1, 8
set xlabel "fractional bits of the snapping grid (8 = 1/256 px, the default)"
set key top right font ",9"

set title "coverage against the exact (unsnapped) coverage: pixels whose visible triangle differs"
set ylabel "% of the covered pixels (log scale)"
set logscale y
set key bottom left font ",9"
plot for [s = 1:4] datafile every ::1 using 2:(pick(9, s)) \
         with linespoints lw 2 pt 7 ps 0.7 lc rgb word(colors, s) title word(scenes, s), \
     for [s = 1:4] datafile every ::1 using 2:(pick(9, s) * (1.0 - column(8) / column(7))) \
         with linespoints lw 1 dt 2 pt 6 ps 0.7 lc rgb word(colors, s) \
         title word(scenes, s) . ": farther than 1/256 px from an edge"
unset logscale y
set key top right font ",9"

set title "picture against the supersampled ground truth"
set ylabel "RMSE (LSB)"
plot for [s = 1:4] datafile every ::1 using 2:(pick(12, s)) \
         with linespoints lw 2 pt 7 ps 0.7 lc rgb word(colors, s) title word(scenes, s)

set title "frame time (Renderer::render, one thread): median, bars min to max"
set ylabel "ms per frame (log scale)"
set logscale y
plot for [s = 1:4] datafile every ::1 using 2:(pick(14, s)):(pick(15, s)):(pick(16, s)) \
         with yerrorlines lw 2 pt 7 ps 0.7 lc rgb word(colors, s) title word(scenes, s)
unset logscale y

set title "crack check: cracks (front - back coverage off the winding number), and pixels drawn\nmore or fewer times than at 8 bits (silhouettes moving, slivers folding)"
set ylabel "pixels"
set yrange [-3:*]
plot for [s = 1:4] datafile every ::1 using 2:(pick(11, s)) \
         with linespoints lw 2 pt 7 ps 0.7 lc rgb word(colors, s) title word(scenes, s) . ": layers changed", \
     for [s = 1:4] datafile every ::1 using 2:(pick(10, s)) \
         with linespoints lw 1 dt 2 pt 4 ps 0.9 lc rgb word(colors, s) title word(scenes, s) . ": cracks"
unset multiplot
