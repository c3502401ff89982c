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
runs = 'fig1b_nts_slave_block fig1b_nts_slave_disc fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc fig2b_mortar_p0_slave_block fig3_mortar_p1_mu020'
titles = 'NTS,_slave_=_block NTS,_slave_=_disc mortar_P1,_slave_=_block mortar_P1,_slave_=_disc mortar_P0,_slave_=_block mortar_P1,_{/Symbol m}_=_0.2'
f1 = hist(word(runs, 1))
cuy = col(f1, 'disc_top_uy')
cry = col(f1, 'disc_top_Ry')
ct = col(f1, 'time')
T = 2.0e-5
tt(k) = system(sprintf("echo '%s' | tr _ ' '", word(titles, k)))
plot for [k = 1:words(runs)] hist(word(runs, k)) using (column(ct) <= T*1.0001 ? -column(cuy) : NaN):(-column(cry)) \
       with lines lw 1.5 lc k title tt(k) . ', loading', \
     for [k = 1:words(runs)] hist(word(runs, k)) using (column(ct) > T*1.0001 ? -column(cuy) : NaN):(-column(cry)) \
       with lines lw 1.2 dt 2 lc k title tt(k) . ', unloading'
