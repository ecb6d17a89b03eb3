# The "extreme" stability sweep's chart (`facet sweeps`, app/accuracy/sweep_extreme.cpp).
# Set with -e: datafile (the sweep's CSV: comma separated, `#` comment lines, a header row),
# outfile, title. Columns are read by name (the header), so added columns do not break it.
# Each row is one triangle drawn by the fast path (one thread) and by the double reference.

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1600, 1800 noenhanced font "sans,10"
} else {
    set terminal png size 1600, 1800 noenhanced
}
set output outfile
set datafile separator ","
set datafile commentschars "#"
set datafile columnheaders
set datafile missing "nan"

# Rows of one family only; every other row is NaN, so plot skips it.
is(f) = strcol("family") eq f
of(f, c) = is(f) ? column(c) : NaN
# Counts on a log axis: 0 is drawn at 0.5 (labelled "0").
cnt(f, c) = is(f) ? (column(c) > 0 ? column(c) : 0.5) : NaN

set multiplot layout 4, 2 title title font ",13"
set grid xtics ytics mytics
set key inside top left opaque font ",9" box
set style data linespoints
set pointsize 0.8

# 1. Time against size.
set title "Size (edge length, px): time per draw" font ",11"
set logscale xy
set format x "1e%T"
set format y "%g"
set xlabel "edge length (px), log"
set ylabel "µs per draw (median), log"
plot datafile using (of("size", "param")):(of("size", "fast_us")) lw 2 lc rgb "#1f77b4" title "fast, generic position", \
     '' using (of("size_pixel_centre", "param")):(of("size_pixel_centre", "fast_us")) lw 2 dt 2 lc rgb "#17becf" title "fast, on a pixel centre", \
     '' using (of("size", "param")):(1000 * of("size", "ref_ms")) lw 1 lc rgb "#7f7f7f" title "reference (double), generic position"

# 2. Covered pixels against size.
set title "Size: covered pixels, fast (points) and reference (line)" font ",11"
set ylabel "pixels covered, log (0 drawn at 0.5)"
set ytics add ("0" 0.5)
set yrange [0.3:*]
plot datafile using (of("size", "param")):(cnt("size", "ref_covered")) with lines lw 3 lc rgb "#c7c7c7" title "reference, generic", \
     '' using (of("size", "param")):(cnt("size", "fast_covered")) with points pt 7 ps 1.0 lc rgb "#1f77b4" title "fast, generic", \
     '' using (of("size_pixel_centre", "param")):(cnt("size_pixel_centre", "ref_covered")) with lines lw 3 dt 2 lc rgb "#9edae5" title "reference, pixel centre", \
     '' using (of("size_pixel_centre", "param")):(cnt("size_pixel_centre", "fast_covered")) with points pt 6 ps 1.4 lc rgb "#17becf" title "fast, pixel centre", \
     '' using (of("size_pixel_centre", "param")):(cnt("size_pixel_centre", "ambiguous")) with points pt 2 ps 1.0 lc rgb "#d62728" title "ambiguous pixels (reference), pixel centre"
set yrange [*:*]
set ytics auto

# 3. Slivers.
set key bottom left
set title "Slivers: time per draw and covered pixels against aspect (long edge / height)" font ",11"
set xlabel "aspect ratio, log"
set ylabel "µs per draw (median), log"
set y2label "pixels covered (fast), log"
set logscale y2
set y2tics
set ytics nomirror
plot datafile using (of("sliver", "param")):(of("sliver", "fast_us")) lw 2 lc rgb "#1f77b4" title "time, long edge 1e3 px", \
     '' using (of("sliver_long", "param")):(of("sliver_long", "fast_us")) lw 2 lc rgb "#ff7f0e" title "time, long edge 1e6 px", \
     '' using (of("sliver", "param")):(cnt("sliver", "fast_covered")) axes x1y2 with points pt 6 lc rgb "#1f77b4" title "pixels, 1e3 px", \
     '' using (of("sliver_long", "param")):(cnt("sliver_long", "fast_covered")) axes x1y2 with points pt 4 lc rgb "#ff7f0e" title "pixels, 1e6 px"

# 4. Far vertices.
set title "Far vertices at ±M px: time per draw and covered pixels" font ",11"
set xlabel "M (px), log"
plot datafile using (of("far_wedge", "param")):(of("far_wedge", "fast_us")) lw 2 lc rgb "#2ca02c" title "time, thin wedge through the image", \
     '' using (of("far_vertex", "param")):(of("far_vertex", "fast_us")) lw 2 lc rgb "#9467bd" title "time, one far vertex (w = 3)", \
     '' using (of("far_wedge", "param")):(cnt("far_wedge", "fast_covered")) axes x1y2 with points pt 6 lc rgb "#2ca02c" title "pixels, wedge", \
     '' using (of("far_vertex", "param")):(cnt("far_vertex", "fast_covered")) axes x1y2 with points pt 4 lc rgb "#9467bd" title "pixels, far vertex"
unset logscale
unset y2tics
unset y2label
set ytics mirror
set format x "%g"

# 5. Near plane: one vertex's w, categorical (it goes through 0 to negative values).
set title "Through the near plane (0.01): one vertex's clip w" font ",11"
set xlabel "w of the moving vertex"
set ylabel "µs per draw (median)"
set y2label "pixels covered"
set y2tics
set ytics nomirror
set xtics rotate by -45 left font ",8"
set yrange [0:*]
set y2range [0:*]
# The categorical panels take their tic labels from one family's rows only (`every` by row
# number): labels of the other rows would overwrite them.
set key outside below horizontal center
stats datafile using (is("near_vertex") ? $0 : NaN) nooutput name "NEAR"
set xrange [-0.5:NEAR_max - NEAR_min + 0.5]
plot datafile every ::NEAR_min::NEAR_max using (column("step")):(column("fast_us")):xticlabels(strcol("label")) lw 2 lc rgb "#1f77b4" title "time, vertex at a fixed pixel", \
     '' using (of("near_fixed_clip", "step")):(of("near_fixed_clip", "fast_us")) lw 2 lc rgb "#ff7f0e" title "time, vertex at fixed clip x, y (pixel to infinity)", \
     '' using (of("near_vertex", "step")):(of("near_vertex", "fast_covered")) axes x1y2 with points pt 6 ps 1.2 lc rgb "#1f77b4" title "pixels, fixed pixel", \
     '' using (of("near_fixed_clip", "step")):(of("near_fixed_clip", "fast_covered")) axes x1y2 with points pt 4 ps 1.2 lc rgb "#ff7f0e" title "pixels, fixed clip x, y"
unset y2tics
unset y2label
set ytics mirror

# 6. Non-finite clip coordinates.
set title "Non-finite clip coordinates: fast path's fragments (alone: 0, but NaN z, which is never read)" font ",11"
set xlabel "the bad vertex"
set ylabel "fragments"
set style fill solid 0.85 border rgb "#404040"
set boxwidth 0.27
set key inside top right
set offsets 0, 0, graph 0.25, 0
stats datafile using (is("nonfinite") ? $0 : NaN) nooutput name "BAD"
set xrange [-0.5:BAD_max - BAD_min + 0.5]
plot datafile every ::BAD_min::BAD_max using (column("step") - 0.28):(column("fragments")):xticlabels(strcol("label")) with boxes lc rgb "#d62728" title "bad triangle alone", \
     '' using (of("nonfinite_mixed", "step")):(of("nonfinite_mixed", "fragments")) with boxes lc rgb "#1f77b4" title "bad triangle, then a good one", \
     '' using (of("nonfinite_mixed", "step") + 0.28):(of("nonfinite_mixed", "ref_covered")) with boxes lc rgb "#c7c7c7" title "reference: what must remain (pixels)"
set xtics norotate font ",10"
set xrange [*:*]
set offsets 0, 0, 0, 0
set key inside top left vertical

# 7. What the tests assert, over every case: flat zero lines.
set title "Every case: coverage differences outside the ambiguity mask, NaN depth (must be 0), max colour difference" font ",11"
set xlabel "case (grouped by family)"
set ylabel "pixels / 8-bit steps"
set yrange [-0.5:3<*]
set xtics rotate by -45 left font ",8"
plot datafile using 0:(column("max_color_diff")):xticlabels(column("step") == 0 ? strcol("family") : "") with impulses lw 2 lc rgb "#ff7f0e" title "max colour difference (LSB; claim: <= 1)", \
     '' using 0:(column("coverage_diff")) with lines lw 3 lc rgb "#d62728" title "coverage differences", \
     '' using 0:(column("nan_depth")) with lines lw 2 dt 2 lc rgb "#9467bd" title "NaN depth values", \
     1 with lines dt 3 lc rgb "#7f7f7f" title "1 LSB"
set yrange [*:*]

# 8. Pixels the reference calls ambiguous (where the fast path may legitimately differ).
set title "Every case: pixels covered (reference) and ambiguous pixels (excluded from the comparison)" font ",11"
set ylabel "pixels, log (0 drawn at 0.5)"
set logscale y
set ytics add ("0" 0.5)
# Headroom above the tallest bar for the key.
stats datafile using (column("ref_covered")) nooutput name "COV"
set yrange [0.3:30 * COV_max + 10]
allcnt(c) = column(c) > 0 ? column(c) : 0.5
plot datafile using 0:(allcnt("ref_covered")):xticlabels(column("step") == 0 ? strcol("family") : "") with impulses lw 2 lc rgb "#1f77b4" title "covered (reference)", \
     '' using 0:(allcnt("ambiguous")) with points pt 7 ps 0.6 lc rgb "#d62728" title "ambiguous"
unset multiplot
