# Cost against error for every measured point of benchmarks/sweep, one panel per scene, one
# series per method, Box2D's points marked, the Pareto front of each scene drawn.
#   gnuplot -e "data='sweep.csv'; pareto='pareto.csv'; output='speed_vs_accuracy.png'" \
#     speed_vs_accuracy.gp
# The scenes and their errors are those of benchmarks/sweep.cpp (kPanels).
set datafile separator comma
set terminal pngcairo size 1500,1100 font "sans,10"
set output output

scenes = "stack20 pyramid20 pyramid40 rain"
errors = "'contact-force error, RMS relative (1-4 s)' 'settled drift 1-4 s (m)' 'settled drift 1-4 s (m)' 'largest penetration at rest 4-6 s (m)'"
methods = "micro sequential reference soft_step"
colours = "#d95f02 #1b9e77 #7570b3 #e7298a"

measured(scene) = strcol(1) eq scene && strcol(9) eq "measured"
of(scene, method) = measured(scene) && strcol(3) eq method

set multiplot layout 2,2 title "Speed against accuracy: every method x iterations or substeps (1-64) x dt (1/30-1/240 s), sleeping off" font ",12"
set logscale xy
set format y "10^{%T}"
set format x "10^{%T}"
set grid
set key outside bottom center horizontal font ",9"
set bmargin 7
set xlabel "cost (ms of computation per simulated second)"
do for [i = 1:words(scenes)] {
  scene = word(scenes, i)
  set title scene
  set ylabel word(errors, i)
  plot for [m = 1:words(methods)] data skip 1 \
         using (of(scene, word(methods, m)) ? $7 : 1/0):8 \
         with points pointtype 7 pointsize 0.8 linecolor rgb word(colours, m) \
         title word(methods, m) noenhanced, \
       data skip 1 using (of(scene, "box2d") ? $7 : 1/0):8 \
         with points pointtype 3 pointsize 1.6 linewidth 2 linecolor rgb "black" \
         title "Box2D 2.4.1", \
       pareto skip 1 using (strcol(1) eq scene ? $5 : 1/0):6 \
         with lines linewidth 2 dashtype 2 linecolor rgb "#444444" title "Pareto front"
}
unset multiplot
