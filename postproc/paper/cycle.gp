# The whole loading cycle: force on the driven disc top against its imposed
# displacement, loading (0 -> T) and unloading (T -> 2T), for the methods.
# Ordinate: -disc_top_Ry (the support pushes the disc down, so Ry < 0; the
# sign is turned so that pushing is positive), in N per mm of thickness.
# Abscissa: indentation -disc_top_uy (mm).
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'" postproc/paper/cycle.gp
load 'common.gp'
set output output('cycle')
set title 'Loading cycle: force on the disc top against indentation (loading and unloading)'
set xrange [0:0.17]
set xtics 0.02
set xlabel 'indentation -u_y of the disc top (mm)'
set ylabel 'force -R_y on the disc top (N/mm), pushing > 0'
set key top left
# Columns found by name in the history header ('# N name').
col(file, name) = int(system(sprintf("awk -v n='%s' '$1 == \"#\" && $3 == n { print $2; f = 1; exit } END { if (!f) print 0 }' '%s'", name, file)))
f1 = hist('fig1b_nts_slave_block')
cuy = col(f1, 'disc_top_uy')
cry = col(f1, 'disc_top_Ry')
ct = col(f1, 'time')
T = 2.0e-5
load_x(dummy) = column(ct) <= T*1.0001 ? -column(cuy) : NaN
unload_x(dummy) = column(ct) > T*1.0001 ? -column(cuy) : NaN
set key font ',9' spacing 0.9
plot hist('fig1b_nts_slave_block')       using (load_x(0)):(-column(cry)) with lines lw 1.4 lc 1 title 'NTS, slave = block, loading', \
     hist('fig1b_nts_slave_disc')        using (load_x(0)):(-column(cry)) with lines lw 1.4 lc 2 title 'NTS, slave = disc, loading', \
     hist('fig2a_mortar_p1_slave_block') using (load_x(0)):(-column(cry)) with lines lw 1.4 lc 3 title 'mortar P1, slave = block, loading', \
     hist('fig2a_mortar_p1_slave_disc')  using (load_x(0)):(-column(cry)) with lines lw 1.4 lc 4 title 'mortar P1, slave = disc, loading', \
     hist('fig2b_mortar_p0_slave_block') using (load_x(0)):(-column(cry)) with lines lw 1.4 lc 6 title 'mortar P0, slave = block, loading', \
     hist('fig3_mortar_p1_mu020')        using (load_x(0)):(-column(cry)) with lines lw 1.4 lc 7 title 'mortar P1, {/Symbol m} = 0.2, loading', \
     hist('fig1b_nts_slave_block')       using (unload_x(0)):(-column(cry)) with lines dt 2 lc 1 title 'unloading (dashed, same colours)', \
     hist('fig1b_nts_slave_disc')        using (unload_x(0)):(-column(cry)) with lines dt 2 lc 2 notitle, \
     hist('fig2a_mortar_p1_slave_block') using (unload_x(0)):(-column(cry)) with lines dt 2 lc 3 notitle, \
     hist('fig2a_mortar_p1_slave_disc')  using (unload_x(0)):(-column(cry)) with lines dt 2 lc 4 notitle, \
     hist('fig2b_mortar_p0_slave_block') using (unload_x(0)):(-column(cry)) with lines dt 2 lc 6 notitle, \
     hist('fig3_mortar_p1_mu020')        using (unload_x(0)):(-column(cry)) with lines dt 2 lc 7 notitle
