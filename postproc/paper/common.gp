# Settings shared by the paper's figures (postproc/paper/fig*.gp, cycle.gp).
# Loaded by each figure script; not meant to be run alone.
#
# Variables (gnuplot -e before the script):
#   res     folder holding the runs, <res>/<deck>/<deck>.* (required)
#   figdir  folder of the images (default '.')
#   format  'png' (pngcairo, default) or 'pdf' (pdfcairo)
#   frame   result frame of the profiles (default 20: t = T, maximum indentation)
#   ccx     two-column file x p of the CalculiX run (Fig. 1(b) only; optional)
#
# Conventions of every profile figure (doc/reproduction.md):
#   abscissa  x (mm), the deformed x of the slave node (column 2 of the
#             contact profile <deck>.contact1.txt);
#   normal    compressive positive: contact pressure p = -sigma_n >= 0 in MPa.
#             Mortar: the multiplier lambda_n (column 9), the paper's curve;
#             node-to-segment: 'pressure' (column 5), nodal force over the
#             node's tributary length;
#   tangent   the tangential multiplier lambda_t (mortar, column 10) in MPa,
#             with raccord's sign (along the slave chain's tangent).
if (!exists("res")) {
  print "give the result folder: gnuplot -e \"res='results/paper/runs'\" postproc/paper/<figure>.gp"
  exit status 2
}
if (!exists("figdir")) figdir = '.'
if (!exists("format")) format = 'png'
if (!exists("frame")) frame = 20
if (format eq 'png') {
  set terminal pngcairo size 900,620 enhanced font ',11' linewidth 1.3
} else {
  if (format eq 'pdf') {
    set terminal pdfcairo size 6in,4.1in enhanced font ',9'
  } else {
    print sprintf("format '%s' is not known; use 'png' or 'pdf'", format)
    exit status 2
  }
}
prof(name) = sprintf('%s/%s/%s.contact1.txt', res, name, name)
hist(name) = sprintf('%s/%s/%s.history.txt', res, name, name)
output(name) = sprintf('%s/%s.%s', figdir, name, format)
# columns of the contact profile
cX = 2; cP = 5; cTAU = 6; cST = 7; cLN = 9; cLT = 10
set grid
set key top right box opaque samplen 3
set xrange [-0.8:0.8]
set xtics 0.2
set xlabel 'x (mm), position along the interface (deformed)'
set ylabel 'normal stress -{/Symbol s}_n (MPa), compression > 0'
