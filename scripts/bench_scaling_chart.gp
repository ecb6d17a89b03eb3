# The chart of `facet bench --scaling --chart OUT.png` (app/report/bench_chart.cpp runs it).
# Set with -e: datafile, outfile, title, t1 and tn (thread labels; tn is "" with one count),
# trilabel and pixlabel (the two x axes).
# Data: block 0 against triangles, block 1 against Mpixels. Columns: x, engine t1, OpenGL t1,
# engine tn, OpenGL tn, linear reference (ms; NaN when not measured).

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1500, 650 noenhanced font "sans,10"
} else {
    set terminal png size 1500, 650 noenhanced
}
set output outfile

set multiplot layout 1, 2 title title font ",12"
set logscale xy
set grid xtics ytics mxtics mytics
set ylabel "ms per frame (median)"
set key top left font ",9"
set style data linespoints

do for [b = 0:1] {
    if (b == 0) {
        set xlabel trilabel
        set format x "%.0s%c"
    } else {
        set xlabel pixlabel
        set format x "%g"
    }
    if (tn ne "") {
        plot datafile index b using 1:2 lc rgb "#1f77b4" pt 7 title "engine ".t1, \
             '' index b using 1:3 lc rgb "#ff7f0e" pt 7 title "OpenGL ".t1, \
             '' index b using 1:4 lc rgb "#1f77b4" dt 2 pt 6 title "engine ".tn, \
             '' index b using 1:5 lc rgb "#ff7f0e" dt 2 pt 6 title "OpenGL ".tn, \
             '' index b using 1:6 with lines lc rgb "#404040" dt 3 lw 2 title "linear (slope 1)"
    } else {
        plot datafile index b using 1:2 lc rgb "#1f77b4" pt 7 title "engine ".t1, \
             '' index b using 1:3 lc rgb "#ff7f0e" pt 7 title "OpenGL ".t1, \
             '' index b using 1:6 with lines lc rgb "#404040" dt 3 lw 2 title "linear (slope 1)"
    }
}
unset multiplot
