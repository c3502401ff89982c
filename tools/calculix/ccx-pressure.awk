# Contact pressure of a CalculiX run of the paper scene, per block-top node,
# at the last time printed (helper of fig1b-ccx.sh and finite-ccx.sh).
#
#   awk -v what='TEXT' [-v at=TIME] -f tools/calculix/ccx-pressure.awk mesh.inp RUN.dat > out
#
# at: the total time to extract (as printed in RUN.dat, e.g. 1 for the end
# of a first step of length 1); default the last time printed.
# mesh.inp (tools/calculix/msh2inp.awk, CPE4) gives the reference x0 of
# each node and the block_top node set; RUN.dat holds *NODE PRINT U for
# NSET=block_top and *CONTACT PRINT CSTR. ccx expands the CPE4 elements into
# bricks and prints the contact stress on the expanded nodes: for mesh node
# i those are nk + 3(i - 1) + 1 .. 3 (nk = the largest node number; observed
# with ccx 2.20); every node so mapped must be a block-top node, else the
# mapping does not hold for this ccx and the script stops (exit 1).
# Output: a comment line (what, time), then "x p" per block-top node,
# unsorted: x = x0 + ux (deformed), p = CSTR pressure (0 where none printed).
FNR == 1 { file++ }
file == 1 && /^\*NODE$/ { innode = 1; next }
file == 1 && /^\*NSET, NSET=block_top$/ { inset = 1; innode = 0; next }
file == 1 && /^\*/ { innode = 0; inset = 0; next }
file == 1 && innode { split($0, a, /, */); x0[a[1] + 0] = a[2]; if (a[1] + 0 > nk) nk = a[1] + 0; next }
file == 1 && inset { n = split($0, a, /, */); for (k = 1; k <= n; k++) if (a[k] != "") top[a[k] + 0] = 1; next }
file == 2 && /displacements \(vx,vy,vz\) for set BLOCK_TOP/ { blk = "u"; t = $NF; next }
file == 2 && /contact stress/ { blk = "p"; t = $NF; next }
file == 2 && /^ *$/ { next }
file == 2 && NF == 4 && $1 ~ /^[0-9]+$/ {
  if (blk == "u") ux[t, $1 + 0] = $2
  if (blk == "p") { i = int(($1 - nk - 1) / 3) + 1; p[t, i] = $2; seen[t, i] = $1 }
  if (at == "" || t + 0 == at + 0) last = t
  next
}
file == 2 { blk = "" }
END {
  for (k in seen) {
    split(k, b, SUBSEP)
    if (b[1] == last && !(b[2] in top)) {
      printf "ccx-pressure: contact node %s maps to mesh node %s, not a block-top node; the node mapping does not hold for this ccx\n", seen[k], b[2] > "/dev/stderr"
      exit 1
    }
  }
  print "# CalculiX " what ", time " last ": x (mm, deformed), pressure (MPa)"
  for (n in top) printf "%.10g %.10g\n", x0[n] + ux[last, n], ((last, n) in p) ? p[last, n] : 0
}
