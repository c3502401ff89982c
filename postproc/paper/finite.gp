# The paper's test with finite strain (issue #13; doc/reproduction.md, "The
# paper's test with finite strain"): normal stress at maximum indentation,
# small strain (the Fig. 1(b) and 2(a) decks, dashed) beside finite strain
# with neo-Hooke bodies (input/paper/finite_*.nml, solid), one panel per
# matching and slave choice; CalculiX with NLGEOM (ccxf) and without (ccx)
# on the slave = block panels when their files exist.
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'; ccx='results/paper/calculix/ccx_pressure.txt'; ccxf='results/paper/calculix-finite/ccx_pressure.txt'" postproc/paper/finite.gp
load 'common.gp'
# four panels: a larger page than common.gp's
if (format eq 'png') {
  set terminal pngcairo size 1080,790 enhanced font ',9' linewidth 1.1
} else {
  set terminal pdfcairo size 8in,5.9in enhanced font ',8'
}
set output output('finite')
if (!exists("ccx")) ccx = ''
if (!exists("ccxf")) ccxf = ''
have(f) = (strlen(f) > 0) ? int(system(sprintf("test -s '%s' && echo 1 || echo 0", f))) : 0
have_ccx = have(ccx)
have_ccxf = have(ccxf)
ccx_curves = ''
if (have_ccxf) {
  ccx_curves = ccx_curves . sprintf(", '%s' using 1:2 with points pt 6 ps 0.6 lc rgb '#000000' title 'CalculiX NLGEOM'", ccxf)
}
if (have_ccx) {
  ccx_curves = ccx_curves . sprintf(", '%s' using 1:2 with points pt 4 ps 0.5 lc rgb '#808080' title 'CalculiX small'", ccx)
}
set yrange [0:*]
set key top left box opaque samplen 2 font ',9'
set multiplot layout 2,2 title 'The paper''s test at maximum indentation (0.1581 mm): small strain (dashed) against finite strain, neo-Hooke (solid)'

set title 'node-to-segment, slave = block ({/Symbol G}_c^2)'
plot prof('fig1b_nts_slave_block') index frame using cX:cP with lines dt 2 lw 1.5 lc rgb '#0060ad' title 'small strain', \
     prof('finite_nts_slave_block') index frame using cX:cP with linespoints pt 7 ps 0.4 lc rgb '#0060ad' title 'finite strain' @ccx_curves

# Node-to-segment with the disc as slave does not reach full depth with
# finite strain on this mesh (doc/reproduction.md): when its run stopped,
# the panel shows the last frame it wrote, beside the small-strain run and
# the finite slave = block run at the same frame.
nd_file = prof('finite_nts_slave_disc')
nd_frame = frame
if (!have(nd_file)) {
  nd_file = sprintf('%s/finite_nts_slave_disc/finite_nts_slave_disc.contact1.incomplete.txt', res)
  nd_frame = have(nd_file) ? int(system(sprintf("awk '/^# frame/ { f = $3 } END { print f + 0 }' '%s'", nd_file))) : -1
}
if (nd_frame == frame) {
  set title 'node-to-segment, slave = disc ({/Symbol G}_c^1)'
  plot prof('fig1b_nts_slave_disc') index frame using cX:cP with lines dt 2 lw 1.5 lc rgb '#dd181f' title 'small strain', \
       nd_file index frame using cX:cP with linespoints pt 5 ps 0.4 lc rgb '#dd181f' title 'finite strain'
} else {
  if (nd_frame >= 0) {
    set title sprintf('node-to-segment, slave = disc ({/Symbol G}_c^1): the finite run stopped; frame %d (t = %.1f T)', nd_frame, nd_frame/20.0)
    plot prof('fig1b_nts_slave_disc') index nd_frame using cX:cP with lines dt 2 lw 1.5 lc rgb '#dd181f' title 'small strain', \
         prof('finite_nts_slave_block') index nd_frame using cX:cP with lines lw 1.5 lc rgb '#0060ad' title 'finite, slave = block', \
         nd_file index nd_frame using cX:cP with linespoints pt 5 ps 0.4 lc rgb '#dd181f' title 'finite, slave = disc'
  } else {
    set title 'node-to-segment, slave = disc ({/Symbol G}_c^1): no finite run'
    plot prof('fig1b_nts_slave_disc') index frame using cX:cP with lines dt 2 lw 1.5 lc rgb '#dd181f' title 'small strain'
  }
}

set title 'mortar P1, slave = block ({/Symbol G}_c^2), {/Symbol l}_n'
plot prof('fig2a_mortar_p1_slave_block') index frame using cX:cLN with lines dt 2 lw 1.5 lc rgb '#009e73' title 'small strain', \
     prof('finite_mortar_p1_slave_block') index frame using cX:cLN with linespoints pt 7 ps 0.4 lc rgb '#009e73' title 'finite strain' @ccx_curves

set title 'mortar P1, slave = disc ({/Symbol G}_c^1), {/Symbol l}_n'
plot prof('fig2a_mortar_p1_slave_disc') index frame using cX:cLN with lines dt 2 lw 1.5 lc rgb '#e69f00' title 'small strain', \
     prof('finite_mortar_p1_slave_disc') index frame using cX:cLN with linespoints pt 5 ps 0.4 lc rgb '#e69f00' title 'finite strain'
unset multiplot
