# Mass scaling (doc/accuracy-cost.md section 14): change of p_max and of the
# contact force against the unscaled run, against the CPU time as a fraction
# of the unscaled run's, one curve per series of tools/mass-scaling-study.sh.
#   gnuplot -e "table='OUTDIR/mass-scaling.txt'; output='mass-scaling.png'" mass-scaling.gp
set terminal pngcairo size 1000,450 font ",10"
set output output
set multiplot layout 1,2
set logscale y
set yrange [1e-6:10]
set xrange [0:0.6]
set xlabel 'CPU time / unscaled CPU time'
set grid
set key top right
set arrow 1 from 0.2,1e-6 to 0.2,10 nohead dt 2
set arrow 2 from 0,0.5 to 0.6,0.5 nohead dt 2
set format y '10^{%T}'
f(s) = sprintf("< awk '$1 == \"%s\" && $2 != 1' %s", s, table)
set ylabel '|change of p_{max}| (%)'
set title 'peak pressure'
plot for [s in "paper_q4_p1 paper_q4_nts paper_q8_p1 hertz_q4_p1"] f(s) using 5:(abs(100*$6)+1e-9) with linespoints title s noenhanced
set ylabel '|change of the contact force| (%)'
set title 'contact force'
plot for [s in "paper_q4_p1 paper_q4_nts paper_q8_p1 hertz_q4_p1"] f(s) using 5:(abs(100*$7)+1e-9) with linespoints title s noenhanced
unset multiplot
