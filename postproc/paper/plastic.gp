# The paper's test with a plastic layer (issue #14; doc/reproduction.md,
# "The paper's test with a plastic layer"): the block J2, yield stress
# 700 MPa, H = 70 MPa (input/paper/plastic_*.nml). Left: normal stress at
# maximum indentation (frame 20), mortar P1 (lambda_n) and node-to-segment
# (pressure), slave = block, beside the elastic layer (Fig. 2(a) deck,
# dashed); middle: the block top after the disc went back up (frame 40),
# its vertical displacement against x; right: the force against the
# indentation over the cycle (raccord: the block-bottom reaction against
# the disc top's descent, history columns 12 and 18). CalculiX *PLASTIC on the same mesh
# (tools/calculix/plastic-ccx.sh, folder ccxpl) when its files exist.
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'; ccxpl='results/paper/calculix-plastic'" postproc/paper/plastic.gp
load 'common.gp'
if (format eq 'png') {
  set terminal pngcairo size 1500,480 enhanced font ',10' linewidth 1.2
} else {
  set terminal pdfcairo size 11in,3.5in enhanced font ',8'
}
set output output('plastic')
if (!exists("ccxpl")) ccxpl = ''
have(f) = (strlen(f) > 0) ? int(system(sprintf("test -s '%s' && echo 1 || echo 0", f))) : 0
ccx_p = ccxpl . '/ccx_pressure.txt'
ccx_r = ccxpl . '/ccx_residual.txt'
ccx_f = ccxpl . '/ccx_force.txt'
curves_p = ''
if (have(ccx_p)) {
  curves_p = sprintf(", '%s' using 1:2 with points pt 6 ps 0.7 lc rgb '#000000' title 'CalculiX *PLASTIC'", ccx_p)
}
curves_r = ''
if (have(ccx_r)) {
  curves_r = sprintf(", '%s' using ($1 + $2):3 with points pt 6 ps 0.7 lc rgb '#000000' title 'CalculiX *PLASTIC'", ccx_r)
}
curves_f = ''
if (have(ccx_f)) {
  curves_f = sprintf(", '%s' using 1:2 with points pt 6 ps 0.5 lc rgb '#000000' title 'CalculiX *PLASTIC (static)'", ccx_f)
}
last = 2*frame
set multiplot layout 1,3 title 'The paper''s test with a J2 layer ({/Symbol s}_y = 700 MPa, H = 70 MPa): loaded to 0.1581 mm and unloaded'

set title 'maximum indentation (t = T)'
set yrange [0:*]
set key top right box opaque samplen 2 font ',9'
plot prof('fig2a_mortar_p1_slave_block') index frame using cX:cLN with lines dt 2 lw 1.2 lc rgb '#808080' title 'elastic layer, mortar P1', \
     prof('plastic_mortar_p1_slave_block') index frame using cX:cLN with linespoints pt 7 ps 0.4 lc rgb '#009e73' title 'J2 layer, mortar P1 ({/Symbol l}_n)', \
     prof('plastic_nts_slave_block') index frame using cX:cP with linespoints pt 5 ps 0.4 lc rgb '#0060ad' title 'J2 layer, node-to-segment (p)' @curves_p

set title 'after unloading (t = 2T): the block top'
set xrange [-0.9:0.9]
set yrange [-0.14:0.03]
set ylabel 'vertical displacement of the block top u_y (mm)'
set key bottom right box opaque samplen 2 font ',9'
plot prof('plastic_mortar_p1_slave_block') index last using cX:3 with linespoints pt 7 ps 0.4 lc rgb '#009e73' title 'J2 layer, mortar P1', \
     prof('plastic_nts_slave_block') index last using cX:3 with linespoints pt 5 ps 0.4 lc rgb '#0060ad' title 'J2 layer, node-to-segment' @curves_r

set title 'force against indentation, load and unload'
set xrange [0:0.16]
set xtics 0.04
set yrange [0:*]
set xlabel 'indentation: descent of the disc top (mm)'
set ylabel 'force (N/mm)'
set key top left box opaque samplen 2 font ',9'
plot hist('fig2a_mortar_p1_slave_block') using (-$18):12 with lines dt 2 lw 1.2 lc rgb '#808080' title 'elastic layer, mortar P1', \
     hist('plastic_mortar_p1_slave_block') using (-$18):12 with lines lw 1.5 lc rgb '#009e73' title 'J2 layer, mortar P1', \
     hist('plastic_nts_slave_block') using (-$18):12 with lines lw 1.5 lc rgb '#0060ad' title 'J2 layer, node-to-segment' @curves_f
unset multiplot
