#!/bin/sh
# Plot a raccord history with gnuplot (postproc/history.gp): energies and
# support reactions against time, written next to the results.
#
#   sh postproc/plot-history.sh STEM [png|pdf]
#
# STEM is the run's path stem, e.g. results/bar_wave/bar_wave (the file
# read is STEM.history.txt); writes STEM.energy.png and STEM.reactions.png
# (or .pdf). Exit 0 on success, 2 on bad arguments or a missing file,
# 3 when gnuplot is not installed (Debian: apt-get install gnuplot-nox).
set -eu
usage="usage: sh postproc/plot-history.sh STEM [png|pdf]   (reads STEM.history.txt)"
if [ "$#" -lt 1 ] || [ "$#" -gt 2 ]; then
  echo "$usage" >&2
  exit 2
fi
stem=$1
format=${2:-png}
case "$format" in
  png|pdf) ;;
  *) echo "plot-history: format '$format' is not known; use png or pdf" >&2; exit 2 ;;
esac
case "$stem" in
  *\'*) echo "plot-history: a stem with a quote (') is not supported: $stem" >&2; exit 2 ;;
esac
stem=${stem%.history.txt}
if [ ! -f "$stem.history.txt" ]; then
  echo "plot-history: $stem.history.txt does not exist (give the stem, e.g. results/bar_wave/bar_wave)" >&2
  exit 2
fi
if ! command -v gnuplot > /dev/null 2>&1; then
  echo "plot-history: gnuplot is not installed (Debian: apt-get install gnuplot-nox)" >&2
  exit 3
fi
exec gnuplot -e "stem='$stem'; format='$format'" "$(dirname "$0")/history.gp"
