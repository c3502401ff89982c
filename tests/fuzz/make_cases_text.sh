# Families of the fuzz set for faults the user cannot see where the
# message pointed: characters an editor does not show, a second value
# on an Abaqus keyword line that was never read, a mesh too large for
# double precision reported as an inverted element, a folder or a broken
# link given as the HDF5 file to restart from or to verify. Sourced by
# make_cases.sh after make_cases_rules.sh; uses its helpers (new_case,
# set_args, set_names, edit_lines, seed_pair) and variables (seeds,
# cases, c).
#
# Families and expected exit codes:
#   control  a form feed, an escape, a vertical tab, a DEL or code 0x01 in
#            the deck or in a mesh line: "text outside a group: '&time'",
#            "expected a section header such as "$Nodes", found
#            "$Nodes"", a node id "*ELEMENT", or read as nothing at all;
#            refused, naming the line, the column and the character. A
#            deck key written name%part (a derived-type component, which
#            no key is) was "runs into the text before it"; refused as a
#            component. Tabs and CRLF line ends run                   2, valid
#   abqparam an Abaqus keyword line of a keyword raccord reads (*NODE,
#            *ELEMENT, *NSET, *ELSET, *SURFACE, *INCLUDE) with a
#            parameter given twice (ELSET=a, ELSET=b: the second never
#            read), or a named parameter without its value (a bare ELSET:
#            no set at all, found missing only at the deck's &body), or a
#            '*' with no keyword (its data lines skipped); refused at the
#            line. Parameters in lower case, without blanks, run    2, valid
#   extent   a node of the mesh file at 1e200, 6e150 or 1.06e101 (the
#            scale-1 twin of the &mesh scale bound of 1e100): "element
#            18 is inverted or degenerate"; refused as a mesh too large
#            for double precision, before the element checks          2
#   h5input  --restart of a folder named x.checkpoint.h5 or of a broken
#            symbolic link, --verify of a folder or a broken link: "not
#            an HDF5 file, or truncated or damaged", "no checkpoint";
#            refused as a folder or as a broken link with its target    2
#   gmshsec  the $MeshFormat version written 4.10 or 2.20 (the numbers
#            4.1 and 2.2: 4.10 was refused), 4.0 or 2*4.1 (refused,
#            naming the version); $NodeData and $Periodic sections,
#            skipped without a word before: run, the log names the
#            skipped sections and $Periodic warns (its node pairs are
#            not applied)                                         2, valid

# ---------------------------------------------------------------- control
# control_case NAME FILE KIND EXPECT NOTE AWK [NAMES]: FILE of its seed pair
# edited by AWK (awk's "\f", "\033" ... make the characters).
control_case() {
  new_case "control.$2.$1" control "$3" "$4" "$2: $5"
  d=$(seed_pair "$2")
  edit_lines "$c/$2" "$6"
  set_args -o out "$d"
  [ -z "${7:-}" ] || set_names "$7"
}
control_case formfeed-group plate.nml bad 2 "a form feed before &time" \
  '$0 == "&time" { $0 = "\f&time" } { print }' "form feed"
control_case esc-number plate.nml bad 2 "an escape after density = 7.8e-9" \
  '{ sub(/density = 7.8e-9/, "density = 7.8e-9\033") } { print }' "escape"
control_case code01-number plate.nml bad 2 "code 0x01 inside young = 2e5" \
  '{ sub(/young = 200000.0/, "young = 2\001e5") } { print }' "control character"
control_case del-key plate.nml bad 2 "a DEL (0x7F) after the key poisson" \
  '{ sub(/poisson = 0.3/, "poisson\177 = 0.3") } { print }' "delete"
control_case vtab-line plate_inp.nml bad 2 "a vertical tab between two keys" \
  '/young = / { sub(/, poisson/, ",\v poisson") } { print }' "vertical tab"
control_case formfeed-nodes plate.msh bad 2 "a form feed before \$Nodes" \
  '$0 == "$Nodes" { $0 = "\f$Nodes" } { print }' "form feed"
control_case formfeed-element plate.inp bad 2 "a form feed before *ELEMENT" \
  '/^\*ELEMENT/ { $0 = "\f" $0 } { print }' "form feed"
control_case vtab-node plate.inp bad 2 "a vertical tab in the line of node 2" \
  '$0 == "2, 2., 0." { $0 = "2, 2.,\v0." } { print }' "vertical tab"
control_case esc-q8 plate_q8.msh bad 2 "an escape at the end of an element line" \
  '$1 == 14 && $2 == 16 { $0 = $0 "\033" } { print }' "escape"
control_case component-key plate.nml bad 2 "young%x = 200000.0 (a derived-type component)" \
  '{ sub(/young = 200000.0/, "young%x = 200000.0") } { print }' "names a component"
control_case tabs-crlf plate.nml valid 0 "tabs around '=' and CRLF line ends" \
  '{ gsub(/ = /, "\t=\t"); print $0 "\r" }'
control_case crlf-inp plate.inp valid 0 "CRLF line ends" '{ print $0 "\r" }'

# ---------------------------------------------------------------- abqparam
# plate.inp: "*NODE, NSET=ALL", "*ELEMENT, TYPE=CPS4, ELSET=plate",
# "*NSET, NSET=left", "*SURFACE, NAME=right, TYPE=ELEMENT".
abq_case() {  # abq_case NAME KIND EXPECT NOTE AWK [NAMES]
  new_case "abqparam.plate.inp.$1" abqparam "$2" "$3" "plate.inp: $4"
  d=$(seed_pair plate.inp)
  edit_lines "$c/plate.inp" "$5"
  set_args -o out "$d"
  [ -z "${6:-}" ] || set_names "$6"
}
abq_case elset-twice bad 2 "*ELEMENT, TYPE=CPS4, ELSET=plate, ELSET=other" \
  '/^\*ELEMENT/ { $0 = $0 ", ELSET=other" } { print }' "given twice"
abq_case elset-twice-blanks bad 2 "*ELEMENT, ..., ELSET=plate, e lset=plate (blanks and case are ignored)" \
  '/^\*ELEMENT/ { $0 = $0 ", e lset=plate" } { print }' "given twice"
abq_case type-twice bad 2 "*ELEMENT, TYPE=CPS4, ELSET=plate, TYPE=CPE4" \
  '/^\*ELEMENT/ { $0 = $0 ", TYPE=CPE4" } { print }' "given twice"
abq_case surface-name-twice bad 2 "*SURFACE, NAME=right, TYPE=ELEMENT, NAME=left_face" \
  '/^\*SURFACE, NAME=right/ { $0 = $0 ", NAME=left_face" } { print }' "given twice"
abq_case elset-bare bad 2 "*ELEMENT, TYPE=CPS4, ELSET (no value)" \
  '/^\*ELEMENT/ { sub(/ELSET=plate/, "ELSET") } { print }' "has no value"
abq_case nset-bare bad 2 "*NSET, NSET (no value) for the set left" \
  '$0 == "*NSET, NSET=left" { $0 = "*NSET, NSET" } { print }' "has no value"
abq_case node-nset-bare bad 2 "*NODE, NSET (no value)" \
  '$0 == "*NODE, NSET=ALL" { $0 = "*NODE, NSET" } { print }' "has no value"
abq_case include-twice bad 2 "*INCLUDE, INPUT=a.inp, INPUT=b.inp" \
  '{ print } END { print "*INCLUDE, INPUT=a.inp, INPUT=b.inp" }' "given twice"
printf '*NSET, NSET=extra\n1\n' > "$c/a.inp"
printf '*NSET, NSET=extra\n2\n' > "$c/b.inp"
abq_case include-bare bad 2 "*INCLUDE, INPUT (no value)" \
  '{ print } END { print "*INCLUDE, INPUT" }' "has no value"
abq_case star-alone bad 2 "a line '*' after the surfaces" \
  '{ print } END { print "*" }' "without a keyword"
abq_case star-comma bad 2 "a line '*, NSET=x' before the last *NSET" \
  '$0 == "*NSET, NSET=left" { print "*, NSET=x" } { print }' "without a keyword"
abq_case lower-no-blanks valid 0 "*element,type=cps4,elset=plate (lower case, no blanks)" \
  '/^\*ELEMENT/ { $0 = "*element,type=cps4,elset=plate" } { print }'
abq_case generate-flag valid 0 "*ELSET, ELSET=bottom_row, GENERATE, with a blank before GENERATE removed" \
  '{ sub(/, GENERATE$/, ",GENERATE") } { print }'

# ---------------------------------------------------------------- extent
new_case extent.plate.msh.node-1e200 extent bad 2 "plate.msh: node 2 at x = 1e200"
d=$(seed_pair plate.msh)
edit_lines "$c/plate.msh" '$0 == "10 0 0" && !hit { $1 = "1e200"; hit = 1 } { print }'
set_args -o out "$d"
set_names "across"
new_case extent.plate.inp.node-6e150 extent bad 2 "plate.inp: node 8 at x = 6e150"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '$0 == "8, 6., 2." { $0 = "8, 6e150, 2." } { print }'
set_args -o out "$d"
set_names "across"
new_case extent.plate.inp.offset-1e101 extent bad 2 "plate.inp: the plate moved to x = 1e101 (6e99 across)"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '/^\*/ { innode = /^\*NODE/ }
  innode && /^[1-8], [0-9.]+, [0-9.]+$/ { split($0, f, ", "); $0 = f[1] ", 1.0" int(f[2]) "e101, " f[3] } { print }'
set_args -o out "$d"
set_names "from the origin"
new_case extent.plate_q8.msh.node-1e300 extent bad 2 "plate_q8.msh: node 3 at y = -1e300"
d=$(seed_pair plate_q8.msh)
edit_lines "$c/plate_q8.msh" '$0 == "3 10 2 0" { $0 = "3 10 -1e300 0" } { print }'
set_args -o out "$d"
set_names "across"

# ---------------------------------------------------------------- h5input
new_case h5input.restart-folder h5input bad 2 "--restart x.checkpoint.h5, a folder"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
mkdir "$c/x.checkpoint.h5"
set_args -o out --restart x.checkpoint.h5 plate.nml
set_names "is a folder"
new_case h5input.restart-brokenlink h5input bad 2 "--restart x.checkpoint.h5, a link to gone.checkpoint.h5"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
ln -s gone.checkpoint.h5 "$c/x.checkpoint.h5"
set_args -o out --restart x.checkpoint.h5 plate.nml
set_names "gone.checkpoint.h5"
new_case h5input.verify-folder h5input bad 2 "--verify run.h5, a folder"
mkdir "$c/run.h5"
set_args --verify run.h5
set_names "is a folder"
new_case h5input.verify-brokenlink h5input bad 2 "--verify run.h5, a link to old/run.h5"
ln -s old/run.h5 "$c/run.h5"
set_args --verify run.h5
set_names "broken symbolic link"

# ---------------------------------------------------------------- gmshsec
# gmsh_case NAME MESH KIND EXPECT NOTE AWK [NAMES]
gmsh_case() {
  new_case "gmshsec.$2.$1" gmshsec "$3" "$4" "$2: $5"
  d=$(seed_pair "$2")
  edit_lines "$c/$2" "$6"
  set_args -o out "$d"
  [ -z "${7:-}" ] || set_names "$7"
}
gmsh_case version-4.10 plate.msh valid 0 "the version written 4.10 (the number 4.1)" \
  'NR == 2 { sub(/^4\.1 /, "4.10 ") } { print }'
gmsh_case version-2.20 plate_q8.msh valid 0 "the version written 2.20 (the number 2.2)" \
  'NR == 2 { sub(/^2\.2 /, "2.20 ") } { print }'
gmsh_case version-4.0 plate.msh bad 2 "the version written 4.0 (MSH 4.0, whose sections differ)" \
  'NR == 2 { sub(/^4\.1 /, "4.0 ") } { print }' "MSH version 4.0"
gmsh_case version-repeat plate.msh bad 2 "the version written 2*4.1 (a Fortran repeat count, no number)" \
  'NR == 2 { sub(/^4\.1 /, "2*4.1 ") } { print }' "MSH version 2*4.1"
gmsh_case periodic-nodedata plate_q8.msh valid 0 "\$NodeData and an empty \$Periodic after \$Elements (skipped; the log names them, \$Periodic warns)" \
  '{ print } /^\$EndElements/ { print "$NodeData"; print "1"; print "\"u\""; print "1"; print "0"; print "3"; print "0"; print "1"; print "1"; print "1 0"; print "$EndNodeData"; print "$Periodic"; print "0"; print "$EndPeriodic" }'
