# Error against iterations (benchmarks/error_vs_iterations): the relative impulse error
# |λ − λ*|/|λ*| of sequential impulses after k sweeps (cold and warm started) and of the
# micro-collision resolver after k impulses per point, on one settled step (t = 1 s; rain 5 s),
# against the global reference's exact answer of the same pre-solve state. One panel per scene.
#   gnuplot -e "data='error_vs_iterations.dat'; output='error_vs_iterations.png'" error_vs_iterations.gp
set terminal pngcairo size 1800,480 font "sans,10"
set output output

scenes = "stack10 stack20 pyramid20 rain"
variants = "sequential_cold sequential_warm micro"
labels = "'sequential, cold start' 'sequential, warm start' 'micro (k impulses per point)'"
colours = "#1b9e77 #66a61e #d95f02"

set multiplot layout 1, words(scenes) title "Impulse error against the exact answer after k iterations (one settled step: t = 1 s, rain 5 s)" font ",12"
set logscale xy
set format y "10^{%T}"
set xrange [1:64]
set yrange [1e-8:2]
set xlabel "k (sweeps; impulses per point for micro)"
set ylabel "|λ − λ*| / |λ*|"
set grid
set key bottom right
do for [s = 1:words(scenes)] {
  set title word(scenes, s)
  plot for [v = 1:words(variants)] data \
         using ((strcol(1) eq word(scenes, s) && strcol(2) eq word(variants, v)) ? $3 : 1/0):4 \
         with linespoints pointtype 7 linewidth 2 linecolor rgb word(colours, v) title word(labels, v)
}
unset multiplot
