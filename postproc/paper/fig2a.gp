# Fig. 2(a): mortar ("raccord integral"), P1 multipliers, frictionless:
# normal stress with the slave on each body.
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'" postproc/paper/fig2a.gp
load 'common.gp'
set output output('fig2a')
set title 'Fig. 2(a): mortar P1, normal stress on {/Symbol G}_c^1 and on {/Symbol G}_c^2'
plot prof('fig2a_mortar_p1_slave_block') index frame using cX:cLN with linespoints pt 7 ps 0.5 lc rgb '#0060ad' \
       title 'mortar P1, slave = block ({/Symbol G}_c^2)', \
     prof('fig2a_mortar_p1_slave_disc') index frame using cX:cLN with linespoints pt 5 ps 0.5 lc rgb '#dd181f' \
       title 'mortar P1, slave = disc ({/Symbol G}_c^1)'
