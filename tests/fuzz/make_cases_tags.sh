# Families of the fuzz set for the ids and entities a mesh file refers to,
# and for inputs whose reading time grew with the square of their size.
# Sourced by make_cases.sh after make_cases_deck.sh; uses its helpers
# (new_case, set_args, set_names, edit_lines, seed_pair) and variables
# (seeds, cases, c).
#
# Families and expected exit codes:
#   ids      node and element ids of 0 or below (Gmsh tags and Abaqus
#            numbers start at 1): accepted without a word (a node 0 is
#            the "no node" of a surface edge's middle), or refused by a
#            later check that named a set or an edge instead; ids of
#            2^31 and more were "not an integer": refused at the line
#            naming the id, or the integer range. A Gmsh element id
#            used twice across types (a quadrilateral with a line's or a
#            point's id) was accepted: refused at its second line      2
#   entities a Gmsh 4.1 element block on an entity that $Entities does not
#            define, on an entity of another dimension than its elements
#            (quadrilaterals on a curve, lines on a surface), a file
#            without $Entities, an entity defined twice or of tag 0: the
#            elements fell in no physical group (or in another's) and the
#            deck's set went "not found" (or a second definition ran);
#            refused at the block's or the entity's line                2
#   slowtext inputs read in a time that grew with the square of their
#            size, so a text well inside the size limits (10^6 characters
#            a line) did not answer within the time limit: a deck line of
#            900000 characters, a group of 10^5 lines, a key of 20000
#            values, 20000 &amplitude groups (their names compared pair by
#            pair, the scene echo joined line by line), an Abaqus *NSET of
#            200000 data lines each ending with a comma (a line continued
#            200000 times); now read in linear time: refused (2) or run
#            (valid) within a second or two                    2, valid

# ---------------------------------------------------------------- ids
ids_case() {  # ids_case NAME MESH NOTE NAMES AWK
  new_case "ids.$2.$1" ids bad 2 "$2: $3"
  d=$(seed_pair "$2")
  edit_lines "$c/$2" "$5"
  set_args -o out "$d"
  set_names "$4"
}
# plate.msh (4.1): element 14 is the line "14 1 5 12 4 " of the surface block.
ids_case element-tag-0 plate.msh "element 14 renamed 0" "element id 0 is not positive" \
  '$0 == "14 1 5 12 4 " { $0 = "0 1 5 12 4 " } { print }'
ids_case element-tag-negative plate.msh "element 14 renamed -14" "element id -14 is not positive" \
  '$0 == "14 1 5 12 4 " { $0 = "-14 1 5 12 4 " } { print }'
ids_case element-tag-3e9 plate.msh "element 18 renamed 3000000000 (beyond 2^31 - 1)" "beyond the integer range" \
  '$0 == "6 18 1 18" { $0 = "6 18 1 3000000000" } $0 == "18 8 2 3 9 " { $0 = "3000000000 8 2 3 9 " } { print }'
# node 1 of plate.msh: its tag line in the block of point 1, then the point
# element "1 1 " and the lines and quadrilaterals that use it
ids_case node-tag-0 plate.msh "node 1 renamed 0 (in its block and in the elements that use it)" "node id 0 is not positive" \
  'n && $0 == "1" { $0 = "0"; n = 0 } $0 == "0 1 0 1" { n = 1 }
   $0 == "1 1 " { $0 = "1 0 " } $0 == "2 1 5 " { $0 = "2 0 5 " } $0 == "13 4 1 " { $0 = "13 4 0 " }
   $0 == "14 1 5 12 4 " { $0 = "14 0 5 12 4 " } { print }'
# plate_q8.msh (2.2): node 1 is used by elements 1 (point), 2 and 13 (lines), 14 (quadrilateral)
ids_case node-id-negative plate_q8.msh "node 1 renamed -1 (in \$Nodes and every element that uses it)" "node id -1 is not positive" \
  '$0 == "1 0 0 0" { $0 = "-1 0 0 0" } $0 == "1 15 2 6 1 1" { $0 = "1 15 2 6 1 -1" }
   $0 == "2 8 2 4 1 1 5 9" { $0 = "2 8 2 4 1 -1 5 9" } $0 == "13 8 2 2 4 4 1 24" { $0 = "13 8 2 2 4 4 -1 24" }
   $1 == 14 && $2 == 16 { $6 = -1 } { print }'
ids_case element-id-0 plate_q8.msh "element 14 renamed 0" "element id 0 is not positive" \
  '$1 == 14 && $2 == 16 { $1 = 0 } { print }'
# An element id used twice across types (a quadrilateral taking the id of
# a line or a point element): Gmsh numbers all elements of a file in one
# sequence; accepted before (the line's id is not kept), now refused at
# the second line
ids_case element-id-of-line plate.msh "quadrilateral 14 renamed 2 (the tag of a line element)" "duplicate element id 2" \
  '$0 == "14 1 5 12 4 " { $0 = "2 1 5 12 4 " } { print }'
ids_case element-id-of-point plate_q8.msh "quadrilateral 14 renamed 1 (the id of the point element)" "duplicate element id 1" \
  '$1 == 14 && $2 == 16 { $1 = 1 } { print }'
ids_case line-id-of-line plate_q8.msh "line element 13 renamed 2 (another line's id)" "duplicate element id 2" \
  '$0 == "13 8 2 2 4 4 1 24" { $0 = "2 8 2 2 4 4 1 24" } { print }'
# plate.inp: node 1 is in element 1 and the set left ("1, 5")
ids_case node-0 plate.inp "node 1 renamed 0 (in element 1 and the set left)" "node id 0 is not positive" \
  '$0 == "1, 0., 0." { $0 = "0, 0., 0." } $0 == "1, 1, 2, 6, 5" { $0 = "1, 0, 2, 6, 5" } $0 == "1, 5" { $0 = "0, 5" } { print }'
ids_case element-negative plate.inp "element 1 renamed -1 (in its surface too)" "element id -1 is not positive" \
  '$0 == "1, 1, 2, 6, 5" { $0 = "-1, 1, 2, 6, 5" } $0 == "1, S3" { $0 = "-1, S3" } $0 == "1, 3, 1" { $0 = "2, 3, 1" } { print }'
ids_case node-3e9 plate.inp "node 1 renamed 3000000000 (beyond 2^31 - 1)" "beyond the integer range" \
  '$0 == "1, 0., 0." { $0 = "3000000000, 0., 0." } { print }'

# ---------------------------------------------------------------- entities
ent_case() {  # ent_case NAME MESH NOTE NAMES AWK
  new_case "entities.$2.$1" entities bad 2 "$2: $3"
  d=$(seed_pair "$2")
  edit_lines "$c/$2" "$5"
  set_args -o out "$d"
  set_names "$4"
}
# plate.msh: "2 1 3 5" heads the block of the five quadrilaterals on
# surface 1, "1 1 1 5" the lines of curve 1; the surface's entity line
# starts "1 0 0 0 10 2 0 1 1 " (physical group 1, 'plate').
ent_case surface-block-on-missing-entity plate.msh "the quadrilaterals' block on surface 7, which \$Entities lacks" \
  "\$Entities does not define" '$0 == "2 1 3 5" { $0 = "2 7 3 5" } { print }'
ent_case quads-on-a-curve plate.msh "the quadrilaterals' block on curve 1" "on an entity of dimension 1" \
  '$0 == "2 1 3 5" { $0 = "1 1 3 5" } { print }'
ent_case quads-on-a-volume plate.msh "the quadrilaterals' block on volume 1" "on an entity of dimension 3" \
  '$0 == "2 1 3 5" { $0 = "3 1 3 5" } { print }'
ent_case lines-on-a-surface plate.msh "the lines of curve 1 in a block on surface 1" "on an entity of dimension 2" \
  '$0 == "1 1 1 5" { $0 = "2 1 1 5" } { print }'
ent_case no-entities plate.msh "the \$Entities section removed" "no \$Entities section" \
  '$0 == "$Entities" { skip = 1 } !skip { print } $0 == "$EndEntities" { skip = 0 }'
ent_case surface-twice plate.msh "surface 1 defined twice in \$Entities (the second in the group of 'top')" \
  "defined a second time" \
  '$0 == "4 4 1 0" { $0 = "4 4 2 0" } { print } /^1 0 0 0 10 2 0 1 1 / { $9 = 5; print }'
ent_case surface-tag-0 plate.msh "surface 1 renamed 0 in \$Entities" "not positive" \
  '/^1 0 0 0 10 2 0 1 1 / { $1 = 0 } { print }'
# contact.msh: "2 2 3 6" heads the block of the upper body's quadrilaterals
ent_case upper-block-on-missing-entity contact.msh "the upper body's block on surface 9, which \$Entities lacks" \
  "\$Entities does not define" '$0 == "2 2 3 6" { $0 = "2 9 3 6" } { print }'

# ---------------------------------------------------------------- slowtext
# Each was over the 20 s limit before (checked on the base binary).
new_case slowtext.plate.nml.title-900k slowtext bad 2 "plate.nml: &run title of 900000 characters on one line"
d=$(seed_pair plate.nml)
{ awk '/title =/ { exit } { print }' "$seeds/plate.nml"
  printf "  title = '"; head -c 900000 /dev/zero | tr '\000' 'a'; printf "'\n"
  awk 'p { print } /title =/ { p = 1 }' "$seeds/plate.nml"; } > "$c/plate.nml"
set_args -o out "$d"
set_names "too long"
new_case slowtext.plate.nml.blanks-900k slowtext valid 0 "plate.nml: a line of 900000 blanks inside &output"
d=$(seed_pair plate.nml)
{ awk '{ print } /^&output/ { exit }' "$seeds/plate.nml"
  head -c 900000 /dev/zero | tr '\000' ' '; echo
  awk 'p { print } /^&output/ { p = 1 }' "$seeds/plate.nml"; } > "$c/plate.nml"
set_args -o out "$d"
new_case slowtext.plate.nml.group-100k-lines slowtext valid 0 "plate.nml: 100000 blank lines inside &amplitude"
d=$(seed_pair plate.nml)
edit_lines "$c/plate.nml" '{ print } /^&amplitude/ { for (i = 0; i < 100000; i++) print "  " }'
set_args -o out "$d"
new_case slowtext.plate.nml.values-20000 slowtext bad 2 "plate.nml: &amplitude time and value of 20000 entries each, on one line"
d=$(seed_pair plate.nml)
edit_lines "$c/plate.nml" '/^  name = .ramp., time =/ { s = "  name = \047ramp\047, time = "; v = "value = "
    for (i = 0; i < 20000; i++) { s = s i "e-10, "; v = v "1.0, " } $0 = s v "1.0" } { print }'
set_args -o out "$d"
set_names "key 'time'"
new_case slowtext.plate.nml.values-100k-lines slowtext bad 2 "plate.nml: &amplitude time of 100000 entries, one a line"
d=$(seed_pair plate.nml)
edit_lines "$c/plate.nml" '/^  name = .ramp., time =/ { print "  name = \047ramp\047, value = 0.0, 1.0"; print "  time = 0.0,"
    for (i = 1; i < 100000; i++) print "  " i "e-10,"; next } { print }'
set_args -o out "$d"
set_names "key 'time'"
new_case slowtext.plate.nml.amplitudes-20000 slowtext valid 0 "plate.nml: 20000 more &amplitude groups (unused)"
d=$(seed_pair plate.nml)
edit_lines "$c/plate.nml" '{ print } END { for (i = 0; i < 20000; i++) printf "&amplitude name = \047a%d\047, time = 0.0, 1.0, value = 0.0, 1.0 /\n", i }'
set_args -o out "$d"
new_case slowtext.plate.inp.continued-200000 slowtext valid 0 "plate.inp: *NSET left continued over 200000 lines \"1,\" (trailing commas)"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '{ print } $0 == "*NSET, NSET=left" { for (i = 0; i < 200000; i++) print "1," }'
set_args -o out "$d"
