#!/bin/sh
# A structured Abaqus mesh of a rectangle, printed on stdout: *NODE, one
# *ELEMENT block (ELSET=body) and node sets of its edges. Shared by
# tools/axi-finite-bench.sh and tools/calculix/tube-axi-ccx.sh, which add
# their own heading, material and steps around it.
#
#   sh tools/rect-mesh-inp.sh TYPE NX NY X0 X1 Y0 Y1 DIGITS [SET=EDGES ...]
#
# TYPE    CAX4 (4-node) or CAX8 (8-node serendipity, midside nodes)
# NX NY   elements along x and y on [X0, X1] x [Y0, Y1]
# DIGITS  digits after the point of the coordinates (%.<DIGITS>e)
# SET=EDGES  a *NSET named SET of the nodes on EDGES, one of left, right,
#         bottom, top or two joined by '+' (bottom+top: node by node, the
#         bottom one then the top one, x increasing)
# Numbering: node 1 + i + (MX + 1) j at grid point (i, j), MX = NX (Q4) or
# 2 NX (Q8, whose grid has no node at odd i and odd j); elements row by
# row from the bottom, corners counter-clockwise, then the midsides
# bottom, right, top, left.
set -eu
[ "$#" -ge 8 ] || { echo "rect-mesh-inp: usage: TYPE NX NY X0 X1 Y0 Y1 DIGITS [SET=EDGES ...]" >&2; exit 1; }
case $1 in CAX4|CAX8) ;; *) echo "rect-mesh-inp: TYPE is CAX4 or CAX8, not '$1'" >&2; exit 1 ;; esac
etype=$1; nx=$2; ny=$3; x0=$4; x1=$5; y0=$6; y1=$7; digits=$8
shift 8
awk -v etype="$etype" -v nx="$nx" -v ny="$ny" -v x0="$x0" -v x1="$x1" -v y0="$y0" -v y1="$y1" \
    -v digits="$digits" -v sets="$*" 'BEGIN {
  q = (etype == "CAX8"); st = q ? 2 : 1; mx = st * nx; my = st * ny
  fmt = "%d, %." digits "e, %." digits "e\n"
  print "*NODE"
  for (j = 0; j <= my; j++) for (i = 0; i <= mx; i++) {
    if (q && i % 2 == 1 && j % 2 == 1) continue
    printf fmt, 1 + i + (mx + 1) * j, x0 + (x1 - x0) * i / mx, y0 + (y1 - y0) * j / my
  }
  print "*ELEMENT, TYPE=" etype ", ELSET=body"
  e = 0
  for (j = 0; j < my; j += st) for (i = 0; i < mx; i += st) {
    n1 = 1 + i + (mx + 1) * j; n2 = n1 + st; n4 = n1 + st * (mx + 1); n3 = n4 + st
    e++
    if (q) printf "%d, %d, %d, %d, %d, %d, %d, %d, %d\n", e, n1, n2, n3, n4, n1 + 1, n2 + (mx + 1), n4 + 1, n1 + (mx + 1)
    else printf "%d, %d, %d, %d, %d\n", e, n1, n2, n3, n4
  }
  ns = split(sets, spec, " ")
  for (s = 1; s <= ns; s++) {
    eq = index(spec[s], "=")
    if (eq == 0) { print "rect-mesh-inp: a set is NAME=EDGES, not \"" spec[s] "\"" > "/dev/stderr"; exit 1 }
    print "*NSET, NSET=" substr(spec[s], 1, eq - 1)
    ne = split(substr(spec[s], eq + 1), edge, "+")
    # nodes along an edge: along x for bottom/top, along y for left/right
    along = (edge[1] == "bottom" || edge[1] == "top") ? mx : my
    for (m = 2; m <= ne; m++) if (((edge[m] == "bottom" || edge[m] == "top") ? mx : my) != along) {
      print "rect-mesh-inp: the edges joined in \"" spec[s] "\" have different node counts" > "/dev/stderr"; exit 1 }
    for (k = 0; k <= along; k++) for (m = 1; m <= ne; m++) {
      if (edge[m] == "bottom") id = 1 + k
      else if (edge[m] == "top") id = 1 + k + my * (mx + 1)
      else if (edge[m] == "left") id = 1 + (mx + 1) * k
      else if (edge[m] == "right") id = 1 + mx + (mx + 1) * k
      else { print "rect-mesh-inp: no edge \"" edge[m] "\" (left, right, bottom, top)" > "/dev/stderr"; exit 1 }
      print id
    }
  }
}'
