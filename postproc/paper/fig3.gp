# Fig. 3: mortar with Coulomb friction, P0 and P1, mu = 0.1, 0.2, 0.5
# (slave = block): normal stress (top) and tangential stress (bottom).
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'" postproc/paper/fig3.gp
load 'common.gp'
if (format eq 'png') { set terminal pngcairo size 900,1000 } else { set terminal pdfcairo size 6in,6.8in }
set output output('fig3')
set multiplot layout 2,1 title 'Fig. 3: mortar, normal and tangential stress, P0 and P1, {/Symbol m} = 0.1, 0.2, 0.5'
mus = '010 020 050'
mul = '0.1 0.2 0.5'
colour(k) = word('#0060ad #00a000 #dd181f', k)
# P1: solid lines. P0: its own marker per mu (triangle, square, diamond),
# large enough to show over the P1 line of the same colour, joined by a
# thin dotted line.
p0mark(k) = word('8 4 12', k) + 0
set key top right font ',9'
plot for [k = 1:3] prof('fig3_mortar_p1_mu' . word(mus, k)) index frame using cX:cLN with lines lw 1.5 lc rgb colour(k) \
       title sprintf('P1, {/Symbol m} = %s', word(mul, k)), \
     for [k = 1:3] prof('fig3_mortar_p0_mu' . word(mus, k)) index frame using cX:cLN with linespoints dt 3 lw 0.8 pt p0mark(k) ps 1.0 lc rgb colour(k) \
       title sprintf('P0, {/Symbol m} = %s', word(mul, k))
set ylabel 'tangential stress {/Symbol l}_t (MPa)'
set key top center
plot for [k = 1:3] prof('fig3_mortar_p1_mu' . word(mus, k)) index frame using cX:cLT with lines lw 1.5 lc rgb colour(k) \
       title sprintf('P1, {/Symbol m} = %s', word(mul, k)), \
     for [k = 1:3] prof('fig3_mortar_p0_mu' . word(mus, k)) index frame using cX:cLT with linespoints dt 3 lw 0.8 pt p0mark(k) ps 1.0 lc rgb colour(k) \
       title sprintf('P0, {/Symbol m} = %s', word(mul, k))
unset multiplot
