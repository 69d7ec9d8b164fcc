# Cost per step against body count on the pyramid family of benchmarks/sweep, log-log, each
# method at its defaults and Box2D, with the fitted exponent (cost ∝ boxes^b) in the legend.
#   gnuplot -e "data='scaling.csv'; output='scaling.png'" scaling.gp
set datafile separator comma
set terminal pngcairo size 900,620 font "sans,10"
set output output

methods = "micro sequential reference soft_step box2d"
labels = "'micro (200 per contact)' 'sequential (≤ 40 sweeps, converged)' 'reference (active set)' 'soft step (4 substeps)' 'Box2D 2.4.1 (8+3)'"
colours = "#d95f02 #1b9e77 #7570b3 #e7298a #000000"

exponent(method) = system(sprintf("awk -F, '$1 == \"%s\" {printf \"%%.2f\", $7; exit}' %s", method, data))
legend(m) = sprintf("%s: cost ∝ boxes^{%s}", word(labels, m), exponent(word(methods, m)))

set title "Cost per step against boxes (pyramids of 10 to 4950 boxes, sleeping off)" font ",12"
set logscale xy
set format y "10^{%T}"
set xlabel "boxes"
set ylabel "time per step (µs, median)"
set grid
set key bottom right
plot for [m = 1:words(methods)] data skip 1 \
       using (strcol(1) eq word(methods, m) ? $3 : 1/0):5 \
       with linespoints pointtype 7 linewidth 2 linecolor rgb word(colours, m) title legend(m)
