# The "camera_paths" stability sweep's chart (`facet sweeps`, app/accuracy/sweep_camera.cpp).
# Set with -e: datafile (the sweep's CSV: comma separated, `#` comment lines, a header row),
# outfile, title. Columns are read by name (the header). One row of panels per path (the paths
# are the CSV's first column, in order): frame time, what was drawn, and the comparison with the
# reference (which must stay at 0 coverage differences, 0 NaN and at most 1 LSB).

set datafile separator ","
set datafile commentschars "#"
set datafile columnheaders
set datafile missing "nan"

# The paths, in the order they appear (a path's rows are contiguous).
paths = system(sprintf("grep -v '^#' '%s' | tail -n +2 | cut -d, -f1 | uniq | tr '\\n' ' '", datafile))
n = words(paths)

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1800, 90 + 270 * n noenhanced font "sans,9"
} else {
    set terminal png size 1800, 90 + 270 * n noenhanced
}
set output outfile

# Counts on a log axis: 0 is drawn at 0.5 (labelled "0").
cnt(c) = column(c) > 0 ? column(c) : 0.5

set multiplot layout n, 3 title title font ",13"
set grid xtics ytics
set style data linespoints
set pointsize 0.7
set xtics rotate by -40 left font ",8"
set key inside top right font ",8" opaque box

do for [i = 1:n] {
    p = word(paths, i)
    # The path's rows, by row number: the tic labels come from them only.
    stats datafile using (strcol("path") eq p ? $0 : NaN) nooutput name "P"
    set xrange [-0.5:P_max - P_min + 0.5]
    if (i == 1) { set key } else { unset key }

    set title p.": time per frame" font ",10"
    set logscale y
    set ylabel "ms, log"
    set yrange [*:*]
    unset ytics
    set ytics
    plot datafile every ::P_min::P_max using (column("step")):(column("ms")):xticlabels(strcol("label")) lw 2 lc rgb "#1f77b4" title "fast (median, one thread)", \
         '' every ::P_min::P_max using (column("step")):(column("ref_ms")) lw 1 dt 2 lc rgb "#7f7f7f" title "reference (double)"

    set title p.": what was drawn" font ",10"
    set ylabel "count, log (0 drawn at 0.5)"
    set yrange [0.3:*]
    set ytics add ("0" 0.5)
    plot datafile every ::P_min::P_max using (column("step")):(cnt("ref_covered")):xticlabels(strcol("label")) with lines lw 4 lc rgb "#c7c7c7" title "pixels covered (reference)", \
         '' every ::P_min::P_max using (column("step")):(cnt("fast_covered")) with points pt 7 lc rgb "#1f77b4" title "pixels covered (fast)", \
         '' every ::P_min::P_max using (column("step")):(cnt("fragments")) lw 1 lc rgb "#2ca02c" title "fragments (fast)", \
         '' every ::P_min::P_max using (column("step")):(cnt("clipped")) lw 1 lc rgb "#ff7f0e" title "triangles clipped"
    unset logscale y

    set title p.": against the reference (outside its ambiguity mask)" font ",10"
    set ylabel "pixels / 8-bit steps"
    set yrange [-0.5:3<*]
    unset ytics
    set ytics
    plot datafile every ::P_min::P_max using (column("step")):(column("max_color_diff")):xticlabels(strcol("label")) with linespoints lw 2 lc rgb "#ff7f0e" title "max colour difference (LSB; claim: <= 1)", \
         '' every ::P_min::P_max using (column("step")):(column("coverage_diff")) with linespoints lw 3 lc rgb "#d62728" title "coverage differences", \
         '' every ::P_min::P_max using (column("step")):(column("nan_depth")) with linespoints lw 2 dt 2 lc rgb "#9467bd" title "NaN depth values", \
         '' every ::P_min::P_max using (column("step")):(column("degenerate") > 0 ? 1 : NaN) with points pt 2 ps 1.5 lc rgb "#000000" title "invalid camera (nothing may draw)", \
         1 with lines dt 3 lc rgb "#7f7f7f" title "1 LSB"
}
unset multiplot
