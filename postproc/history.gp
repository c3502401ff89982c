# Plot a raccord history file (doc/output-format.md): energies and support
# reactions against time. Non-interactive; writes two image files.
#
#   gnuplot -e "stem='results/bar_wave/bar_wave'" postproc/history.gp
#   gnuplot -e "stem='results/bar_wave/bar_wave'; format='pdf'" postproc/history.gp
#
# Variables (set with -e before the script):
#   stem    the run's path stem (required): reads <stem>.history.txt
#   format  'png' (default, pngcairo) or 'pdf' (pdfcairo)
#   out     stem of the images (default: stem): <out>.energy.<format> and
#           <out>.reactions.<format>
#
# Columns are found by name in the header ('# N name' lines), so the script
# works for any scene: energies by their fixed names, reactions from every
# '<set>_Rx' / '<set>_Ry' pair. Needs awk (to read the header).

if (!exists("stem")) {
  print "history.gp: give the run's stem, e.g. gnuplot -e \"stem='results/bar_wave/bar_wave'\" postproc/history.gp"
  exit status 2
}
if (!exists("format")) format = 'png'
if (!exists("out")) out = stem
file = stem . '.history.txt'

if (format eq 'png') {
  set terminal pngcairo size 1000,750 enhanced font ',10'
} else {
  if (format eq 'pdf') {
    set terminal pdfcairo size 8in,6in enhanced font ',9'
  } else {
    print sprintf("history.gp: format '%s' is not known; use 'png' or 'pdf'", format)
    exit status 2
  }
}

# Header lookup: col('kinetic') is the column number of 'kinetic', 0 if absent.
header = system(sprintf("awk '$1 == \"#\" && $2 ~ /^[0-9]+$/ { print $2, $3 }' '%s'", file))
if (strlen(header) == 0) {
  print sprintf("history.gp: no column header ('# N name' lines) in %s; is it a raccord history file?", file)
  exit status 2
}
col(name) = int(system(sprintf("awk -v n='%s' '$1 == \"#\" && $3 == n { print $2; f = 1; exit } END { if (!f) print 0 }' '%s'", name, file)))
# Names of the columns whose name ends with a suffix, e.g. every '<set>_Rx'.
names_ending(suffix) = system(sprintf("awk -v s='%s' '$1 == \"#\" && $2 ~ /^[0-9]+$/ && substr($3, length($3) - length(s) + 1) == s { printf \"%%s \", $3 }' '%s'", suffix, file))

t = col('time')
if (t == 0) {
  print sprintf("history.gp: %s has no 'time' column", file)
  exit status 2
}

set grid
set key outside right top noenhanced
# Fixed margins so that the panels line up whatever the width of their keys.
set lmargin 12
set rmargin at screen 0.78
set xlabel 'time'
set format x '%g'

# 1. Energies: the account of doc/theory.md section 4, and the balance
#    relative to the largest energy (zero to round-off for a sound run).
set output out . '.energy.' . format
# Names and column numbers of the energies this history has.
enames = ''
ecols = ''
do for [name in 'kinetic internal external_work damping_work contact_work friction_work energy_balance'] {
  c = col(name)
  if (c > 0) { enames = enames . name . ' '; ecols = ecols . sprintf('%d ', c) }
}
set multiplot layout 2,1 title 'energy account: ' . stem noenhanced
set ylabel 'energy'
plot for [k = 1:words(enames)] file using t:(column(int(word(ecols, k)))) with lines lw 1.5 title word(enames, k)
set ylabel 'balance / largest energy'
set format y '%.1e'
rel = col('energy_balance_rel')
if (rel > 0) {
  plot file using t:rel with lines lw 1.5 title 'energy balance rel'
} else {
  unset key
  set label 1 'no energy balance rel column' at graph 0.5, 0.5 center
  plot [0:1][0:1] NaN notitle
  unset label 1
}
unset multiplot
set format y '%g'
set key outside right top

# 2. Reactions of each support (sum over its constrained nodes), x and y.
set output out . '.reactions.' . format
# Every '<set>_Rx' with its '<set>_Ry': names and column numbers.
rx = names_ending('_Rx')
cx = ''
cy = ''
do for [name in rx] {
  cx = cx . sprintf('%d ', col(name))
  cy = cy . sprintf('%d ', col(substr(name, 1, strlen(name) - 1) . 'y'))
}
set title 'support reactions: ' . stem noenhanced
set ylabel 'reaction (force)'
if (words(rx) > 0) {
  plot for [k = 1:words(rx)] file using t:(column(int(word(cx, k)))) with lines lw 1.5 lc k dt 1 \
         title word(rx, k), \
       for [k = 1:words(rx)] file using t:(column(int(word(cy, k)))) with lines lw 1.5 lc k dt 2 \
         title substr(word(rx, k), 1, strlen(word(rx, k)) - 1) . 'y'
} else {
  unset key
  set label 1 'this scene has no supports' at graph 0.5, 0.5 center
  plot [0:1][0:1] NaN notitle
  unset label 1
}
unset output
print sprintf("history.gp: wrote %s.energy.%s and %s.reactions.%s", out, format, out, format)
