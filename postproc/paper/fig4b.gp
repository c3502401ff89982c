# Fig. 4(b): Q2 (8-node) elements, mortar P0 and P1, mu = 0.2: normal and
# tangential stress.
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'" postproc/paper/fig4b.gp
load 'common.gp'
set output output('fig4b')
set title 'Fig. 4(b): Q_2 elements, mortar P0 and P1, {/Symbol m} = 0.2'
set ylabel 'stress (MPa): normal -{/Symbol s}_n (> 0), tangential {/Symbol l}_t'
plot prof('fig4b_q8_mortar_p1_mu020') index frame using cX:cLN with linespoints pt 7 ps 0.5 lc rgb '#0060ad' \
       title 'normal, P1', \
     prof('fig4b_q8_mortar_p0_mu020') index frame using cX:cLN with linespoints pt 4 ps 0.6 lc rgb '#dd181f' \
       title 'normal, P0', \
     prof('fig4b_q8_mortar_p1_mu020') index frame using cX:cLT with linespoints pt 7 ps 0.5 dt 2 lc rgb '#0060ad' \
       title 'tangential, P1', \
     prof('fig4b_q8_mortar_p0_mu020') index frame using cX:cLT with linespoints pt 4 ps 0.6 dt 2 lc rgb '#dd181f' \
       title 'tangential, P0'
