# `facet sweeps` view-angle chart (app/accuracy/sweep_view_angle.cpp writes the CSV).
# Set with -e: datafile, outfile, title.
# Columns: surface, degrees, method, rmse, max, over2, pixels, rmse_reference, max_reference, ms.

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1400, 1000 noenhanced font "sans,10"
} else {
    set terminal png size 1400, 1000 noenhanced
}
set output outfile
set datafile separator ","
set datafile missing "nan"

methods = "affine subdivided:32 subdivided:16 subdivided:8 perspective"
colors = "#d62728 #ff7f0e #bcbd22 #2ca02c #1f77b4"
surfaces = "facet floor"
set multiplot layout 2, 2 title title font ",12"
set grid
set xrange [0:90]
set xtics 0, 10, 90
set key below horizontal font ",9"
do for [s = 1:2] {
    surf = word(surfaces, s)
    set title surf . ": RMSE against the ground truth (8x8 samples, bilinear on level 0)"
    set xlabel "degrees off the surface normal"
    set ylabel "RMSE over fully covered pixels (LSB)"
    plot for [m = 1:5] datafile every ::1 using 2:((strcol(1) eq surf && strcol(3) eq word(methods, m)) ? $4 : NaN) \
         with linespoints lw 2 pt 7 ps 0.6 lc rgb word(colors, m) title word(methods, m)
    set title surf . ": the interpolation's own error, against the 1-sample perspective reference"
    set ylabel "RMSE over covered pixels (LSB)"
    plot for [m = 1:5] datafile every ::1 using 2:((strcol(1) eq surf && strcol(3) eq word(methods, m)) ? $8 : NaN) \
         with linespoints lw 2 pt 7 ps 0.6 lc rgb word(colors, m) title word(methods, m)
}
unset multiplot
