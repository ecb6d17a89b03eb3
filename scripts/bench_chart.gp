# The main chart of `facet bench --chart OUT.png` (app/report/bench_chart.cpp runs it).
# Set with -e: datafile, outfile, title, configs (space-separated names, one data block each,
# in that order), t1 and tn (thread labels, e.g. "t=1", "t=2"; tn is "" with one thread count).
# Data columns: x, case, engine t1, OpenGL t1, engine tn, OpenGL tn (ms; NaN when not measured).

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1600, 1100 noenhanced font "sans,10"
} else {
    set terminal png size 1600, 1100 noenhanced
}
set output outfile

n = words(configs)
cols = (n > 1) ? 2 : 1
rows = (n + cols - 1) / cols
set multiplot layout rows, cols title title font ",12"
set logscale y
set grid ytics mytics
set ylabel "ms per frame (median, log scale)"
set xtics rotate by -35 left nomirror
set style fill solid 0.9 border rgb "#404040"
set boxwidth 0.18
set offsets 0.5, 0.5, 0, 0

do for [i = 1:n] {
    set title word(configs, i) font ",11"
    # One legend for all panels, in the first one's top left (the small cases leave it empty).
    if (i == 1) {
        set key inside top left vertical opaque font ",9"
    } else {
        unset key
    }
    if (tn ne "") {
        plot datafile index (i - 1) using ($1 - 0.3):3:xtic(2) with boxes lc rgb "#1f77b4" title "engine ".t1, \
             '' index (i - 1) using ($1 - 0.1):4 with boxes lc rgb "#ff7f0e" title "OpenGL ".t1, \
             '' index (i - 1) using ($1 + 0.1):5 with boxes lc rgb "#9ecae1" title "engine ".tn, \
             '' index (i - 1) using ($1 + 0.3):6 with boxes lc rgb "#fdd0a2" title "OpenGL ".tn, \
             '' index (i - 1) using ($1 - 0.4):(0.5 * $4):(0.2):(0) with vectors nohead lw 3 lc rgb "#d62728" title "target: engine <= 0.5 x OpenGL", \
             '' index (i - 1) using ($1):(0.5 * $6):(0.2):(0) with vectors nohead lw 3 lc rgb "#d62728" notitle
    } else {
        plot datafile index (i - 1) using ($1 - 0.1):3:xtic(2) with boxes lc rgb "#1f77b4" title "engine ".t1, \
             '' index (i - 1) using ($1 + 0.1):4 with boxes lc rgb "#ff7f0e" title "OpenGL ".t1, \
             '' index (i - 1) using ($1 - 0.2):(0.5 * $4):(0.2):(0) with vectors nohead lw 3 lc rgb "#d62728" title "target: engine <= 0.5 x OpenGL"
    }
}
unset multiplot
