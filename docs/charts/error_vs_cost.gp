# Error against cost (benchmarks/error_vs_iterations): on one settled step of each scene, the
# velocity error sqrt(dᵀW d / λ*ᵀW λ*) of each method after k = 1…64 iterations against the
# median time of that solve (µs). The velocity error, not the impulse error: a pyramid's load can
# be split between a face's two corners in many ways that leave the same velocities, so its
# impulse error stays near 0.46 for every method while the velocities converge.
#   gnuplot -e "data='error_vs_iterations.dat'; output='error_vs_cost.png'" error_vs_cost.gp
set terminal pngcairo size 1800,480 font "sans,10"
set output output

scenes = "stack20 pyramid8 pyramid20 rain"
variants = "sequential_cold sequential_warm micro"
labels = "'sequential, cold start' 'sequential, warm start' 'micro (k impulses per point)'"
colours = "#1b9e77 #66a61e #d95f02"

set multiplot layout 1, words(scenes) title "Velocity error against the exact answer, against the cost of the solve (one settled step; points: k = 1 … 64)" font ",12"
set logscale xy
set format y "10^{%T}"
set yrange [1e-8:2]
set xlabel "µs for the velocity solve (median)"
set ylabel "velocity error (energy norm)"
set grid
set key bottom left
do for [s = 1:words(scenes)] {
  set title word(scenes, s)
  plot for [v = 1:words(variants)] data \
         using ((strcol(1) eq word(scenes, s) && strcol(2) eq word(variants, v)) ? $7 : 1/0):5 \
         with linespoints pointtype 7 linewidth 2 linecolor rgb word(colours, v) title word(labels, v)
}
unset multiplot
