# Each method's instructions per step split into finding contacts, preparing, solving velocities,
# solving positions and the rest, one panel per scene (solver_benchmark --cost-split).
#   gnuplot -e "data='cost_split.csv'; output='cost_split.png'" cost_split.gp
set datafile separator comma
set terminal pngcairo size 1200,520 font "sans,10"
set output output

scenes = "pyramid20 pyramid40 rain"
colours = "#7570b3 #e6ab02 #1b9e77 #d95f02 #66a61e #999999"
rows(scene) = sprintf("< awk -F, 'NR == 1 || $1 == \"%s\"' %s", scene, data)

set style data histograms
set style histogram rowstacked
set style fill solid 0.9 border rgb "#404040"
set boxwidth 0.7
set grid ytics
set ylabel "instructions per step (millions)"
set xtics rotate by 20 right
set yrange [0:*]
set key at screen 0.855, 0.8 left Left reverse samplen 2
set multiplot layout 1,3 margins 0.06, 0.84, 0.2, 0.88 spacing 0.06 title "Where a step's instructions go (callgrind, steps after warm-up, sleeping off)" font ",12"
do for [s = 1:words(scenes)] {
  set title word(scenes, s)
  if (s > 1) { unset key }
  plot for [c = 3:8] rows(word(scenes, s)) using c:xtic(2) title columnheader(c) \
       linecolor rgb word(colours, c - 2)
}
unset multiplot
