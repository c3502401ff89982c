# Fig. 4(a): mortar P1, frictionless: Q1 (4-node, paper_q4) against Q2
# (8-node, paper_q8) with the same interface node spacing.
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'" postproc/paper/fig4a.gp
load 'common.gp'
set output output('fig4a')
set title 'Fig. 4(a): mortar P1, normal stress for Q_1 and Q_2 elements'
plot prof('fig4a_q4_mortar_p1') index frame using cX:cLN with linespoints pt 7 ps 0.5 lc rgb '#0060ad' \
       title 'Q_1 (4-node), mortar P1', \
     prof('fig4a_q8_mortar_p1') index frame using cX:cLN with linespoints pt 4 ps 0.6 lc rgb '#dd181f' \
       title 'Q_2 (8-node), mortar P1'
