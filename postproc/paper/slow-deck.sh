#!/bin/sh
# Write a copy of a paper deck with the loading twice as slow (T doubled:
# maximum indentation at 4e-5 s instead of 2e-5 s, the cycle ends at 8e-5 s),
# for the quasi-static check of doc/reproduction.md. Everything else (mesh,
# materials, damping, 40 frames, so frame 20 is still t = T) is unchanged;
# the mesh path becomes absolute so that the copy can live anywhere.
#
#   sh postproc/paper/slow-deck.sh input/paper/fig2a_mortar_p1_slave_block.nml OUT.nml
set -eu
src=$1 dst=$2
srcdir=$(cd "$(dirname "$src")" && pwd)
mkdir -p "$(dirname "$dst")"
awk -v dir="$srcdir" '
  NR == 1 { print "! Copy of " FILENAME " with T doubled (written by postproc/paper/slow-deck.sh)." }
  # amplitude times and the end time are doubled; the values are not touched
  /^[ \t]*time[ \t]*=/ {
    sub(/^[ \t]*time[ \t]*=[ \t]*/, "")
    n = split($0, t, /[ \t]*,[ \t]*/)
    line = "  time = "
    for (k = 1; k <= n; k++) line = line (k > 1 ? ", " : "") sprintf("%.6e", 2 * t[k])
    print line; next
  }
  /^[ \t]*t_end[ \t]*=/ {
    match($0, /t_end[ \t]*=[ \t]*[0-9.eEdD+-]+/)
    v = substr($0, RSTART, RLENGTH); sub(/t_end[ \t]*=[ \t]*/, "", v)
    sub(/t_end[ \t]*=[ \t]*[0-9.eEdD+-]+/, sprintf("t_end = %.6e", 2 * v)); print; next
  }
  /^[ \t]*file[ \t]*=/ {
    match($0, /\047[^\047]*\047/)
    f = substr($0, RSTART + 1, RLENGTH - 2)
    if (f !~ /^\//) f = dir "/" f
    print "  file = \047" f "\047"; next
  }
  /^[ \t]*title[ \t]*=/ { sub(/\047[ \t]*$/, ", T doubled\047"); print; next }
  { print }
' "$src" > "$dst.tmp"
mv "$dst.tmp" "$dst"
