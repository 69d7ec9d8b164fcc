# One chart of docs/stability.md: a stress scene's knob against its failure figure, one series
# per method (the knob values its bisection visited), and the criterion's limit as a dashed line.
# Called by scripts/stability as
#   gnuplot -e 'data="DIR/SCENE.dat"; output="PNG"' -e 'load "DIR/SCENE.gp"' stress/stability_chart.gp
# where SCENE.gp (written by stress_catalogue) sets title, xlabel, ylabel, limit, logx, logy.
set terminal pngcairo size 720,420 font ",9"
set output output
set title title
set xlabel xlabel
set ylabel ylabel
set key below
set format y "%g"
set grid
if (logx) set logscale x
if (logy) set logscale y
set style data linespoints
stats data using 1 nooutput
blocks = STATS_blocks
plot for [i=0:blocks-1] data index i using 1:2 title columnheader(1) pointsize 0.7, \
     limit with lines dashtype 2 linecolor rgb "black" title "limit"
