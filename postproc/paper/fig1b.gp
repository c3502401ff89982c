# Fig. 1(b): node-to-segment, frictionless, normal stress at maximum
# indentation, slave = block top against slave = disc arc, and CalculiX
# (node-to-surface, slave = block top) when its file exists.
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'; ccx='results/paper/calculix/ccx_pressure.txt'" postproc/paper/fig1b.gp
load 'common.gp'
set output output('fig1b')
set title 'Fig. 1(b): node-to-segment, normal stress at maximum indentation (0.1581 mm)'
if (!exists("ccx")) ccx = ''
have_ccx = 0
if (strlen(ccx) > 0) { have_ccx = int(system(sprintf("test -s '%s' && echo 1 || echo 0", ccx))) }
ccx_curve = ''
if (have_ccx) {
  ccx_curve = sprintf(", '%s' using 1:2 with linespoints pt 6 ps 0.6 dt 2 lc rgb '#000000' title 'CalculiX 2.20, node-to-surface, slave = block'", ccx)
}
plot prof('fig1b_nts_slave_block') index frame using cX:cP with linespoints pt 7 ps 0.5 lc rgb '#0060ad' \
       title 'raccord, slave = block ({/Symbol G}_c^2)', \
     prof('fig1b_nts_slave_disc') index frame using cX:cP with linespoints pt 5 ps 0.5 lc rgb '#dd181f' \
       title 'raccord, slave = disc ({/Symbol G}_c^1)' @ccx_curve
