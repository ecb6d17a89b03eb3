# `facet sweeps` depth-precision chart (app/accuracy/sweep_depth.cpp writes the CSV).
# Set with -e: datafile, outfile, title.
# Columns: distance, relative_gap, fighting, smallest_resolved. Rows run by distance, then from the largest gap.

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1400, 560 noenhanced font "sans,10"
} else {
    set terminal png size 1400, 560 noenhanced
}
set output outfile
set datafile separator ","

distances = "1 10 100 1000 10000"
colors = "#d62728 #ff7f0e #2ca02c #1f77b4 #9467bd"
set multiplot layout 1, 2 title title font ",12"
set grid
set key below horizontal font ",9"

set title "Share of the far plane showing through the near one"
set logscale x 10
set format x "%.0e"
set xlabel "gap between the planes, delta / d (log scale)"
set ylabel "z-fighting pixels (share of covered)"
set yrange [-0.02:1.02]
# 2^-24: a float's relative spacing, the storage format's own limit.
set arrow 1 from 2**-24, graph 0 to 2**-24, graph 1 nohead dt 2 lc rgb "#808080"
set label 1 "float ulp 2^-24" at 2**-24, graph 0.95 offset 0.5, 0 font ",9"
plot for [k = 1:5] datafile every ::1 using 2:($1 == word(distances, k) + 0 ? $3 : NaN) \
     with linespoints lw 2 pt 7 ps 0.5 lc rgb word(colors, k) title "d = " . word(distances, k)
unset arrow 1
unset label 1

set title "Smallest gap resolved without z-fighting, against distance"
set xlabel "distance d (log scale)"
set ylabel "smallest resolved delta (log scale)"
set logscale y 10
set format y "%.0e"
set autoscale y
set xrange [0.5:20000]
# Every row of a distance carries its smallest resolved delta/d; smooth unique takes one per d.
plot datafile every ::1 using 1:($4 * $1) smooth unique with linespoints lw 2 pt 7 \
     lc rgb "#1f77b4" title "smallest resolved delta", \
     x * 2**-24 with lines dt 2 lc rgb "#808080" title "d * 2^-24 (one float ulp of depth)"
unset multiplot
