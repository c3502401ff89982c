# Families of the fuzz set for what is not a plain input file and for
# inputs of hostile size. Sourced by make_cases.sh after make_cases_names.sh;
# uses its helpers (new_case, set_args, set_names, set_key, add_to_group,
# edit_lines, seed_pair) and variables (seeds, cases, c).
#
# Families and expected exit codes:
#   special  a pipe (FIFO, no writer), /dev/zero, /dev/null or a folder
#            given as the deck, the mesh, an *INCLUDE file, the --restart
#            checkpoint or the --verify file: refused before it is opened
#            (a pipe blocked the open for ever, killed by the time limit;
#            /dev/null as mesh was called "included while it is read")    2
#   longtext a deck key, group, value or mesh field of 100000 characters:
#            refused, the message quotes it cut short ("... (N
#            characters)"; the whole text made a 100 kB message line)      2
#   manysets tens of thousands of Abaqus sets and surfaces (quoted and
#            unquoted) or Gmsh physical names: must run within the time
#            limit (set lookups were O(n^2): 60000 *NSET ran for minutes) valid
#   inpkw    Abaqus keywords cut short (*ELEM, *NSE, *SURF: Abaqus takes
#            them, raccord skipped them with their data): refused; blanks
#            inside a keyword (*N SET) are ignored, as in Abaqus     2, valid
#   inpgeom  Abaqus keywords that make or move nodes or elements (*SYSTEM,
#            *NGEN, *NFILL, *NCOPY, *NMAP, *ELGEN, *ELCOPY), *NODE with
#            SYSTEM=C or S, *NSET with ELSET= (no data lines): refused
#            (skipped as "no mesh data", the mesh lacked those nodes or
#            elements or held the nodes elsewhere, exit 0; the *NSET was
#            "set is empty" at the deck); SYSTEM=R reads as x, y   2, valid
#   binary   a binary file (an HDF5 result) given to *INCLUDE: refused at
#            its first NUL byte (its lines were skipped as data of the
#            last keyword, exit 0)                                        2
#   bom      a UTF-8 byte-order mark before the first line of a mesh (as
#            the deck accepts one): read as without (the Gmsh reader did
#            not find $MeshFormat, the Abaqus one saw a data line)    valid
#   plane    nodes off one plane z = const (a Gmsh node or an Abaqus *NODE
#            with another z): refused, naming both nodes (the z was
#            dropped without a word); every node at one z reads as the
#            x-y plane                                                 2, valid
#   clobber  the deck or mesh named like one of the run's files in the
#            output folder (plate.log with -o .): refused before anything
#            is written (the log replaced the deck); a near name runs  2, valid

# ---------------------------------------------------------------- special
# special_case NAME NOTE WHAT: WHAT is mkfifo, zero, null or folder; the
# file in its place is $c/$sp_file, set by the caller before the call.
special_make() {  # special_make KIND PATH
  rm -rf "$2"
  case $1 in
    fifo) mkfifo "$2" ;;
    zero) ln -s /dev/zero "$2" ;;
    null) ln -s /dev/null "$2" ;;
    folder) mkdir "$2" ;;
  esac
}
if command -v mkfifo > /dev/null 2>&1; then
  for kind in fifo zero null folder; do
    new_case "special.deck.$kind" special bad 2 "the deck is a $kind"
    cp "$seeds/plate.msh" "$c/"
    special_make $kind "$c/d.nml"
    set_args -o out d.nml
    new_case "special.mesh.$kind" special bad 2 "plate.nml's mesh plate.msh is a $kind"
    d=$(seed_pair plate.msh)
    special_make $kind "$c/plate.msh"
    set_args -o out "$d"
    set_names "plate.msh"
    new_case "special.include.$kind" special bad 2 "plate.inp includes inc.inp, a $kind"
    d=$(seed_pair plate.inp)
    echo "*INCLUDE, INPUT=inc.inp" >> "$c/plate.inp"
    special_make $kind "$c/inc.inp"
    set_args -o out "$d"
    set_names "inc.inp"
    new_case "special.restart.$kind" special bad 2 "--restart c.checkpoint.h5, a $kind"
    cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
    special_make $kind "$c/c.checkpoint.h5"
    set_args -o out --restart c.checkpoint.h5 plate.nml
    set_names "c.checkpoint.h5"
    new_case "special.verify.$kind" special bad 2 "--verify r.h5, a $kind"
    special_make $kind "$c/r.h5"
    set_args --verify r.h5
    set_names "r.h5"
  done
fi

# ---------------------------------------------------------------- longtext
# A regular file of one line longer than the readers take (10^6 characters).
new_case longtext.deck-endless-line longtext bad 2 "the deck: 1100000 NUL-free characters and no end of line"
cp "$seeds/plate.msh" "$c/"
head -c 1100000 /dev/zero | tr '\000' 'a' > "$c/d.nml"
set_args -o out d.nml
set_names "longer than"
new_case longtext.mesh-endless-line longtext bad 2 "plate.msh: 1100000 characters and no end of line"
d=$(seed_pair plate.msh)
head -c 1100000 /dev/zero | tr '\000' 'a' > "$c/plate.msh"
set_args -o out "$d"
set_names "longer than"
long=$(awk 'BEGIN { for (i = 0; i < 100000; i++) printf "a" }')
new_case longtext.plate.nml.key longtext bad 2 "&run with a key of 100000 characters"
d=$(seed_pair plate.nml)
add_to_group "$c/plate.nml" run "$long = 1"
set_args -o out "$d"
set_names "(100000 characters)"
new_case longtext.plate.nml.value longtext bad 2 "&output frames = 1aaa... (100001 characters)"
d=$(seed_pair plate.nml)
set_key "$c/plate.nml" frames "1$long"
set_args -o out "$d"
set_names "characters)"
new_case longtext.plate.nml.text longtext bad 2 "&run title of 100000 characters"
d=$(seed_pair plate.nml)
set_key "$c/plate.nml" title "'$long'"
set_args -o out "$d"
set_names "(100002 characters)"
new_case longtext.plate.nml.group longtext bad 2 "a group &aaa... of 100000 characters"
d=$(seed_pair plate.nml)
echo "&$long /" >> "$c/plate.nml"
set_args -o out "$d"
set_names "unknown group"
new_case longtext.plate.inp.field longtext bad 2 "a *NODE coordinate of 100000 characters"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" -v L="$long" 'f == 0 && /^\*NODE/ { print; getline; sub(/,[^,]*$/, ", 1" L); f = 1 } { print }'
set_args -o out "$d"
set_names "(100001 characters)"
new_case longtext.plate.inp.label longtext bad 2 "the surface top renamed with 100000 characters, listed in the message"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" -v L="$long" '{ sub(/NAME=top/, "NAME=" L) } { print }'
set_args -o out "$d"
set_names "(100000 characters)"
new_case longtext.plate.msh.physname longtext bad 2 "plate.msh's physical name right (a load surface) renamed with 100000 characters"
d=$(seed_pair plate.msh)
edit_lines "$c/plate.msh" -v L="$long" '$0 == "1 3 \"right\"" { $0 = "1 3 \"" L "\"" } { print }'
set_args -o out "$d"
set_names "(100000 characters)"

# ---------------------------------------------------------------- manysets
new_case manysets.plate.inp.nsets manysets valid 0 "60000 more *NSET in plate.inp"
d=$(seed_pair plate.inp)
awk 'BEGIN { for (i = 0; i < 60000; i++) printf "*NSET, NSET=s%d\n1\n", i }' >> "$c/plate.inp"
set_args -o out "$d"
new_case manysets.plate.inp.quoted manysets valid 0 "30000 pairs of \"s<i>\" and s<i> (two sets each) in plate.inp"
d=$(seed_pair plate.inp)
awk 'BEGIN { for (i = 0; i < 30000; i++) printf "*NSET, NSET=\"s%d\"\n1\n*NSET, NSET=s%d\n2\n", i, i }' >> "$c/plate.inp"
set_args -o out "$d"
new_case manysets.plate.inp.surfaces manysets valid 0 "30000 more *SURFACE in plate.inp"
d=$(seed_pair plate.inp)
awk 'BEGIN { for (i = 0; i < 30000; i++) printf "*SURFACE, NAME=s%d\n1, S1\n", i }' >> "$c/plate.inp"
set_args -o out "$d"
new_case manysets.plate_q8.msh.physnames manysets valid 0 "60000 more (unused) physical names in plate_q8.msh"
d=$(seed_pair plate_q8.msh)
edit_lines "$c/plate_q8.msh" '/^\$PhysicalNames/ { print; getline; print $1 + 60000; for (i = 0; i < 60000; i++) printf "1 %d \"x%d\"\n", 1000 + i, i; next } { print }'
set_args -o out "$d"

# ---------------------------------------------------------------- clobber
# An input with the name of one of the run's output files, in the output
# folder: refused before anything is written (the deck plate.log run with
# -o . was replaced by the run's log).
new_case clobber.deck-log clobber bad 2 "the deck plate.log run with -o ."
cp "$seeds/plate.msh" "$c/"
cp "$seeds/plate.nml" "$c/plate.log"
set_args -o . plate.log
set_names "would be overwritten"
for m in plate.lock plate.scene.nml plate.h5.part plate.contact2.incomplete.txt; do
  new_case "clobber.mesh-$m" clobber bad 2 "plate.nml's mesh named $m, run with -o ."
  d=$(seed_pair plate.nml)
  mv "$c/plate.msh" "$c/$m"
  set_key "$c/plate.nml" file "'$m'"
  set_key "$c/plate.nml" format "'gmsh'"
  set_args -o . "$d"
  set_names "would be overwritten"
done
new_case clobber.mesh-subfolder clobber bad 2 "the mesh out/../out/plate.lock, run with -o ./out/"
d=$(seed_pair plate.nml)
mkdir "$c/out"
mv "$c/plate.msh" "$c/out/plate.lock"
set_key "$c/plate.nml" file "'out/../out/plate.lock'"
set_key "$c/plate.nml" format "'gmsh'"
set_args -o ./out/ "$d"
set_names "would be overwritten"
new_case clobber.mesh-other-name clobber valid 0 "the mesh plate.history.msh (no output has that name), run with -o ."
d=$(seed_pair plate.nml)
mv "$c/plate.msh" "$c/plate.history.msh"
set_key "$c/plate.nml" file "'plate.history.msh'"
set_args -o . "$d"

# ---------------------------------------------------------------- inpkw
for k in "ELEMENT, TYPE=CPS4, ELSET=plate:ELEM:ELEMENT" "NSET, NSET=left:NSE:NSET" "SURFACE, NAME=top:SURF:SURFACE"; do
  full=${k%%:*}; rest=${k#*:}; short=${rest%%:*}; word=${rest#*:}
  new_case "inpkw.plate.inp.$short" inpkw bad 2 "plate.inp: *$full written *$short${full#"$word"}"
  d=$(seed_pair plate.inp)
  edit_lines "$c/plate.inp" -v a="*$full" -v b="*$short${full#"$word"}" 'index($0, a) == 1 && !done { $0 = b substr($0, length(a) + 1); done = 1 } { print }'
  set_args -o out "$d"
  set_names "write *$word"
done
new_case inpkw.plate.inp.blank-inside inpkw valid 0 "plate.inp: *NSET written *N SET (blanks ignored)"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '/^\*NSET, NSET=left/ { sub(/^\*NSET/, "*N SET") } { print }'
set_args -o out "$d"

# ---------------------------------------------------------------- inpgeom
# inpgeom_case NAME NOTE NAMES AWK: plate.inp edited by AWK (edit_lines)
inpgeom_case() {
  new_case "inpgeom.plate.inp.$1" inpgeom bad 2 "plate.inp: $2"
  d=$(seed_pair plate.inp)
  edit_lines "$c/plate.inp" "$4"
  set_args -o out "$d"
  set_names "$3"
}
inpgeom_case system-c "*NODE, NSET=ALL, SYSTEM=C" "SYSTEM=C" '/^\*NODE, NSET=ALL/ { $0 = $0 ", SYSTEM=C" } { print }'
inpgeom_case system-s "*NODE, SYSTEM=s (lower case)" "SYSTEM=s" '/^\*NODE, NSET=ALL/ { $0 = "*NODE, SYSTEM=s" } { print }'
inpgeom_case system-keyword "*SYSTEM 10., 0., 0. before *NODE" "*SYSTEM places the nodes" '/^\*NODE, NSET=ALL/ { print "*SYSTEM"; print "10., 0., 0." } { print }'
for k in NGEN NFILL NCOPY NMAP ELGEN ELCOPY; do
  inpgeom_case "$(echo $k | tr A-Z a-z)" "*$k before *NSET, NSET=left (its data skipped)" "*$k" "/^\\*NSET, NSET=left/ { print \"*$k, NSET=gen\"; print \"1, 4, 1\" } { print }"
done
inpgeom_case nset-elset "*NSET, NSET=left, ELSET=plate (the nodes of an element set)" "is not read" '/^\*NSET, NSET=left/ { $0 = "*NSET, NSET=left, ELSET=plate" } $0 == "1, 5" { next } { print }'
new_case inpgeom.plate.inp.system-r inpgeom valid 0 "plate.inp: *NODE, NSET=ALL, SYSTEM=R (Cartesian)"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '/^\*NODE, NSET=ALL/ { $0 = $0 ", SYSTEM=R" } { print }'
set_args -o out "$d"

# ---------------------------------------------------------------- plane
new_case plane.plate.msh.one-node-z plane bad 2 "plate.msh with one node at z = 0.5"
d=$(seed_pair plate.msh)
edit_lines "$c/plate.msh" '/^\$Nodes/ { on = 1 } /^\$EndNodes/ { on = 0 } on && NF == 3 && !done && $1 != 0 { $3 = "0.5"; done = 1 } { print }'
set_args -o out "$d"
set_names "not in one plane"
new_case plane.plate.inp.one-node-z plane bad 2 "plate.inp with *NODE 2 at z = -1e-3"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '$0 == "2, 2., 0." { $0 = "2, 2., 0., -1e-3" } { print }'
set_args -o out "$d"
set_names "not in one plane"
new_case plane.plate.msh.constant-z plane valid 0 "plate.msh with every node at z = 5"
d=$(seed_pair plate.msh)
edit_lines "$c/plate.msh" '/^\$Nodes/ { on = 1 } /^\$EndNodes/ { on = 0 } on && NF == 3 { $3 = "5" } { print }'
set_args -o out "$d"
new_case plane.plate.inp.constant-z plane valid 0 "plate.inp with every node at z = 5"
d=$(seed_pair plate.inp)
edit_lines "$c/plate.inp" '/^\*/ { on = ($0 ~ /^\*NODE/) } on && !/^\*/ { $0 = $0 ", 5." } { print }'
set_args -o out "$d"

# ---------------------------------------------------------------- bom
for m in plate.msh plate.inp plate_q8.msh contact.msh; do
  new_case "bom.$m" bom valid 0 "$m with a UTF-8 byte-order mark"
  d=$(seed_pair "$m")
  { printf '\357\273\277'; cat "$seeds/$m"; } > "$c/$m"
  set_args -o out "$d"
done

# ---------------------------------------------------------------- binary
new_case binary.plate.inp.include-h5 binary bad 2 "plate.inp includes x.inp, bytes of an HDF5 file"
d=$(seed_pair plate.inp)
echo "*INCLUDE, INPUT=x.inp" >> "$c/plate.inp"
{ printf '\211HDF\r\n\032\n\000\000\000\000'; head -c 300 /dev/zero; printf 'tail\n'; } > "$c/x.inp"
set_args -o out "$d"
set_names "NUL byte"
new_case binary.plate.msh.nul-in-node binary bad 2 "plate.msh with a NUL byte in a node line"
d=$(seed_pair plate.msh)
l=$(awk '$0 == "10 0 0" { print NR; exit }' "$seeds/plate.msh")
{ head -n "$((l - 1))" "$seeds/plate.msh"; printf '10 0\000 0\n'; tail -n "+$((l + 1))" "$seeds/plate.msh"; } > "$c/plate.msh"
set_args -o out "$d"
set_names "NUL byte"
