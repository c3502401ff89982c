# Families of the fuzz set for input rules a user could trip over without
# a word: scenes that ran with a meaning nobody asked for, and messages
# that sent the user looking for the wrong fault. Sourced by make_cases.sh
# after make_cases_tags.sh; uses its helpers (new_case, set_args,
# set_names, edit_lines, seed_pair) and variables (seeds, cases, c).
#
# Families and expected exit codes:
#   thickness a contact pair between plane bodies of different
#            thicknesses: accepted, the contact stresses taken per unit
#            of the slave body's thickness while the master's stresses
#            were per unit of its own; refused, naming the pair and both
#            thicknesses (doc/scene-reference.md, &contact_pair). The
#            same thickness on both bodies (not 1) runs              2, valid
#   brokenlink the deck, the mesh or an Abaqus *INCLUDE given as a
#            symbolic link whose target is missing (or a loop of links):
#            "does not exist" (or the runtime's "cannot open"), while ls
#            shows the file; refused, naming the link and its target   2
#   setrange an Abaqus *NSET / *ELSET entry of 2^31 or more: "neither a
#            node id nor a node set"; refused as an id beyond the integer
#            range, as the node and element ids are                    2
#   endpart  a lone *End Part (or *End Instance, *End Assembly) without
#            its opening keyword, which is refused: read past without a
#            word; refused at its line                                  2

# ---------------------------------------------------------------- thickness
# contact.nml: the bodies 'lower' and 'upper', each on one line
# "name = '...', elset = '...'".
thick_case() {  # thick_case NAME KIND EXPECT NOTE AWK [NAMES]
  new_case "thickness.contact.nml.$1" thickness "$2" "$3" "contact.nml: $4"
  d=$(seed_pair contact.nml)
  edit_lines "$c/contact.nml" "$5"
  set_args -o out "$d"
  [ -z "${6:-}" ] || set_names "$6"
}
thick_case upper-2 bad 2 "the master body 'upper' 2 mm thick, the slave 'lower' 1 mm (the default)" \
  '/name = .upper./ { $0 = $0 ", thickness = 2.0" } { print }' "thickness"
thick_case lower-half bad 2 "the slave body 'lower' 0.5 mm thick, the master 'upper' 1 mm (the default)" \
  '/name = .lower./ { $0 = $0 ", thickness = 0.5" } { print }' "thickness"
thick_case both-3 valid 0 "both bodies 3 mm thick" \
  '/name = .(lower|upper)./ { $0 = $0 ", thickness = 3.0" } { print }'

# ---------------------------------------------------------------- brokenlink
new_case brokenlink.deck brokenlink bad 2 "the deck d.nml is a link to gone.nml, which is missing"
cp "$seeds/plate.msh" "$c/"
ln -s gone.nml "$c/d.nml"
set_args -o out d.nml
set_names "broken symbolic link"
new_case brokenlink.deck-loop brokenlink bad 2 "the deck d.nml is a link to e.nml, a link to d.nml"
cp "$seeds/plate.msh" "$c/"
ln -s e.nml "$c/d.nml"
ln -s d.nml "$c/e.nml"
set_args -o out d.nml
set_names "broken symbolic link"
new_case brokenlink.mesh brokenlink bad 2 "plate.nml's mesh plate.msh is a link to /nonexistent/plate.msh"
d=$(seed_pair plate.msh)
rm -f "$c/plate.msh"
ln -s /nonexistent/plate.msh "$c/plate.msh"
set_args -o out "$d"
set_names "/nonexistent/plate.msh"
new_case brokenlink.include brokenlink bad 2 "plate.inp includes inc.inp, a link to old/inc.inp, which is missing"
d=$(seed_pair plate.inp)
echo "*INCLUDE, INPUT=inc.inp" >> "$c/plate.inp"
ln -s old/inc.inp "$c/inc.inp"
set_args -o out "$d"
set_names "old/inc.inp"

# ---------------------------------------------------------------- setrange
# plate.inp: "*NSET, NSET=left" is followed by "1, 5"; the element set
# bottom_row is a GENERATE range, so an extra *ELSET is appended.
new_case setrange.plate.inp.nset-3e9 setrange bad 2 "plate.inp: *NSET left lists 3000000000"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '$0 == "1, 5" { $0 = "1, 5, 3000000000" } { print }'
set_args -o out "$d"
set_names "beyond the integer range"
new_case setrange.plate.inp.nset-2p31 setrange bad 2 "plate.inp: *NSET left lists 2147483648 (2^31)"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '$0 == "1, 5" { $0 = "2147483648, 1, 5" } { print }'
set_args -o out "$d"
set_names "beyond the integer range"
new_case setrange.plate.inp.elset-neg setrange bad 2 "plate.inp: an *ELSET lists -99999999999"
d=$(seed_pair plate.inp)
printf '*ELSET, ELSET=extra\n1, -99999999999\n' >> "$c/plate.inp"
set_args -o out "$d"
set_names "beyond the integer range"

# ---------------------------------------------------------------- endpart
for kw in "End Part" "END PART" "End Instance" "End Assembly"; do
  name=$(echo "$kw" | tr ' ' '-')
  new_case "endpart.plate.inp.$name" endpart bad 2 "plate.inp: a lone *$kw after the elements"
  d=$(seed_pair plate.inp)
  edit_lines "$c/plate.inp" -v kw="$kw" '{ print } $0 == "   8, 7" { print "*" kw }'
  set_args -o out "$d"
  set_names "*$kw"
done
