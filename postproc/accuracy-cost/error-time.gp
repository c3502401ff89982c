# Error against CPU time, log-log, one curve per element and method, for one
# problem of the accuracy-cost study (tools/accuracy-cost.sh runs it):
#   gnuplot -e "table='OUT/hertz.txt'; problem='hertz'; output='OUT/figures/hertz.png'" error-time.gp
# Left: the relative L2 error of the profile (Cattaneo: the tangential
# traction; patch test: the largest pressure deviation); right: a second
# error (peak pressure; Cattaneo: stick zone; patch test: the RMS deviation).
# Each point is one mesh level, coarse to fine from the left.
header = system("head -n 1 '" . table . "'")
col(name) = sum [i = 2:words(header)] (word(header, i) eq name ? i - 1 : 0)
if (problem eq 'cattaneo') { e1 = 'err_l2_shear'; e2 = 'err_stick'; t1 = 'tangential traction, relative L2 error'; t2 = 'stick zone |c_h - c| / a' }
if (problem eq 'patch') { e1 = 'err_max'; e2 = 'err_l2'; t1 = 'max |p - p_{exact}| / p_{exact}'; t2 = 'RMS (p - p_{exact}) / p_{exact}' }
if (problem eq 'hertz' || problem eq 'paper') { e1 = 'err_l2'; e2 = 'err_peak'; t1 = 'pressure, relative L2 error'; t2 = 'peak pressure, |relative error|' }
c1 = col(e1); c2 = col(e2); ccpu = col('cpu_s')
series = 'q4_nts q4_p0 q4_p1 q8_nts q8_p0 q8_p1 q4_ccx'
label(s) = (s eq 'q4_ccx') ? 'CalculiX Q4 (static, penalty)' : \
  sprintf('%s %s', (s[1:2] eq 'q4' ? 'Q4' : 'Q8'), (s[4:] eq 'nts' ? 'node-to-segment' : (s[4:] eq 'p0' ? 'mortar P0' : 'mortar P1')))
sel(s) = sprintf("< awk '!/^#/ && $2 \"_\" $3 == \"%s\"' '%s'", s, table)
has(s) = int(system(sprintf("awk '!/^#/ && $2 \"_\" $3 == \"%s\"' '%s' | wc -l", s, table))) > 0
set terminal pngcairo size 1200,500 font ',10'
set output output
set multiplot layout 1,2 title sprintf('accuracy-cost study: %s (one point per mesh level; CPU time of the run)', problem)
set logscale xy
set format y '10^{%L}'
set xlabel 'CPU time per run (s)'
set grid
set key bottom left font ',9'
do for [pass = 1:2] {
  c = (pass == 1) ? c1 : c2
  set ylabel (pass == 1) ? t1 : t2
  plot for [s in series] (has(s) ? sel(s) : "< true") using (column(ccpu)):(abs(column(c)) > 0 ? abs(column(c)) : 1/0) \
       with linespoints lw 1.5 pt (s[4:] eq 'nts' ? 6 : (s[4:] eq 'p0' ? 4 : (s[4:] eq 'p1' ? 8 : 2))) \
       title label(s)
}
unset multiplot
