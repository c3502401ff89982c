# The whole loading cycle: the force through the contact against the
# imposed displacement of the disc top, loading (0 -> T) and unloading
# (T -> 2T), for the methods.
# Ordinate: |contact1_Fy|, the vertical contact force on the slave (its
# size: the slave is the block or the disc), in N per mm of thickness. Not disc_top_Ry: the driven
# top also carries the disc's inertia (its ringing); nor block_bottom_Ry, which
# carries the block's damping (doc/reproduction.md, "The load cycle").
# Abscissa: indentation -disc_top_uy (mm).
#   gnuplot -e "res='results/paper/runs'; figdir='results/paper/figures'" postproc/paper/cycle.gp
load 'common.gp'
set output output('cycle')
set title 'Loading cycle: contact force against indentation (loading and unloading)'
set xrange [0:0.17]
set xtics 0.02
set xlabel 'indentation -u_y of the disc top (mm)'
set ylabel 'vertical contact force (N/mm)'
set key top left
# Columns found by name in the history header ('# N name').
col(file, name) = int(system(sprintf("awk -v n='%s' '$1 == \"#\" && $3 == n { print $2; f = 1; exit } END { if (!f) print 0 }' '%s'", name, file)))
f1 = hist('fig1b_nts_slave_block')
cuy = col(f1, 'disc_top_uy')
cry = col(f1, 'contact1_Fy')
ct = col(f1, 'time')
T = 2.0e-5
load_x(dummy) = column(ct) <= T*1.0001 ? -column(cuy) : NaN
unload_x(dummy) = column(ct) > T*1.0001 ? -column(cuy) : NaN
set key font ',9' spacing 0.9
# The six runs nearly coincide, so each has its own colour, dash pattern
# and marker; the markers are placed every few rows with a different
# interval per run, so that where the lines lie on top of each other the
# markers of all six still show. Loading: thicker lines; unloading: thin.
runs = 'fig1b_nts_slave_block fig1b_nts_slave_disc fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc fig2b_mortar_p0_slave_block cycle_mortar_p1_mu020'
t1 = 'NTS, slave = block'; t2 = 'NTS, slave = disc'; t3 = 'mortar P1, slave = block'
t4 = 'mortar P1, slave = disc'; t5 = 'mortar P0, slave = block'; t6 = 'mortar P1, {/Symbol m} = 0.2'
colour(k) = word('#000000 #e69f00 #0072b2 #d55e00 #009e73 #cc79a7', k)
dash(k) = k
marker(k) = word('1 2 4 6 8 12', k) + 0
every(k) = word('47 53 59 61 67 71', k) + 0
name(k) = word(runs, k)
title_of(k) = value(sprintf('t%d', k))
plot for [k = 1:6] hist(name(k)) using (load_x(0)):(abs(column(cry))) with linespoints lw 1.6 dt dash(k) \
       pt marker(k) ps 0.8 pi every(k) lc rgb colour(k) title title_of(k) . ', loading', \
     for [k = 1:6] hist(name(k)) using (unload_x(0)):(abs(column(cry))) with linespoints lw 0.8 dt dash(k) \
       pt marker(k) ps 0.6 pi every(k) lc rgb colour(k) title (k == 1 ? 'unloading (thin lines, same styles)' : '')
