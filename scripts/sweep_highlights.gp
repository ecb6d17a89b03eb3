# `facet sweeps` highlights chart (app/accuracy/sweep_highlights.cpp writes the CSV).
# Set with -e: datafile, outfile, title.
# Columns: rings, shininess, gouraud_peak, phong_peak, ratio, gouraud_rmse, phong_rmse,
# gouraud_ms, phong_ms. Rows run by rings, then shininess.

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1400, 560 noenhanced font "sans,10"
} else {
    set terminal png size 1400, 560 noenhanced
}
set output outfile
set datafile separator ","

rings = "8 16 32 64"
colors = "#d62728 #ff7f0e #2ca02c #1f77b4"
set multiplot layout 1, 2 title title font ",12"
set grid
set logscale x 2
set xlabel "shininess s (log scale)"
set key below horizontal font ",9"

set title "Gouraud's highlight peak as a share of Phong's (1: kept, 0: lost)"
set ylabel "Gouraud peak / Phong peak"
set yrange [0:1.05]
set arrow 1 from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lc rgb "#808080"
plot for [r = 1:4] datafile every ::1 using 2:($1 == word(rings, r) + 0 ? $5 : NaN) \
     with linespoints lw 2 pt 7 ps 0.7 lc rgb word(colors, r) title word(rings, r) . " rings"
unset arrow 1
set autoscale y

set title "RMSE against the ground truth (Phong per sample, 8x8), fully covered pixels"
set ylabel "RMSE (LSB)"
plot for [r = 1:4] datafile every ::1 using 2:($1 == word(rings, r) + 0 ? $6 : NaN) \
     with linespoints lw 2 pt 7 ps 0.7 lc rgb word(colors, r) title "Gouraud, " . word(rings, r) . " rings", \
     for [r = 1:4] datafile every ::1 using 2:($1 == word(rings, r) + 0 ? $7 : NaN) \
     with linespoints lw 1 dt 2 pt 6 ps 0.6 lc rgb word(colors, r) title "Phong, " . word(rings, r) . " rings"
unset multiplot
