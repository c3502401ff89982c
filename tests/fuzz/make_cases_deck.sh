# Families of the fuzz set for what the deck's text may hold and what the
# results can hold of it. Sourced by make_cases.sh after make_cases_files.sh;
# uses its helpers (new_case, set_args, set_names, set_key, add_to_group,
# edit_lines, seed_pair) and variables (seeds, cases, c).
#
# Families and expected exit codes:
#   resnames names the results cannot hold: a body or support set name
#            with '/' or '.', a name (body, pair surface) that is not
#            UTF-8 or holds a control character, a deck file name that is
#            not UTF-8, a body named like the block of another body with
#            Q4 and Q8 elements (NAME_1): refused at the deck's line, so by
#            --check too (before: --check passed and the run stopped when
#            the results were opened, or, for the bytes, ran to exit 0 with
#            an .xmf that is not XML); a UTF-8 name and a Latin-1 title run
#                                                                   2, valid
#   subscript an entry of a list key given twice (velocity = 1.0, 2.0,
#            velocity(1) = 5.0; value(1) twice; a repeat count 2*1.0 then
#            velocity(2); an amplitude time(1) after the whole table): the
#            last one won without a word; a subscript on a key that is not
#            a list (name(1:1) = 'q' changed one letter of the name, title
#            and set too): refused naming both items. Entries set once each,
#            a null entry set later and a table extended by time(3) run
#                                                                   2, valid
#   logical  &output stress = a word that is not true or false (tomato,
#            full, fish, .trueish., yes, 0): refused (Fortran reads any
#            word starting with t or f as a logical, so stress = full gave
#            .false. without a word); T, .t., true, .FALSE. run    2, valid

#   stepfix  a step count above 2^53 from a tiny dt (1e-320) or safety
#            (1e-300), or a huge t_end: the message named only "shorten
#            t_end"; it now names what to change (dt, safety, or t_end and
#            the units behind the stable step)                           2

#   deckend  '&end' closing a group (the older namelist form gfortran reads
#            too) runs like '/' (it was "the group is not closed by '/'");
#            a second '/' or an '&end' after a closed group is refused as
#            closing no group (it was "text outside a group: '/'" or
#            "unknown group '&end'")                               2, valid

#   deckenc  a text in typographic quotes (UTF-8 single and double, their
#            Windows-1252 bytes, a backtick) or opened with ' and closed
#            with a typographic quote, a deck saved as UTF-16: refused,
#            naming the quotes or the encoding (they were "text must be in
#            quotes; write name = '<the typographic quotes kept>'", "not
#            closed on this line" and "text outside a group: '<the line
#            with NUL bytes>'"); a typographic apostrophe inside a quoted
#            title runs                                            2, valid

#   nullval  a key whose value is only null repeat counts (frames = 1*,
#            velocity = 2*, young = 1*): refused as having no value, like
#            'young = ,' (the default was kept without a word, or a
#            required key was "missing" at the group's line); a null entry
#            beside a value (velocity = 1*, 5.0) runs              2, valid

# ---------------------------------------------------------------- resnames
latin1=$(printf '\351')
for v in "slash:a/b:--check" "dot:.:" "slash-run:p/q:"; do
  tag=${v%%:*}; rest=${v#*:}; val=${rest%%:*}; opt=${rest#*:}
  new_case "resnames.body-$tag" resnames bad 2 "plate.nml: &body name = '$val' ${opt:+($opt)}"
  d=$(seed_pair plate.nml)
  set_key "$c/$d" name "'$val'"
  set_args $opt -o out "$d"
  set_names "key 'name'"
done
new_case resnames.body-latin1 resnames bad 2 "plate.nml: &body name with a Latin-1 byte (e9)"
d=$(seed_pair plate.nml)
set_key "$c/$d" name "'pl${latin1}te'"
set_args -o out "$d"
set_names "not UTF-8"
new_case resnames.body-control resnames bad 2 "plate.nml: &body name with a control character (01)"
d=$(seed_pair plate.nml)
set_key "$c/$d" name "'pl$(printf '\001')te'"
set_args -o out "$d"
set_names "control character"
new_case resnames.body-truncated-utf8 resnames bad 2 "plate.nml: &body name ending in the first byte of a 2-byte UTF-8 character"
d=$(seed_pair plate.nml)
set_key "$c/$d" name "'plat$(printf '\303')'"
set_args --check "$d"
set_names "not UTF-8"
new_case resnames.pair-latin1 resnames bad 2 "contact.nml and contact.msh: slave surface named with a Latin-1 byte"
d=$(seed_pair contact.nml)
edit_lines "$c/contact.msh" -v n="\"l${latin1}wer_top\"" '$0 == "1 5 \"lower_top\"" { $0 = "1 5 " n } { print }'
set_key "$c/$d" slave "'l${latin1}wer_top'"
set_args -o out "$d"
set_names "key 'slave'"
for v in "slash:le/ft" "dot:."; do
  tag=${v%%:*}; val=${v#*:}
  new_case "resnames.set-$tag" resnames bad 2 "plate.msh and plate.nml: the fixed set 'left' named '$val'"
  d=$(seed_pair plate.nml)
  edit_lines "$c/plate.msh" -v n="\"$val\"" '$0 == "1 2 \"left\"" { $0 = "1 2 " n } { print }'
  set_key "$c/$d" set "'$val'"
  set_args --check "$d"
  set_names "key 'set'"
done
new_case resnames.deck-latin1 resnames bad 2 "the deck named p<e9>.nml (the .xmf names p<e9>.h5)"
cp "$seeds/plate.nml" "$c/p${latin1}.nml"
cp "$seeds/plate.msh" "$c/"
set_args -o out "p${latin1}.nml"
set_names "file name"
new_case resnames.block-collision resnames bad 2 "body 'a' of a Q4 and a Q8 element (blocks a_1, a_2) beside a body 'a_1'"
cat > "$c/m.msh" <<'MESH'
$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
2 1 "a"
2 2 "b"
$EndPhysicalNames
$Nodes
16
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 2 0 0
6 3 0 0
7 3 1 0
8 2 1 0
9 2.5 0 0
10 3 0.5 0
11 2.5 1 0
12 2 0.5 0
13 4 0 0
14 5 0 0
15 5 1 0
16 4 1 0
$EndNodes
$Elements
3
1 3 2 1 1 1 2 3 4
2 16 2 1 2 5 6 7 8 9 10 11 12
3 3 2 2 3 13 14 15 16
$EndElements
MESH
cat > "$c/d.nml" <<'DECK'
&mesh file = 'm.msh' /
&body name = 'a', young = 1e5, poisson = 0.3, density = 1e-9, velocity = 1.0, 0.0 /
&body name = 'a_1', elset = 'b', young = 1e5, poisson = 0.3, density = 1e-9 /
&time t_end = 1e-5 /
&output frames = 1 /
DECK
set_args --check d.nml
set_names "rename one of the two bodies"
new_case resnames.block-other-name resnames valid 0 "body 'a' of a Q4 and a Q8 element beside a body 'a_3'"
cp "$cases/resnames.block-collision/m.msh" "$c/"
sed "s/'a_1'/'a_3'/" "$cases/resnames.block-collision/d.nml" > "$c/d.nml"
set_args -o out d.nml
new_case resnames.body-utf8 resnames valid 0 "plate.nml: &body name in UTF-8 (plâte)"
d=$(seed_pair plate.nml)
set_key "$c/$d" name "'pl$(printf '\303\242')te'"
set_args -o out "$d"
new_case resnames.title-latin1 resnames valid 0 "plate.nml: &run title with a Latin-1 byte (free text)"
d=$(seed_pair plate.nml)
set_key "$c/$d" title "'caf${latin1}'"
set_args -o out "$d"

# ---------------------------------------------------------------- subscript
# sub_case NAME KIND EXPECT NOTE DECK KEY VALUE [NAMES]
sub_case() {
  new_case "subscript.$1" subscript "$2" "$3" "$4"
  d=$(seed_pair "$5")
  set_key "$c/$d" "$6" "$7"
  set_args -o out "$d"
  [ -n "${8:-}" ] && set_names "$8"
  return 0
}
sub_case velocity-whole-then-1 bad 2 "plate.nml: velocity = 1.0, 2.0, velocity(1) = 5.0" plate.nml velocity "1.0, 2.0, velocity(1) = 5.0" "entry 1 is given twice"
sub_case velocity-2-twice bad 2 "plate.nml: velocity(2) = 1.0, velocity(2) = 3.0" plate.nml velocity "0.0, velocity(2) = 1.0, velocity(2) = 3.0" "entry 2 is given twice"
sub_case velocity-repeat-then-2 bad 2 "plate.nml: velocity = 2*1.0, velocity(2) = 5.0" plate.nml velocity "2*1.0, velocity(2) = 5.0" "entry 2 is given twice"
sub_case body_force-section bad 2 "plate.nml: body_force = 0.0, -1.0e-3, body_force(1:2) = 1.0, 1.0" plate.nml body_force "0.0, -1.0e-3, body_force(1:2) = 1.0, 1.0" "entry 1 is given twice"
sub_case time-whole-then-1 bad 2 "plate.nml: &amplitude time = 0.0, 2.0e-6, time(1) = 1.0e-6" plate.nml time "0.0, 2.0e-6, time(1) = 1.0e-6" "entry 1 is given twice"
new_case subscript.value-1-twice subscript bad 2 "plate_q8.nml: &boundary 'right' value(1) = 1.0e-3, value(1:2) = 2.0e-3, 0.0"
d=$(seed_pair plate_q8.nml)
edit_lines "$c/$d" '{ sub(/value\(1\) = 1.0e-3/, "value(1) = 1.0e-3, value(1:2) = 2.0e-3, 0.0") } { print }'
must_differ "$c/$d"
set_args -o out "$d"
set_names "entry 1 is given twice"
sub_case name-substring bad 2 "plate.nml: &body name = 'plate', name(1:1) = 'q' (made 'qlate')" plate.nml name "'plate', name(1:1) = 'q'" "subscript applies only"
sub_case title-substring bad 2 "plate.nml: &run title(1:5) = 'hello'" plate.nml title "'x', title(1:5) = 'hello'" "subscript applies only"
sub_case set-substring bad 2 "plate.nml: &boundary set = 'left', set(1:1) = 'r' (made 'reft')" plate.nml set "'left', set(1:1) = 'r'" "subscript applies only"
sub_case poisson-subscript bad 2 "plate.nml: &body poisson(1) = 0.3" plate.nml poisson "0.3, poisson(1) = 0.3" "subscript applies only"
sub_case velocity-1-then-2 valid 0 "plate.nml: velocity = 1.0, velocity(2) = 5.0" plate.nml velocity "1.0, velocity(2) = 5.0"
sub_case velocity-null-then-1 valid 0 "plate.nml: velocity = , 1.0, velocity(1) = 5.0" plate.nml velocity ", 1.0, velocity(1) = 5.0"
new_case subscript.time-extended subscript valid 0 "plate.nml: &amplitude time = 0.0, 2.0e-6, time(3) = 3.0e-6, value(3) = 1.0"
d=$(seed_pair plate.nml)
set_key "$c/$d" time "0.0, 2.0e-6, time(3) = 3.0e-6"
set_key "$c/$d" value "0.0, 1.0, value(3) = 1.0"
set_args -o out "$d"

# ---------------------------------------------------------------- logical
for w in tomato full fish .trueish. yes 0; do
  new_case "logical.stress-$w" logical bad 2 "plate.nml: &output stress = $w"
  d=$(seed_pair plate.nml)
  set_key "$c/$d" stress "$w"
  set_args -o out "$d"
  set_names "not a logical value"
done
for w in T .t. true .FALSE.; do
  new_case "logical.stress-valid-$w" logical valid 0 "plate.nml: &output stress = $w"
  d=$(seed_pair plate.nml)
  set_key "$c/$d" stress "$w"
  set_args -o out "$d"
done

# ---------------------------------------------------------------- stepfix
new_case stepfix.dt-1e-320 stepfix bad 2 "plate.nml: &time dt = 1e-320 (a subnormal step)"
d=$(seed_pair plate.nml)
add_to_group "$c/$d" time "dt = 1e-320"
set_args --check "$d"
set_names "give a larger &time dt"
new_case stepfix.safety-1e-300 stepfix bad 2 "plate.nml: &time safety = 1e-300"
d=$(seed_pair plate.nml)
set_key "$c/$d" safety "1e-300"
set_args --check "$d"
set_names "raise &time safety"
new_case stepfix.t_end-1e25 stepfix bad 2 "plate_q8.nml: &time t_end = 1e25 (the default safety)"
d=$(seed_pair plate_q8.nml)
set_key "$c/$d" t_end "1e25"
set_args --check "$d"
set_names "even safety = 1 would not do"

# ---------------------------------------------------------------- deckend
new_case deckend.plate.nml.end-every-group deckend valid 0 "plate.nml: every group closed by &end instead of /"
d=$(seed_pair plate.nml)
edit_lines "$c/$d" '$0 == "/" { $0 = "&end" } { print }'
set_args -o out "$d"
new_case deckend.plate_q8.nml.END-inline deckend valid 0 "plate_q8.nml: one-line groups closed by &END (a comment after it)"
d=$(seed_pair plate_q8.nml)
edit_lines "$c/$d" '/^&[a-z]/ && / \/$/ { sub(/ \/$/, " \&END ! closed") } { print }'
set_args -o out "$d"
new_case deckend.plate.nml.end-after-slash deckend bad 2 "plate.nml: '&end' after the '/' of &run"
d=$(seed_pair plate.nml)
edit_lines "$c/$d" '$0 == "/" && !done { print; $0 = "&end"; done = 1 } { print }'
set_args -o out "$d"
set_names "no group is open"
new_case deckend.plate.nml.slash-twice deckend bad 2 "plate.nml: '//' closing &run"
d=$(seed_pair plate.nml)
edit_lines "$c/$d" '$0 == "/" && !done { $0 = "//"; done = 1 } { print }'
set_args -o out "$d"
set_names "no group is open"

# ---------------------------------------------------------------- deckenc
# enc_case NAME NOTE OPEN CLOSE: plate.nml with name = <OPEN>plate<CLOSE>
enc_case() {
  new_case "deckenc.plate.nml.$1" deckenc bad 2 "plate.nml: &body name = $2"
  d=$(seed_pair plate.nml)
  set_key "$c/$d" name "$3plate$4"
  set_args -o out "$d"
  set_names "typographic"
}
enc_case utf8-single "UTF-8 left and right single quotes" "$(printf '\342\200\230')" "$(printf '\342\200\231')"
enc_case utf8-double "UTF-8 left and right double quotes" "$(printf '\342\200\234')" "$(printf '\342\200\235')"
enc_case cp1252-double "Windows-1252 double quotes (bytes 147, 148)" "$(printf '\223')" "$(printf '\224')"
enc_case backtick "backticks" '`' '`'
enc_case plain-then-utf8 "opened with ' and closed with a UTF-8 right single quote" "'" "$(printf '\342\200\231')"
new_case deckenc.plate.nml.utf16le deckenc bad 2 "plate.nml saved as UTF-16LE with its byte-order mark"
d=$(seed_pair plate.nml)
{ printf '\377\376'; awk '{ n = length($0); for (i = 1; i <= n; i++) printf "%s%c", substr($0, i, 1), 0; printf "\n%c", 0 }' "$seeds/plate.nml"; } > "$c/$d"
set_args -o out "$d"
set_names "UTF-16"
new_case deckenc.plate.nml.utf16be deckenc bad 2 "plate.nml saved as UTF-16BE without a byte-order mark"
d=$(seed_pair plate.nml)
awk '{ n = length($0); for (i = 1; i <= n; i++) printf "%c%s", 0, substr($0, i, 1); printf "%c\n", 0 }' "$seeds/plate.nml" > "$c/$d"
set_args -o out "$d"
set_names "UTF-16"
new_case deckenc.plate.nml.apostrophe-in-title deckenc valid 0 "plate.nml: title = 'Bob<U+2019>s plate' (a typographic apostrophe inside plain quotes)"
d=$(seed_pair plate.nml)
set_key "$c/$d" title "'Bob$(printf '\342\200\231')s plate'"
set_args -o out "$d"

# ---------------------------------------------------------------- nullval
for v in "frames:1*" "young:1*" "velocity:2*" "body_force:1*, 1*" "t_end:1*" "title:1*" "safety:3*"; do
  k=${v%%:*}; val=${v#*:}
  new_case "nullval.plate.nml.$k" nullval bad 2 "plate.nml: $k = $val (null values only)"
  d=$(seed_pair plate.nml)
  set_key "$c/$d" "$k" "$val"
  set_args -o out "$d"
  set_names "has no value"
done
new_case nullval.plate.nml.velocity-null-and-value nullval valid 0 "plate.nml: velocity = 1*, 5.0 (entry 1 keeps its default)"
d=$(seed_pair plate.nml)
set_key "$c/$d" velocity "1*, 5.0"
set_args -o out "$d"
