# Gmsh MSH 4.1 ASCII (2D, 4-node quads type 3 or 8-node quads type 16, lines
# type 1 or 8) -> CalculiX/Abaqus input: *NODE, *ELEMENT per physical surface
# (ELSET = its name, CPE4 or CPE8, nodes turned counter-clockwise if needed),
# *NSET per physical curve (the nodes of its line elements) and, for each
# physical curve, an element-face surface *SURFACE, NAME=S_<curve> made of
# the faces of the quads whose edge is a line element of that curve.
#
#   awk -f tools/calculix/msh2inp.awk input/paper/paper_q4_fine.msh > mesh.inp
#   awk -v extrude=1 -f tools/calculix/msh2inp.awk MESH > mesh.inp
#
# With extrude=1 (4-node quads only) the mesh becomes one layer of C3D8
# bricks of thickness 1 (z = 0 and z = 1; node i + OFF above node i, OFF =
# the largest node tag, written as a comment line "** offset OFF"), the node
# sets hold both layers and the surfaces are brick faces S3..S6. Plane
# strain is then uz = 0 on every node (the caller's *BOUNDARY). This keeps
# CalculiX's node numbers equal to the mesh's: with CPE4, ccx expands the
# elements itself and prints contact results on the expanded nodes.
#
# Coordinates are written with 12 significant digits (ccx reads at most 20
# characters a field). Written for the paper meshes of raccord (input/paper/paper.geo); it reads
# only what those files hold ($PhysicalNames, $Entities, $Nodes, $Elements)
# and stops with a message on anything else it needs and does not know.
function fail(msg) { print "msh2inp: " msg > "/dev/stderr"; err = 1; exit 2 }
function ekey(a, b) { return (a < b) ? a SUBSEP b : b SUBSEP a }
/^\$MeshFormat/ { getline; if ($1 + 0 < 4.1 || $2 != 0) fail("only MSH 4.1 ASCII is read (found " $1 " " $2 ")"); next }
/^\$PhysicalNames/ {
  getline; n = $1
  for (i = 1; i <= n; i++) { getline; nm = $3; for (k = 4; k <= NF; k++) nm = nm " " $k; gsub(/"/, "", nm); pname[$1, $2] = nm }
  next
}
/^\$Entities/ {
  getline; np = $1; nc = $2; ns = $3; nv = $4
  for (i = 1; i <= np; i++) { getline; for (k = 1; k <= $5; k++) ephys[0, $1, k] = $(5 + k); enp[0, $1] = $5 }
  for (i = 1; i <= nc; i++) { getline; for (k = 1; k <= $8; k++) ephys[1, $1, k] = $(8 + k); enp[1, $1] = $8 }
  for (i = 1; i <= ns; i++) { getline; for (k = 1; k <= $8; k++) ephys[2, $1, k] = $(8 + k); enp[2, $1] = $8 }
  if (nv > 0) fail("3D entities are not read")
  next
}
/^\$Nodes/ {
  getline; nb = $1
  for (b = 1; b <= nb; b++) {
    getline; m = $4
    if ($3 != 0) fail("parametric nodes are not read")
    for (i = 1; i <= m; i++) { getline; tag[i] = $1 }
    for (i = 1; i <= m; i++) { getline; nn++; ntag[nn] = tag[i]; nx[tag[i]] = $1; ny[tag[i]] = $2 }
  }
  next
}
/^\$Elements/ {
  getline; nb = $1
  for (b = 1; b <= nb; b++) {
    getline; dim = $1; ent = $2; ty = $3; m = $4
    for (i = 1; i <= m; i++) {
      getline
      if (dim == 1) {
        if (ty != 1 && ty != 8) fail("line element type " ty " is not read")
        for (k = 1; k <= enp[1, ent]; k++) {
          pt = ephys[1, ent, k]; nm = pname[1, pt]
          curves[nm] = 1
          for (j = 2; j <= NF; j++) if (!((nm, $j) in inset)) { inset[nm, $j] = 1; setn[nm]++; setl[nm, setn[nm]] = $j }
          onedge[nm, ekey($2, $3)] = 1
        }
      } else if (dim == 2) {
        if (ty == 3) nen = 4; else if (ty == 16) nen = 8; else fail("surface element type " ty " is not read (4- or 8-node quads only)")
        if (enp[2, ent] < 1) fail("a surface without physical group holds elements")
        nm = pname[2, ent_first = ephys[2, ent, 1]]
        ne++; etag[ne] = $1; eset[ne] = nm; elen[ne] = nen
        for (j = 1; j <= nen; j++) en[ne, j] = $(j + 1)
        if (!(nm in bodies)) { bodies[nm] = 1; nbody++; body[nbody] = nm }
      }
    }
  }
  next
}
END {
  if (err) exit 2
  if (nn == 0 || ne == 0) fail("no nodes or no surface elements found")
  print "** written by tools/calculix/msh2inp.awk from " FILENAME (extrude ? " (extruded: one layer of C3D8, thickness 1)" : "")
  off = 0
  for (i = 1; i <= nn; i++) if (ntag[i] + 0 > off) off = ntag[i] + 0
  if (extrude) print "** offset " off
  print "*NODE"
  for (i = 1; i <= nn; i++) printf "%d, %.12g, %.12g%s\n", ntag[i], nx[ntag[i]], ny[ntag[i]], (extrude ? ", 0" : "")
  if (extrude) for (i = 1; i <= nn; i++) printf "%d, %.12g, %.12g, 1\n", ntag[i] + off, nx[ntag[i]], ny[ntag[i]]
  if (extrude) {
    print "*NSET, NSET=all_nodes"
    for (i = 1; i <= nn; i++) printf "%d, %d\n", ntag[i], ntag[i] + off
  }
  flipped = 0
  for (b = 1; b <= nbody; b++) {
    nm = body[b]; first = 1
    for (e = 1; e <= ne; e++) {
      if (eset[e] != nm) continue
      if (first) { if (extrude && elen[e] != 4) fail("extrude=1 takes 4-node quads only")
        printf "*ELEMENT, TYPE=%s, ELSET=%s\n", (extrude ? "C3D8" : (elen[e] == 4 ? "CPE4" : "CPE8")), nm; first = 0 }
      # signed area of the corner polygon; clockwise elements are reversed
      a = 0
      for (j = 1; j <= 4; j++) { p = en[e, j]; q = en[e, j % 4 + 1]; a += nx[p] * ny[q] - nx[q] * ny[p] }
      if (a < 0) {
        flipped++
        t = en[e, 2]; en[e, 2] = en[e, 4]; en[e, 4] = t
        if (elen[e] == 8) { t5 = en[e, 5]; t6 = en[e, 6]; t7 = en[e, 7]; t8 = en[e, 8]; en[e, 5] = t8; en[e, 6] = t7; en[e, 7] = t6; en[e, 8] = t5 }
      }
      line = etag[e]
      for (j = 1; j <= elen[e]; j++) line = line ", " en[e, j]
      if (extrude) for (j = 1; j <= 4; j++) line = line ", " (en[e, j] + off)
      print line
    }
  }
  for (nm in curves) {
    printf "*NSET, NSET=%s\n", nm
    for (i = 1; i <= setn[nm]; i++) printf "%d%s", setl[nm, i], (i % 12 == 0 || i == setn[nm]) ? "\n" : ", "
    if (extrude) for (i = 1; i <= setn[nm]; i++) printf "%d%s", setl[nm, i] + off, (i % 12 == 0 || i == setn[nm]) ? "\n" : ", "
    nf = 0
    for (e = 1; e <= ne; e++)
      for (j = 1; j <= 4; j++)
        if ((nm, ekey(en[e, j], en[e, j % 4 + 1])) in onedge) { nf++; fe[nf] = etag[e]; ff[nf] = j }
    if (nf > 0) {
      printf "*SURFACE, NAME=S_%s, TYPE=ELEMENT\n", nm
      for (i = 1; i <= nf; i++) printf "%d, S%d\n", fe[i], ff[i] + (extrude ? 2 : 0)
    }
  }
  if (flipped) printf "msh2inp: %d clockwise elements reversed\n", flipped > "/dev/stderr"
}
