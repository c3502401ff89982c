# Families of the fuzz set for the names the deck gives to the mesh's sets
# and for the bounds of the deck's numbers. Sourced by make_cases.sh after
# make_cases_features.sh: it uses the helpers of both (new_case, set_names,
# set_key, add_to_group, edit_lines, fcase, fkey, fvalid) and the same seeds.
#
# Families and expected exit codes:
#   names   the deck's set, surface and element-set names against the
#           mesh's: an Abaqus mesh reads them as Abaqus reads labels
#           (without regard to case unless quoted: "top" and top are two
#           sets, "TOP" and top one), a Gmsh mesh exactly (as Gmsh does).
#           Names in another case (Abaqus unquoted: valid; Abaqus quoted
#           and Gmsh: refused, the message names the mesh's spelling), a
#           quoted and an unquoted label of one spelling (two sets, each
#           reached), pairs that resolve to one surface or to the same pair, a name
#           of the wrong kind (element set, node set, physical group of
#           another dimension) as contact surface, load surface, boundary
#           set or body; the message says what the name is and lists the
#           names of the kind asked for, at most 20 of them      2 (valid)
#   bounds  friction above its bound (1e3), large but accepted friction
#           (runs, a warning), tolerance outside (0, 1)           2 (valid)
#
# Program bugs these families found, fixed at their root: an Abaqus mesh's
# names were compared with the deck's case-sensitively (doc/mesh-formats.md
# said case-insensitively); "top" and top were merged into one set although
# Abaqus keeps a quoted label's case (then "Top" beside TOP was refused;
# now each is its own set, as in Abaqus); 'Top'/'TOP' pairs on an Abaqus mesh
# escaped the check for a pair given twice; friction had no upper bound and
# tolerance none (a tolerance of 1e300 was taken); a contact surface, load
# surface or boundary set that named a set of another kind said only "not
# found", and the list of names had no bound.

# ---------------------------------------------------------------- names
# Abaqus: the deck's names in other cases run as the seed does.
fvalid deck-upper names axi.nml "every mesh name of the deck in upper case"
sed -i "s/elset = 'disc'/elset = 'DISC'/; s/elset = 'punch'/elset = 'PUNCH'/; s/set = 'disc_bottom'/set = 'DISC_BOTTOM'/; s/set = 'punch_top'/set = 'Punch_Top'/; s/set = 'disc_right'/set = 'DISC_right'/; s/slave = 'punch_bottom'/slave = 'PUNCH_BOTTOM'/; s/master = 'disc_top'/master = 'Disc_Top'/" "$fdeck"
must_differ "$fdeck"
fvalid mesh-upper names axi.nml "the .inp's set and surface names in upper case, the deck's in lower"
edit_lines "$fmesh" '/^\*/ { $0 = toupper($0) } { print }'
fvalid mesh-mixed names plate_inp.nml "plate.inp's names as Left / RIGHT / Top, the deck's as written"
cp "$seeds/plate.inp" "$c/"
edit_lines "$c/plate.inp" '{ sub(/NSET=left/, "NSET=Left"); sub(/NAME=right/, "NAME=RIGHT"); sub(/NAME=top/, "NAME=Top"); sub(/ELSET=plate/, "ELSET=Plate"); print }'
fvalid set-merged names plate_inp.nml "*NSET, NSET=LEFT adds a node to the set left (one set for Abaqus)"
cp "$seeds/plate.inp" "$c/"
printf '*NSET, NSET=LEFT\n1\n' >> "$c/plate.inp"
fvalid quoted-same names axi.nml "a quoted label spelled as the deck spells it"
edit_lines "$fmesh" '$0 == "*SURFACE, NAME=punch_top, TYPE=ELEMENT" { $0 = "*SURFACE, NAME=\"punch_top\", TYPE=ELEMENT" } { print }'
# Abaqus keeps a quoted label's case (Abaqus Analysis User's Guide, "Input
# syntax rules", Labels): "Punch_axis" and punch_axis are two sets there.
fvalid quoted-nset-apart names axi.nml "*NSET, NSET=\"Punch_axis\" beside punch_axis: two sets"
printf '*NSET, NSET="Punch_axis"\n21\n' >> "$fmesh"
fvalid quoted-surface-apart names axi.nml "*SURFACE, NAME=\"Disc_Top\" beside disc_top: two surfaces"
printf '*SURFACE, NAME="Disc_Top", TYPE=ELEMENT\n1, S3\n' >> "$fmesh"
# A quoted label in upper case is the unquoted label: "DISC_TOP" adds to
# disc_top, here a face it has already (refused as an edge listed twice).
fcase names.axi.inp.quoted-upper-joins names bad 2 axi.nml "*SURFACE, NAME=\"DISC_TOP\" adds disc_top's face again"
printf '*SURFACE, NAME="DISC_TOP", TYPE=ELEMENT\n1, S3\n' >> "$fmesh"
set_names "disc_top"
# "disc" (both disc elements) and disc (the label DISC, element 1 only):
# the deck's 'disc' is "disc" (spelt alike: the seed's run), its 'DISC' or
# 'Disc' is DISC, which leaves element 2 out of every body.
fvalid quoted-lower-first names axi.nml "ELSET=\"disc\" on *ELEMENT and *ELSET, ELSET=disc (element 1): 'disc' is \"disc\""
edit_lines "$fmesh" '$0 == "*ELEMENT, TYPE=CAX8, ELSET=disc" { $0 = "*ELEMENT, TYPE=CAX8, ELSET=\"disc\"" } { print }'
printf '*ELSET, ELSET=disc\n1\n' >> "$fmesh"
fcase names.axi.inp.unquoted-beside-quoted names bad 2 axi.nml "as above, the deck's 'Disc' is DISC (element 1): element 2 in no body"
edit_lines "$fmesh" '$0 == "*ELEMENT, TYPE=CAX8, ELSET=disc" { $0 = "*ELEMENT, TYPE=CAX8, ELSET=\"disc\"" } { print }'
printf '*ELSET, ELSET=disc\n1\n' >> "$fmesh"
set_key "$fdeck" elset "'Disc'"
set_names "no &body"
# A quoted label is found only as spelt: the deck's other case is refused,
# naming the quoted spelling.
for n in punch_top disc_bottom; do
  fcase "names.axi.inp.quoted-case-$n" names bad 2 axi.nml "*SURFACE, NAME=\"$n\" capitalised, the deck's '$n'"
  edit_lines "$fmesh" -v n="$n" '$0 == "*SURFACE, NAME=" n ", TYPE=ELEMENT" { $0 = "*SURFACE, NAME=\"" toupper(substr(n, 1, 1)) substr(n, 2) "\", TYPE=ELEMENT" } { print }'
  set_names "double quotes"
done
# A data line names a set by the same rule: "disc_row" in quotes is the
# label disc_row, not the set disc_row of the *ELSET line (the label
# DISC_ROW), and is undefined; "DISC_ROW" in quotes is that set.
fcase names.axi.inp.quoted-entry-undefined names bad 2 axi.nml "*SURFACE face line naming \"disc_row\" (the set is DISC_ROW)"
edit_lines "$fmesh" '$0 == "disc_row, S3" { $0 = "\"disc_row\", S3" } { print }'
set_names "\"disc_row\""
fvalid quoted-entry-upper names axi.nml "*SURFACE face line naming \"DISC_ROW\" (the label of disc_row)"
edit_lines "$fmesh" '$0 == "disc_row, S3" { $0 = "\"DISC_ROW\", S3" } { print }'
# Blanks in an unquoted label are ignored (Abaqus), kept in a quoted one.
fvalid blanks-unquoted names axi.nml "ELSET=disc row (blanks ignored: DISCROW), named Disc Row by disc_top's face line"
edit_lines "$fmesh" '{ sub(/ELSET=disc_row/, "ELSET=disc row"); sub(/^disc_row, S3$/, "Disc Row, S3") } { print }'
# A label of no character, or blanks only, is refused.
fcase names.axi.inp.empty-label names bad 2 axi.nml "*NSET, NSET=\"\" (no label)"
printf '*NSET, NSET=""\n21\n' >> "$fmesh"
set_names "needs its name"
fcase names.axi.inp.blank-label names bad 2 axi.nml "*SURFACE, NAME=\" \" (blanks only)"
printf '*SURFACE, NAME=" ", TYPE=ELEMENT\n1, S3\n' >> "$fmesh"
set_names "no label"
fcase names.axi.inp.empty-node-nset names bad 2 axi.nml "*NODE, NSET= (empty)"
edit_lines "$fmesh" '$0 == "*NODE, NSET=disc_nodes" { $0 = "*NODE, NSET=" } { print }'
set_names "no label"
# Inside the .inp: a data line that names a set of the other kind says so.
fcase names.axi.inp.surface-on-nset names bad 2 axi.nml "disc_top's faces given on the node set disc_nodes"
edit_lines "$fmesh" '$0 == "disc_row, S3" { $0 = "disc_nodes, S3" } { print }'
set_names "is a node set"
fcase names.axi.inp.nset-of-elset names bad 2 axi.nml "*NSET, NSET=extra listing the element set disc_row"
printf '*NSET, NSET=extra\ndisc_row\n' >> "$fmesh"
set_names "is an element set"
fcase names.axi.inp.elset-of-surface names bad 2 axi.nml "*ELSET, ELSET=extra listing the surface disc_top"
printf '*ELSET, ELSET=extra\ndisc_top\n' >> "$fmesh"
set_names "is a surface"
# Pairs that resolve to one surface, or to one pair, on an Abaqus mesh.
fcase names.axi.nml.pair-self-case names bad 2 axi.nml "slave 'disc_top', master 'DISC_TOP'"
set_key "$fdeck" slave "'disc_top'"
set_key "$fdeck" master "'DISC_TOP'"
set_names "same surface"
fcase names.axi.nml.pair-twice-case names bad 2 axi.nml "the pair again as PUNCH_BOTTOM / Disc_Top"
echo "&contact_pair slave = 'PUNCH_BOTTOM', master = 'Disc_Top', method = 'mortar' /" >> "$fdeck"
set_names "contact_pair #1"
fvalid pair-two-pass-case names axi.nml "two-pass contact with the second pair in upper case"
echo "&contact_pair slave = 'DISC_TOP', master = 'PUNCH_BOTTOM', method = 'mortar', friction = 0.2 /" >> "$fdeck"
# A name of the wrong kind: the message says what it is.
fkey slave-elset names axi.nml slave "'disc_row'" "element set"
fkey master-elset-case names axi.nml master "'DISC'" "element set"
fkey slave-nset names axi.nml slave "'disc_nodes'" "node set"
fkey load-on-nset names axi.nml set "'punch_axis'" "node set" 2
fkey load-on-elset names axi.nml set "'disc_row'" "element set" 2
fkey fixed-on-elset names axi.nml set "'Disc_Row'" "element set" 1
fkey body-on-surface names axi.nml elset "'disc_top'" "surface" 1
fkey body-on-nset names axi.nml elset "'punch_axis'" "node set" 2
fkey slave-unknown names axi.nml slave "'punch_bottm'" "surfaces there" 1
# Gmsh compares exactly: a name in another case is refused, naming the mesh's spelling.
fkey slave-case names loop.nml slave "'Pin_Surface'" "pin_surface"
fkey master-case names loop.nml master "'HOLE'" "case-sensitive"
fkey elset-case names loop.nml elset "'PIN'" "case-sensitive" 1
fkey set-case names loop.nml set "'Plate_Edge'" "plate_edge" 1
fkey pressure-case names finite.nml set "'Upper_Top'" "upper_top" 4
# Gmsh groups of another dimension.
fkey slave-phys-surface names loop.nml slave "'pin'" "physical curve"
fkey master-phys-point names loop.nml master "'pin_center'" "node set"
fkey pressure-phys-point names finite.nml set "'lower_anchor'" "node set" 4
fkey fixed-phys-surface names finite.nml set "'lower'" "element set" 1
fkey body-phys-point names finite.nml elset "'upper_anchor'" "node set" 2
# Gmsh keeps "hole" and "HOLE" apart: both are usable, each by its spelling.
fvalid two-cases names loop.nml "plate_edge renamed HOLE beside hole: the deck names each exactly"
edit_lines "$fmesh" '$0 == "1 1 \"plate_edge\"" { $0 = "1 1 \"HOLE\"" } { print }'
set_key "$fdeck" set "'HOLE'" 1
# More than 20 surfaces: the list is cut, with the count of the others.
fcase names.axi.inp.many-surfaces names bad 2 axi.nml "30 more surfaces and an unknown slave"
i=0
while [ $i -lt 30 ]; do
  i=$((i + 1))
  printf '*SURFACE, NAME=extra_%02d, TYPE=ELEMENT\n11, S2\n' "$i" >> "$fmesh"
done
set_key "$fdeck" slave "'punch_side'"
set_names "more)"

# ---------------------------------------------------------------- bounds
fkey friction-above bounds axi.nml friction "1000.5" "friction" 1 contact_pair
for v in 1.0e4 1.0e300; do
  fkey "friction-$v" bounds loop.nml friction "$v" "friction" 1 contact_pair
done
for v in 1.0 2.0 1.0e300 0.0 -1.0e-10; do
  fkey "tolerance-$v" bounds finite.nml tolerance "$v" "tolerance" 1 contact_pair
done
# Large but accepted: the pairs stick, the solves converge (a warning names the key).
for d in axi.nml loop.nml; do
  for v in 50.0 1000.0; do
    fvalid "friction-$v" bounds "$d" "friction = $v (accepted, a warning)"
    set_key "$fdeck" friction "$v"
  done
done
fvalid friction-1000-nts bounds contact.nml "node-to-segment with friction = 1000"
set_key "$fdeck" friction "1000.0"
fvalid friction-1000-weighted bounds finite.nml "mortar 'weighted' with friction = 1000"
set_key "$fdeck" friction "1000.0"
