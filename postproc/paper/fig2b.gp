# Fig. 2(b): mortar, P0 against P1 multipliers, frictionless (slave = block;
# slave = disc dashed).
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'" postproc/paper/fig2b.gp
load 'common.gp'
set output output('fig2b')
set title 'Fig. 2(b): mortar, normal stress for M_{hn}^0 (P0) and M_{hn}^1 (P1)'
plot prof('fig2a_mortar_p1_slave_block') index frame using cX:cLN with linespoints pt 7 ps 0.5 lc rgb '#0060ad' \
       title 'P1, slave = block', \
     prof('fig2b_mortar_p0_slave_block') index frame using cX:cLN with linespoints pt 4 ps 0.6 lc rgb '#dd181f' \
       title 'P0, slave = block', \
     prof('fig2a_mortar_p1_slave_disc') index frame using cX:cLN with lines dt 2 lc rgb '#0060ad' \
       title 'P1, slave = disc', \
     prof('fig2b_mortar_p0_slave_disc') index frame using cX:cLN with lines dt 3 lc rgb '#dd181f' \
       title 'P0, slave = disc'
