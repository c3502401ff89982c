#!/bin/sh
# Generate the bad-input fuzz cases of raccord from the good seeds.
#
#   sh make_cases.sh SEED_DIR CASES_DIR
#
# SEED_DIR   tests/fuzz/seeds: four good scenes and their meshes
#            plate.nml     + plate.msh     (one body, Gmsh 4.1, Q4)
#            plate_q8.nml  + plate_q8.msh  (one body, Gmsh 2.2, Q8)
#            plate_inp.nml + plate.inp     (one body, Abaqus .inp, Q4)
#            contact.nml   + contact.msh   (two bodies, a contact pair, Gmsh 4.1)
# CASES_DIR  emptied first; one folder per case, named <family>.<detail>
#
# Every case folder holds the deck and mesh it runs on and a file case.txt:
#   family=<family>          the family (see below)
#   kind=bad|maybe|valid     bad: the input is wrong by construction and must
#                            be refused; maybe: a random mutation that may
#                            happen to be a valid input (exit 0 with complete
#                            results is then accepted and counted apart);
#                            valid: a mutation known to change nothing that
#                            matters (a comment), which must run through
#   expect=<codes>           allowed non-zero exit codes, e.g. "2" or "2 3"
#   args=<arguments>         raccord's arguments, run from the case folder
#   setup=<name>             optional: a special run (disk_full, disk_full_now,
#                            not_writable, locked, damage)
#   env=<VAR=value>          optional: one environment variable for the run
#   damage=<suffix> <r> <mode>, deck=<deck>   with setup=damage (see
#                            make_cases_hostile.sh)
#   note=<text>              what was done to the seed
#
# The cases are the same on every run and every machine: the positions come
# from a Park-Miller generator written in awk (exact in double precision),
# with a fixed seed per family and file; nothing depends on the awk's own
# rand(), the date or the locale.
#
# Families and expected exit codes (doc/user-guide.md, section 3):
#   trunc     truncation of a deck or mesh at random byte offsets        2
#   flip      one bit flipped at a random byte                            2 or 3 (maybe)
#   subst     one character replaced by a syntax character                2 or 3 (maybe)
#   count     wrong counts in Gmsh section headers                       2
#   nonnum    a numeric field replaced by text, nan, inf, 1e999 ...      2
#   lines     a random line deleted or duplicated                        2 (maybe)
#   phys      physically bad values (young <= 0, poisson >= 0.5 ...)     2
#   sets      missing or empty sets and surfaces                         2
#   chain     a contact surface that is not one chain of one body        2
#   invert    inverted or degenerate elements (node ids swapped)         2
#   meshfile  a mesh file that does not exist, is a folder, wrong format 2
#   outdir    an output folder that cannot be created or written         4
#   diskfull  the output folder fills up during the run (tmpfs)          4
#   cmdline   bad command lines                                          1
#   and the families of make_cases_hostile.sh (sizes, overflow, paths,
#   damage, meshmix, threads, validdeck, messages) and of
#   make_cases_features.sh (axi, finite, plastic, pairs, loops, mscale,
#   abaqus, gmshphys, restart, fmutate), described there, and of
#   make_cases_names.sh (names, bounds), make_cases_files.sh (special,
#   longtext, manysets, inpgeom, ...), make_cases_deck.sh
#   (resnames, subscript, logical, stepfix, deckend, deckenc, nullval) and
#   make_cases_tags.sh (ids, entities, slowtext) and make_cases_rules.sh
#   (thickness, brokenlink, setrange, endpart) and make_cases_text.sh
#   (control, abqparam, extent, h5input, gmshsec).
set -u
LC_ALL=C
export LC_ALL

seeds=$1
cases=$2

rm -rf "$cases"
mkdir -p "$cases" || { echo "make_cases: cannot create $cases" >&2; exit 1; }

ncase=0

# new_case NAME FAMILY KIND EXPECT NOTE: create the folder, set $c, write case.txt.
# The args default to "-o out <deck>" and are set by the caller with set_args.
new_case() {
  c=$cases/$1
  if [ -d "$c" ]; then echo "make_cases: duplicate case $1" >&2; exit 1; fi
  mkdir -p "$c"
  printf 'family=%s\nkind=%s\nexpect=%s\nnote=%s\n' "$2" "$3" "$4" "$5" > "$c/case.txt"
  ncase=$((ncase + 1))
}
set_args() { printf 'args=%s\n' "$*" >> "$c/case.txt"; }
set_setup() { printf 'setup=%s\n' "$1" >> "$c/case.txt"; }

# mesh_of DECK: the mesh file a seed deck names.
mesh_of() {
  case $1 in
    plate.nml) echo plate.msh ;;
    plate_q8.nml) echo plate_q8.msh ;;
    plate_inp.nml) echo plate.inp ;;
    contact.nml) echo contact.msh ;;
  esac
}
# deck_of MESH: the seed deck that reads a mesh.
deck_of() {
  case $1 in
    plate.msh) echo plate.nml ;;
    plate_q8.msh) echo plate_q8.nml ;;
    plate.inp) echo plate_inp.nml ;;
    contact.msh) echo contact.nml ;;
  esac
}
is_deck() { case $1 in *.nml) return 0 ;; *) return 1 ;; esac; }

# seed_pair FILE: copy the seed deck and mesh that go with FILE into $c; print the deck.
seed_pair() {
  if is_deck "$1"; then d=$1; else d=$(deck_of "$1"); fi
  cp "$seeds/$d" "$seeds/$(mesh_of "$d")" "$c/"
  echo "$d"
}

# rng SEED N MAX: N pseudo-random integers in [0, MAX), one a line.
rng() {
  awk -v s="$1" -v n="$2" -v m="$3" 'BEGIN {
    x = s % 2147483647; if (x <= 0) x += 2147483646
    for (i = 0; i < 5; i++) x = (16807 * x) % 2147483647
    for (i = 0; i < n; i++) { x = (16807 * x) % 2147483647; print int(x / 2147483647 * m) }
  }'
}

fsize() { wc -c < "$1" | tr -d ' '; }
nlines() { awk 'END { print NR }' "$1"; }
byte_at() { od -An -tu1 -j "$2" -N1 "$1" | tr -d ' \n'; }

# put_byte FILE POS BYTE: FILE with the byte at POS (0-based) replaced by BYTE (0..255), on stdout.
put_byte() {
  head -c "$2" "$1"
  # shellcheck disable=SC2059
  printf "\\$(printf %03o "$3")"
  tail -c +"$(($2 + 2))" "$1"
}

# deck_code FILE: the deck without comments, blank lines and trailing blanks
# (quotes respected): two decks with the same code are the same scene.
deck_code() {
  awk '{
    out = ""; q = ""
    for (i = 1; i <= length($0); i++) {
      ch = substr($0, i, 1)
      if (q != "") { if (ch == q) q = ""; out = out ch; continue }
      if (ch == "!") break
      if (ch == "\047" || ch == "\"") q = ch
      out = out ch
    }
    sub(/[ \t\r]+$/, "", out)
    if (out != "") print out
  }' "$1"
}

# deck_broken FILE: exit 0 when the deck is certainly bad: it ends inside a
# group or a quoted text, or lacks a complete &mesh, &body or &time group.
deck_broken() {
  deck_code "$1" | awk '
    {
      line = $0
      for (i = 1; i <= length(line); i++) {
        ch = substr(line, i, 1)
        if (q != "") { if (ch == q) q = ""; continue }
        if (ch == "\047" || ch == "\"") { q = ch; continue }
        if (ch == "&" && !open) {
          name = tolower(substr(line, i + 1)); sub(/[^a-z_].*/, "", name)
          open = 1; cur = name; continue
        }
        if (ch == "/" && open) { open = 0; done[cur] = 1 }
      }
    }
    END {
      if (open || q != "") exit 0
      if (!done["mesh"] || !done["body"] || !done["time"]) exit 0
      exit 1
    }'
}

# classify_deck ORIG MUTANT: "valid" when only comments or blank lines
# changed, "bad" when certainly broken, else "maybe".
classify_deck() {
  if [ "$(deck_code "$1")" = "$(deck_code "$2")" ]; then echo valid
  elif deck_broken "$2"; then echo bad
  else echo maybe; fi
}

# set_key DECK KEY VALUE [N]: replace the value of KEY (the N-th occurrence
# in the deck, default 1) by VALUE, in place. The value runs to the next
# comma that starts another key, or to the end of the line.
set_key() {
  awk -v key="$2" -v val="$3" -v nth="${4:-1}" '
    {
      line = $0
      if (!done && match(line, "(^|[ ,&])" key "[ ]*=")) {
        seen++
        if (seen == nth) {
          pre = substr(line, 1, RSTART + RLENGTH - 1)
          rest = substr(line, RSTART + RLENGTH)
          # the next ", key =" ends the value, or the "/" that closes a
          # one-line group, or a comment
          if (match(rest, ",[ ]*[a-z_]+(\\([0-9]\\))?[ ]*=")) tail = substr(rest, RSTART)
          else if (match(rest, "[ ]*/[ ]*(!.*)?$")) tail = " " substr(rest, RSTART)
          else if (match(rest, "[ ]*!")) tail = " " substr(rest, RSTART)
          else tail = ""
          line = pre " " val tail
          done = 1
        }
      }
      print line
    }
    END { if (!done) exit 1 }' "$1" > "$1.tmp" && mv "$1.tmp" "$1" || {
      echo "make_cases: key $2 not found in $1" >&2; rm -f "$1.tmp"; exit 1; }
  must_differ "$1"
}

# add_to_group DECK GROUP TEXT [N]: add TEXT to the N-th &GROUP (default
# 1): on the next line, or before the "/" of a one-line group.
add_to_group() {
  awk -v g="&$2" -v text="$3" -v nth="${4:-1}" '
    tolower($1) == g && ++seen == nth {
      if ($0 ~ /\/[ \t]*$/) { sub(/\/[ \t]*$/, ", " text " /"); print; next }
      print; print "  " text; next
    }
    { print }' "$1" > "$1.tmp" && mv "$1.tmp" "$1"
  must_differ "$1"
}

# must_differ FILE: stop when FILE (in a case folder) is still the seed of
# the same name: the edit that should have made the case did not apply.
must_differ() {
  if [ -f "$seeds/$(basename "$1")" ] && cmp -s "$1" "$seeds/$(basename "$1")"; then
    echo "make_cases: case $c: the edit of $(basename "$1") changed nothing" >&2
    exit 1
  fi
}
# set_names TEXT: stderr must name TEXT (case-insensitive) in its ERROR line.
set_names() { printf 'names=%s\n' "$1" >> "$c/case.txt"; }

# edit_lines FILE AWK-PROGRAM: rewrite FILE in place with an awk program.
edit_lines() {
  _ef=$1; shift
  awk "$@" "$_ef" > "$_ef.tmp" && mv "$_ef.tmp" "$_ef"
  must_differ "$_ef"
}

all_files="plate.nml plate.msh plate_q8.nml plate_q8.msh plate_inp.nml plate.inp contact.nml contact.msh"

# ---------------------------------------------------------------- trunc
# Gmsh files cut anywhere before the last byte of "$EndElements" are bad (a
# section without its end); decks are classified by deck_broken; an .inp
# cut between lines can be valid, so .inp cuts are "maybe".
fam_seed=100
for f in $all_files; do
  fam_seed=$((fam_seed + 1))
  size=$(fsize "$seeds/$f")
  for off in $(rng "$fam_seed" 12 "$((size - 1))" | sort -n -u); do
    new_case "trunc.$f.$off" trunc bad 2 "$f cut after $off of $size bytes"
    d=$(seed_pair "$f")
    head -c "$off" "$seeds/$f" > "$c/$f"
    if is_deck "$f"; then
      kind=$(classify_deck "$seeds/$f" "$c/$f")
    else
      case $f in *.inp) kind=maybe ;; *) kind=bad ;; esac
    fi
    sed -i "s/^kind=.*/kind=$kind/" "$c/case.txt"
    set_args -o out "$d"
  done
done

# ---------------------------------------------------------------- flip / subst
# flip: XOR one byte with a single bit; subst: replace it by a character
# that means something to a reader (quote, slash, comma, '&', '!', '=',
# '$', '*', newline, tab, NUL, a letter, a sign ...). Deck mutants that only
# touch comments are "valid"; other mutants are "maybe" (a flipped digit
# is still a number) unless the deck is certainly broken.
subst_chars="39 34 47 44 38 33 61 36 42 10 9 0 120 45 43 46 101 32 255 59 40"
nsubst=$(echo "$subst_chars" | awk '{ print NF }')
fam_seed=200
for f in $all_files; do
  fam_seed=$((fam_seed + 1))
  size=$(fsize "$seeds/$f")
  i=0
  rng "$fam_seed" 16 "$((size * 8))" > "$cases/.r1"
  rng "$((fam_seed + 50))" 16 "$nsubst" > "$cases/.r2"
  paste "$cases/.r1" "$cases/.r2" > "$cases/.r"
  while read -r r1 r2; do
    i=$((i + 1))
    pos=$((r1 / 8)); bit=$((r1 % 8))
    old=$(byte_at "$seeds/$f" "$pos")
    if [ "$i" -le 8 ]; then
      fam=flip; new=$((old ^ (1 << bit)))
      note="$f byte $pos: $old xor $((1 << bit)) = $new"
    else
      fam=subst; new=$(echo "$subst_chars" | awk -v k="$((r2 + 1))" '{ print $k }')
      [ "$new" -eq "$old" ] && new=120
      note="$f byte $pos: $old replaced by $new"
    fi
    name="$fam.$f.$pos"
    [ -d "$cases/$name" ] && name="$name.$i"
    new_case "$name" "$fam" maybe "2 3" "$note"
    d=$(seed_pair "$f")
    put_byte "$seeds/$f" "$pos" "$new" > "$c/$f"
    if is_deck "$f"; then
      kind=$(classify_deck "$seeds/$f" "$c/$f")
      sed -i "s/^kind=.*/kind=$kind/" "$c/case.txt"
    fi
    set_args -o out "$d"
  done < "$cases/.r"
done
rm -f "$cases/.r" "$cases/.r1" "$cases/.r2"

# ---------------------------------------------------------------- count
# count_case MESH NAME LINE-MATCH FIELD DELTA NOTE: add DELTA to field FIELD
# of the first line after the line LINE-MATCH (a section header line).
count_case() {
  new_case "count.$1.$2" count bad 2 "$6"
  d=$(seed_pair "$1")
  edit_lines "$c/$1" -v hdr="$3" -v fld="$4" -v dl="$5" '
    hit == 1 { $fld = $fld + dl; hit = 2 }
    $0 == hdr && !hit { hit = 1 }
    { print }'
  set_args -o out "$d"
}
for m in plate.msh contact.msh; do
  count_case "$m" physnames-plus1 '$PhysicalNames' 1 1 "$m: \$PhysicalNames count + 1"
  count_case "$m" physnames-minus1 '$PhysicalNames' 1 -1 "$m: \$PhysicalNames count - 1"
  count_case "$m" entities-points-plus1 '$Entities' 1 1 "$m: \$Entities number of points + 1"
  count_case "$m" entities-curves-minus1 '$Entities' 2 -1 "$m: \$Entities number of curves - 1"
  count_case "$m" entities-surfaces-plus1 '$Entities' 3 1 "$m: \$Entities number of surfaces + 1"
  count_case "$m" nodes-blocks-plus1 '$Nodes' 1 1 "$m: \$Nodes numEntityBlocks + 1"
  count_case "$m" nodes-blocks-minus1 '$Nodes' 1 -1 "$m: \$Nodes numEntityBlocks - 1"
  count_case "$m" nodes-total-plus1 '$Nodes' 2 1 "$m: \$Nodes numNodes + 1"
  count_case "$m" nodes-total-minus1 '$Nodes' 2 -1 "$m: \$Nodes numNodes - 1"
  count_case "$m" elements-blocks-plus1 '$Elements' 1 1 "$m: \$Elements numEntityBlocks + 1"
  count_case "$m" elements-blocks-minus1 '$Elements' 1 -1 "$m: \$Elements numEntityBlocks - 1"
  count_case "$m" elements-total-plus1 '$Elements' 2 1 "$m: \$Elements numElements + 1"
  count_case "$m" elements-total-minus1 '$Elements' 2 -1 "$m: \$Elements numElements - 1"
done
count_case plate_q8.msh physnames-plus1 '$PhysicalNames' 1 1 'plate_q8.msh: $PhysicalNames count + 1'
count_case plate_q8.msh physnames-minus1 '$PhysicalNames' 1 -1 'plate_q8.msh: $PhysicalNames count - 1'
count_case plate_q8.msh nodes-plus1 '$Nodes' 1 1 'plate_q8.msh (2.2): $Nodes count + 1'
count_case plate_q8.msh nodes-minus1 '$Nodes' 1 -1 'plate_q8.msh (2.2): $Nodes count - 1'
count_case plate_q8.msh nodes-zero '$Nodes' 1 -28 'plate_q8.msh (2.2): $Nodes count 0'
count_case plate_q8.msh elements-plus1 '$Elements' 1 1 'plate_q8.msh (2.2): $Elements count + 1'
count_case plate_q8.msh elements-minus1 '$Elements' 1 -1 'plate_q8.msh (2.2): $Elements count - 1'
count_case plate_q8.msh elements-double '$Elements' 1 18 'plate_q8.msh (2.2): $Elements count doubled'
# An element line of 2.2 that claims one tag more than it gives (its node
# list then starts one field late and is one node short).
new_case count.plate_q8.msh.element-ntags-plus1 count bad 2 'plate_q8.msh (2.2): element 14 says 3 tags for its 2'
d=$(seed_pair plate_q8.msh)
edit_lines "$c/plate_q8.msh" '$1 == 14 && $2 == 16 { $3 = $3 + 1 } { print }'
set_args -o out "$d"
# The 4.1 entity blocks: the number of nodes / elements of one block.
# plate.msh: node block "1 1 0 4" (curve 1, 4 nodes) and element block "2 1 3 5".
for delta in 1 -1; do
  new_case "count.plate.msh.node-block$delta" count bad 2 "plate.msh: nodes in the block of curve 1 $delta"
  d=$(seed_pair plate.msh)
  edit_lines "$c/plate.msh" -v dl="$delta" '$0 == "1 1 0 4" && !hit { $4 = $4 + dl; hit = 1 } { print }'
  set_args -o out "$d"
  new_case "count.plate.msh.elem-block$delta" count bad 2 "plate.msh: elements in the surface block $delta"
  d=$(seed_pair plate.msh)
  edit_lines "$c/plate.msh" -v dl="$delta" '$0 == "2 1 3 5" && !hit { $4 = $4 + dl; hit = 1 } { print }'
  set_args -o out "$d"
done
# An entity's physical-tag count one too many (4.1 $Entities, surface 1).
new_case count.plate.msh.entity-physicals count bad 2 'plate.msh: surface entity 1 lists 2 physical tags but gives 1'
d=$(seed_pair plate.msh)
edit_lines "$c/plate.msh" '$0 ~ /^1 0 0 0 10 2 0 1 1 / && !hit { $8 = 2; hit = 1 } { print }'
set_args -o out "$d"

# ---------------------------------------------------------------- nonnum
# nonnum_mesh MESH NAME AWK-CONDITION FIELD TEXT: field FIELD of the first
# line matching the condition becomes TEXT.
nonnum_mesh() {
  new_case "nonnum.$1.$2" nonnum bad 2 "$1: field $4 of the first line matching $3 set to '$5'"
  d=$(seed_pair "$1")
  edit_lines "$c/$1" -v fld="$4" -v txt="$5" "($3) && !hit { \$fld = txt; hit = 1 } { print }"
  set_args -o out "$d"
}
for t in abc 1.0.0 nan inf 1e999 0x10 --1 '1,5'; do
  tn=$(echo "$t" | tr ',' '_')
  nonnum_mesh plate.msh "x-$tn" '$0 == "3.999999999991017 0 0"' 1 "$t"
done
for t in abc 2.5 -3 99; do
  nonnum_mesh plate.msh "elem-node-$t" '$0 == "15 5 6 11 12 "' 3 "$t"
done
nonnum_mesh plate.msh nodes-count-abc '$0 == "9 12 1 12"' 2 abc
nonnum_mesh plate.msh elements-count-1.5 '$0 == "6 18 1 18"' 2 1.5
nonnum_mesh plate.msh format-version '$0 == "4.1 0 8"' 1 four
nonnum_mesh plate.msh format-filetype '$0 == "4.1 0 8"' 2 x
nonnum_mesh plate.msh entity-tag '$0 ~ /^1 0 0 0 10 2 0 1 1 /' 9 one
nonnum_mesh plate.msh physname-dim '$0 == "2 1 \"plate\""' 1 two
for t in abc nan 1e999; do
  nonnum_mesh plate_q8.msh "y-$t" '$1 == 14 && NF == 4' 3 "$t"
done
nonnum_mesh plate_q8.msh elem-type '$1 == 15 && NF == 13' 2 quad
nonnum_mesh plate_q8.msh elem-node '$1 == 15 && NF == 13' 13 x7
nonnum_mesh plate_q8.msh node-id '$1 == 7 && NF == 4' 1 7a
nonnum_mesh contact.msh node-x-inf '$0 == "0.4999999999986921 -0.5 0"' 1 inf
nonnum_mesh contact.msh node-y-text '$0 == "0.4999999999986921 -0.5 0"' 2 y
# Abaqus: a comma-separated field.
nonnum_inp() {
  new_case "nonnum.plate.inp.$1" nonnum bad 2 "plate.inp: $2"
  d=$(seed_pair plate.inp)
  edit_lines "$c/plate.inp" "$3"
  set_args -o out "$d"
}
nonnum_inp node-x-abc "node 3 x = abc" '$0 == "3, 4., 0." { $0 = "3, abc, 0." } { print }'
nonnum_inp node-y-nan "node 6 y = nan" '$0 == "6, 2., 2." { $0 = "6, 2., nan" } { print }'
nonnum_inp node-y-missing "node 6 without y" '$0 == "6, 2., 2." { $0 = "6, 2." } { print }'
nonnum_inp node-id-text "node id 'six'" '$0 == "6, 2., 2." { $0 = "six, 2., 2." } { print }'
nonnum_inp elem-node-text "element 2 node 'x'" '$0 == "2, 2, 3, 7, 6" { $0 = "2, 2, 3, x, 6" } { print }'
nonnum_inp elem-node-real "element 2 node 3.5" '$0 == "2, 2, 3, 7, 6" { $0 = "2, 2, 3, 3.5, 6" } { print }'
nonnum_inp elem-short "element 2 with 3 nodes" '$0 == "2, 2, 3, 7, 6" { $0 = "2, 2, 3, 7" } { print }'
nonnum_inp generate-text "GENERATE step 'one'" '$0 == "1, 3, 1" { $0 = "1, 3, one" } { print }'
nonnum_inp face-S5 "surface face S5" '$0 == "3, S2" { $0 = "3, S5" } { print }'
nonnum_inp face-missing "surface line without face" '$0 == "3, S2" { $0 = "3" } { print }'
# Decks: a value of the wrong type (added to GROUP when the seed lacks the key).
nonnum_deck() {  # nonnum_deck DECK KEY VALUE TAG [GROUP]
  new_case "nonnum.$1.$2-$4" nonnum bad 2 "$1: $2 = $3"
  cp "$seeds/$1" "$seeds/$(mesh_of "$1")" "$c/"
  if grep -q "[ ,&]$2 *=" "$c/$1"; then set_key "$c/$1" "$2" "$3"
  else add_to_group "$c/$1" "${5:-}" "$2 = $3"; fi
  set_args -o out "$1"
  set_names "$2"
}
nonnum_deck plate.nml young abc abc
nonnum_deck plate.nml young "'200000'" quoted
nonnum_deck plate.nml young nan nan
nonnum_deck plate.nml young inf inf
nonnum_deck plate.nml young -inf minf
nonnum_deck plate.nml young 1e999 1e999
nonnum_deck plate.nml poisson 0.3.1 dots
nonnum_deck plate.nml density '7.8e-9x' suffix
nonnum_deck plate.nml t_end "" empty
nonnum_deck plate.nml frames 2.5 real
nonnum_deck plate.nml frames two text
nonnum_deck plate.nml history_every 99999999999 big
nonnum_deck plate.nml stress maybe word
nonnum_deck plate.nml hypothesis plane_stress unquoted
nonnum_deck plate.nml hypothesis "'plane_stess'" typo
nonnum_deck plate.nml velocity "0.0, 0.0, 0.0" three
nonnum_deck plate.nml body_force "'x', 0.0" text
nonnum_deck plate.nml time "0.0, abc" text
nonnum_deck plate.nml scale "1.0d" exp
nonnum_deck plate_q8.nml components "'z'" z
nonnum_deck plate_q8.nml type "'clamped'" word
nonnum_deck plate_inp.nml format "'nastran'" word
nonnum_deck contact.nml friction .true. logical
nonnum_deck contact.nml method "'penalty'" word
nonnum_deck contact.nml multiplier "'P2'" word
nonnum_deck contact.nml max_iterations 1.5 real contact_pair

# ---------------------------------------------------------------- lines
# One line deleted or duplicated at random. Mesh mutants are "maybe" (a
# duplicated Abaqus set line is harmless), deck mutants are classified.
fam_seed=300
for f in $all_files; do
  fam_seed=$((fam_seed + 1))
  n=$(nlines "$seeds/$f")
  k=0
  for l in $(rng "$fam_seed" 10 "$n" | awk '!seen[$0]++'); do
    k=$((k + 1))
    l=$((l + 1))
    if [ $((k % 2)) -eq 1 ]; then op=del; else op=dup; fi
    new_case "lines.$f.$op$l" lines maybe 2 "$f: line $l ${op}eted"
    [ "$op" = dup ] && sed -i 's/dupeted/duplicated/' "$c/case.txt"
    d=$(seed_pair "$f")
    if [ "$op" = del ]; then edit_lines "$c/$f" -v l="$l" 'NR != l'
    else edit_lines "$c/$f" -v l="$l" '{ print } NR == l'; fi
    if is_deck "$f"; then
      kind=$(classify_deck "$seeds/$f" "$c/$f")
      sed -i "s/^kind=.*/kind=$kind/" "$c/case.txt"
    fi
    set_args -o out "$d"
  done
done

# ---------------------------------------------------------------- phys
# phys DECK KEY VALUE [N] [GROUP]: KEY set to VALUE (the N-th occurrence);
# when the deck lacks the key, it is added to the N-th &GROUP.
phys() {
  tag=$(printf '%s' "$3" | tr -c 'A-Za-z0-9.+-' '_')
  new_case "phys.$1.$2${4:-}=$tag" phys bad 2 "$1: $2 = $3 (occurrence ${4:-1})"
  cp "$seeds/$1" "$seeds/$(mesh_of "$1")" "$c/"
  if grep -q "[ ,&]$2 *=" "$c/$1"; then set_key "$c/$1" "$2" "$3" "${4:-1}"
  else add_to_group "$c/$1" "${5:-}" "$2 = $3" "${4:-1}"; fi
  set_args -o out "$1"
  set_names "$2"
}
for deck in plate.nml plate_q8.nml plate_inp.nml contact.nml; do
  for v in 0.0 -1.0 -200000.0; do phys "$deck" young "$v"; done
  for v in 0.5 0.6 -1.0 -1.5; do phys "$deck" poisson "$v"; done
  for v in 0.0 -7.8e-9; do phys "$deck" density "$v"; done
  for v in 0.0 -1.0; do phys "$deck" thickness "$v" "" body; done
  for v in 0.0 -1.0e-6; do phys "$deck" t_end "$v"; done
  phys "$deck" dt 1.0e-3 "" time
  for v in 1.5 0.0 -0.5; do phys "$deck" safety "$v" "" time; done
  phys "$deck" damping -1.0 "" time
done
phys plate_q8.nml damping -5.0 1 body
phys contact.nml poisson 0.5 2
phys contact.nml density 0.0 2
phys contact.nml young -1.0 2
new_case phys.contact.nml.body-damping=-1.0 phys bad 2 "contact.nml: &body 'upper' damping = -1.0"
cp "$seeds/contact.nml" "$seeds/contact.msh" "$c/"
add_to_group "$c/contact.nml" body "damping = -1.0" 2
set_args -o out contact.nml
for v in -0.1 -1.0; do phys contact.nml friction "$v"; done
phys contact.nml search_distance -1.0 "" contact_pair
phys contact.nml tolerance 0.0 "" contact_pair
phys contact.nml tolerance -1.0e-10 "" contact_pair
phys contact.nml max_iterations 0 "" contact_pair
for v in 0.0 -1.0; do phys plate.nml scale "$v"; done
phys plate.nml frames -1
phys plate.nml history_every -1
phys plate.nml progress_seconds -1.0
phys plate.nml time "2.0e-6, 0.0"
phys plate.nml time "0.0, 0.0"
phys plate.nml value "0.0, 1.0, 2.0"
phys plate.nml value "0.0"
phys plate_q8.nml time "0.0, 2.0e-6, 1.0e-6"
# Two bodies with one name, two amplitudes with one name.
new_case phys.contact.nml.same-body-name phys bad 2 "contact.nml: both bodies named 'lower'"
cp "$seeds/contact.nml" "$seeds/contact.msh" "$c/"
set_key "$c/contact.nml" name "'lower'" 2
set_args -o out contact.nml
new_case phys.plate_q8.nml.two-amplitudes phys bad 2 "plate_q8.nml: amplitude 'ramp' defined twice"
cp "$seeds/plate_q8.nml" "$seeds/plate_q8.msh" "$c/"
echo "&amplitude name = 'ramp', time = 0.0, value = 1.0 /" >> "$c/plate_q8.nml"
set_args -o out plate_q8.nml
new_case phys.plate.nml.no-time phys bad 2 "plate.nml: no &time group"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
edit_lines "$c/plate.nml" '/^&time/ { skip = 1 } !skip { print } skip && /^\// { skip = 0 }'
set_args -o out plate.nml
new_case phys.plate.nml.no-body phys bad 2 "plate.nml: no &body group"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
edit_lines "$c/plate.nml" '/^&body/ { skip = 1 } !skip { print } skip && /^\// { skip = 0 }'
set_args -o out plate.nml

# ---------------------------------------------------------------- sets
setcase() {  # setcase DECK NAME KEY VALUE [N]
  new_case "sets.$1.$2" sets bad 2 "$1: $3 = $4 (occurrence ${5:-1})"
  cp "$seeds/$1" "$seeds/$(mesh_of "$1")" "$c/"
  set_key "$c/$1" "$3" "$4" "${5:-1}"
  set_args -o out "$1"
  v=$(echo "$4" | tr -d "'")
  set_names "${v:-$3}"
}
setcase plate.nml elset-missing elset "'nope'"
setcase plate.nml elset-is-curve elset "'left'"
setcase plate.nml set-missing set "'nope'"
setcase plate.nml set-empty-name set "''"
setcase plate.nml pressure-on-point set "'corner'" 2
setcase plate.nml pressure-on-surface-set set "'plate'" 2
setcase plate.nml fixed-on-elset set "'plate'"
setcase plate.nml amplitude-missing amplitude "'nope'"
setcase plate.nml name-empty name "''"
setcase plate_q8.nml traction-on-point set "'corner'" 3
setcase plate_q8.nml set-case set "'BOTTOM'"
setcase plate_inp.nml elset-missing elset "'plat'"
setcase plate_inp.nml pressure-on-nset set "'left'" 2
setcase plate_inp.nml set-missing set "'right_col'" 2
setcase contact.nml slave-missing slave "'nope'"
setcase contact.nml master-missing master "'nope'"
setcase contact.nml slave-empty-name slave "''"
setcase contact.nml slave-is-master slave "'upper_bottom'"
setcase contact.nml elset-of-other-body elset "'upper'"
# Sets that exist but are empty.
new_case sets.plate.msh.empty-physical sets bad 2 "plate.msh: physical curve 'right' (tag 3) attached to no entity; the deck loads it"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
edit_lines "$c/plate.msh" '$0 ~ /^2 10 0 0 10 2 0 1 3 / { $8 = 0; $9 = "" } { print }'
set_args -o out plate.nml
new_case sets.plate.msh.empty-elset sets bad 2 "plate.msh: physical surface 'plate' attached to no entity (the quads are in no set)"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
edit_lines "$c/plate.msh" '$0 ~ /^1 0 0 0 10 2 0 1 1 / { $8 = 0; $9 = "" } { print }'
set_args -o out plate.nml
new_case sets.plate_q8.msh.physical-without-elements sets bad 2 "plate_q8.msh: the deck fixes 'corner', whose point element is removed"
cp "$seeds/plate_q8.nml" "$seeds/plate_q8.msh" "$c/"
edit_lines "$c/plate_q8.msh" '$0 == "$Elements" { print; getline; print $1 - 1; next } $0 == "1 15 2 6 1 1" { next } { print }'
set_args -o out plate_q8.nml
new_case sets.plate.inp.empty-nset sets bad 2 "plate.inp: *NSET left with no data line"
cp "$seeds/plate_inp.nml" "$seeds/plate.inp" "$c/"
edit_lines "$c/plate.inp" '$0 == "1, 5" { next } { print }'
set_args -o out plate_inp.nml
new_case sets.plate.inp.empty-surface sets bad 2 "plate.inp: *SURFACE right with no data line"
cp "$seeds/plate_inp.nml" "$seeds/plate.inp" "$c/"
edit_lines "$c/plate.inp" '$0 == "3, S2" { next } { print }'
set_args -o out plate_inp.nml
new_case sets.plate.inp.empty-elset sets bad 2 "plate.inp: *ELSET bottom_row GENERATE with no data line, the surface bottom built on it"
cp "$seeds/plate_inp.nml" "$seeds/plate.inp" "$c/"
edit_lines "$c/plate.inp" '$0 == "1, 3, 1" { next } { print }'
echo "&boundary set = 'bottom', type = 'pressure', pressure = 1.0 /" >> "$c/plate_inp.nml"
set_args -o out plate_inp.nml
new_case sets.plate.inp.set-before-definition sets bad 2 "plate.inp: *SURFACE bottom names the elset bottom_row before it is defined"
cp "$seeds/plate_inp.nml" "$seeds/plate.inp" "$c/"
edit_lines "$c/plate.inp" '/^\*ELSET, ELSET=bottom_row/ { getline; next } { print } /^bottom_row, S1/ { print "*ELSET, ELSET=bottom_row, GENERATE"; print "1, 3, 1" }'
set_args -o out plate_inp.nml
new_case sets.contact.msh.empty-slave sets bad 2 "contact.msh: the slave surface lower_top (tag 5) attached to no curve"
cp "$seeds/contact.nml" "$seeds/contact.msh" "$c/"
edit_lines "$c/contact.msh" '$0 ~ /^3 0 0 0 1 0 0 1 5 / { $8 = 0; $9 = "" } { print }'
set_args -o out contact.nml

# A surface edge listed twice (a repeated line element or face): refused,
# or at least not loaded twice.
new_case sets.plate.msh.repeated-edge sets bad 2 "plate.msh: the line element of 'right' repeated under the id 19 (the pressure acts on it)"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
edit_lines "$c/plate.msh" '$0 == "6 18 1 18" { $0 = "6 19 1 19" } $0 == "1 2 1 1" { print "1 2 1 2"; print "19 2 3"; next } { print }'
set_args -o out plate.nml
new_case sets.plate_q8.msh.repeated-edge sets bad 2 "plate_q8.msh (2.2): the line element of 'top' from node 3 repeated under the id 19 (the traction acts on it)"
cp "$seeds/plate_q8.nml" "$seeds/plate_q8.msh" "$c/"
edit_lines "$c/plate_q8.msh" '$0 == "18" { $0 = 19 } { print } $0 == "8 8 2 5 3 3 15 19" { print "19 8 2 5 3 3 15 19" }'
set_args -o out plate_q8.nml
new_case sets.plate.inp.repeated-face sets bad 2 "plate.inp: the face '2, S3' listed twice in *SURFACE top (the pressure acts on it)"
cp "$seeds/plate_inp.nml" "$seeds/plate.inp" "$c/"
edit_lines "$c/plate.inp" '{ print } $0 == "2, S3" { print }'
set_args -o out plate_inp.nml

# ---------------------------------------------------------------- chain
# contact.msh curves: 1 lower_bottom, 2 lower_right, 3 lower_top (slave),
# 4 lower_left, 5 upper_bottom (master), 6 upper_right, 7 upper_top,
# 8 upper_left. Lower block: quads 19 (1 9 10 4) and 20 (9 2 3 10); its top
# is the line elements 6 (3 10) and 7 (10 4) of curve 3; 9-10 is the inner side.
# chain_case NAME KIND NOTE AWK: rewrite contact.msh with AWK.
chain_case() {
  new_case "chain.$1" chain "$2" 2 "$3"
  cp "$seeds/contact.nml" "$seeds/contact.msh" "$c/"
  edit_lines "$c/contact.msh" "$4"
  set_args -o out contact.nml
}
chain_case slave-two-pieces bad "slave lower_top = curves 3 and 1 (top and bottom of the lower block)" \
  '$0 ~ /^1 0 -0.5 0 1 -0.5 0 1 3 / { $8 = 2; $9 = $9 " 5" } { print }'
chain_case master-two-pieces bad "master upper_bottom = curves 5 and 7 (bottom and top of the upper block)" \
  '$0 ~ /^7 0 0.5 0 1 0.5 0 1 9 / { $8 = 2; $9 = $9 " 7" } { print }'
chain_case master-gap bad "master upper_bottom without its middle line element (10 11 12): two pieces" \
  '$0 == "12 26 1 26" { $0 = "12 25 1 26" } $0 == "1 5 1 3" { $0 = "1 5 1 2" } $0 == "10 11 12 " { next } { print }'
chain_case slave-on-two-bodies bad "slave lower_top = curves 3 and 7 (lower top and upper top)" \
  '$0 ~ /^7 0 0.5 0 1 0.5 0 1 9 / { $8 = 2; $9 = $9 " 5" } { print }'
chain_case slave-overlaps-master bad "curve 5 (upper bottom) in both lower_top and upper_bottom" \
  '$0 ~ /^5 0 0 0 1 0 0 1 7 / { $8 = 2; $9 = "7 5" } { print }'
chain_case slave-branch bad "lower_top gets the inner side 10-9 of the lower block: a branch at node 10, an edge inside the body" \
  '$0 == "12 26 1 26" { $0 = "12 27 1 27" } $0 == "1 3 1 2" { $0 = "1 3 1 3" } { print } $0 == "7 10 4 " { print "27 10 9" }'
chain_case slave-not-on-element bad "lower_top's line element 7 made 10-1, a diagonal of quad 19 (no element side)" \
  '$0 == "7 10 4 " { $0 = "7 10 1" } { print }'
chain_case slave-closed-loop maybe "slave lower_top = the whole boundary of the lower block (curves 1 to 4: a closed loop)" \
  'NF == 12 && $8 == 1 && ($9 == 3 || $9 == 4 || $9 == 6) { $8 = 2; $9 = $9 " 5" } { print }'
for pair in "lower_top lower_bottom" "upper_bottom upper_top" "lower_anchor upper_bottom" "lower_top upper_anchor" "lower_top lower_top"; do
  set -- $pair
  new_case "chain.pair-$1-$2" chain bad 2 "contact.nml: slave = $1, master = $2"
  cp "$seeds/contact.nml" "$seeds/contact.msh" "$c/"
  [ "$1" = lower_top ] || set_key "$c/contact.nml" slave "'$1'"
  [ "$2" = upper_bottom ] || set_key "$c/contact.nml" master "'$2'"
  set_args -o out contact.nml
done

# ---------------------------------------------------------------- invert
# invert_gmsh MESH NAME AWK-CONDITION I J NOTE: swap fields I and J of the
# first line matching the condition (an element line).
swap_fields() {
  edit_lines "$c/$1" -v i="$3" -v j="$4" "($2) && !hit { t = \$i; \$i = \$j; \$j = t; hit = 1 } { print }"
}
for e in "14 5 12 4" "16 7 10 11" "18 2 3 9"; do
  set -- $e
  el=$1
  for sw in "2 3" "2 4" "2 5" "3 5" "4 5"; do
    set -- $sw
    new_case "invert.plate.msh.e$el-$1$2" invert bad 2 "plate.msh: element $el, fields $1 and $2 of its line swapped"
    d=$(seed_pair plate.msh)
    swap_fields plate.msh "\$1 == $el && NF == 5" "$1" "$2"
    set_args -o out "$d"
  done
done
# plate_q8.msh (2.2): element lines "id 16 2 1 1 n1..n8": corners are fields 6..9.
for el in 14 16 18; do
  for sw in "6 7" "6 8" "7 9" "6 10"; do
    set -- $sw
    new_case "invert.plate_q8.msh.e$el-$1$2" invert bad 2 "plate_q8.msh: element $el, fields $1 and $2 swapped"
    d=$(seed_pair plate_q8.msh)
    swap_fields plate_q8.msh "\$1 == $el && \$2 == 16" "$1" "$2"
    set_args -o out "$d"
  done
done
for sw in "2 3" "2 4" "3 5"; do
  set -- $sw
  new_case "invert.plate.inp.e1-$1$2" invert bad 2 "plate.inp: element 1, nodes $(($1 - 1)) and $(($2 - 1)) swapped"
  d=$(seed_pair plate.inp)
  edit_lines "$c/plate.inp" -F ', ' -v OFS=', ' -v i="$1" -v j="$2" '$0 == "1, 1, 2, 6, 5" { t = $i; $i = $j; $j = t } { print }'
  set_args -o out "$d"
done
# contact.msh: the first quadrilateral of each body.
for body in lower upper; do
  new_case "invert.contact.msh.$body" invert bad 2 "contact.msh: first quad of $body with nodes 1 and 3 swapped"
  d=$(seed_pair contact.msh)
  if [ "$body" = lower ]; then tag='2 1 3'; else tag='2 2 3'; fi
  edit_lines "$c/contact.msh" -v hdr="$tag" 'hit == 1 { t = $2; $2 = $4; $4 = t; hit = 2 } index($0, hdr) == 1 && !hit { hit = 1 } { print }'
  set_args -o out "$d"
done
# Degenerate elements: a node repeated, a node that does not exist.
new_case invert.plate.msh.repeated-node invert bad 2 "plate.msh: element 15 = 5 6 6 12"
d=$(seed_pair plate.msh); edit_lines "$c/plate.msh" '$0 == "15 5 6 11 12 " { $0 = "15 5 6 6 12" } { print }'; set_args -o out "$d"
new_case invert.plate.msh.undefined-node invert bad 2 "plate.msh: element 15 uses node 99"
d=$(seed_pair plate.msh); edit_lines "$c/plate.msh" '$0 == "15 5 6 11 12 " { $0 = "15 5 6 99 12" } { print }'; set_args -o out "$d"
new_case invert.plate.msh.collapsed-node invert bad 2 "plate.msh: node 11 moved onto node 12 (a zero-length side)"
d=$(seed_pair plate.msh); edit_lines "$c/plate.msh" '$0 == "3.999999999999996 2 0" { $0 = "1.999999999999998 2 0" } { print }'; set_args -o out "$d"
new_case invert.plate.msh.flat-element invert bad 2 "plate.msh: node 11 moved to y = 0 (element 15 and 16 flattened)"
d=$(seed_pair plate.msh); edit_lines "$c/plate.msh" '$0 == "3.999999999999996 2 0" { $0 = "3.999999999999996 0 0" } { print }'; set_args -o out "$d"
new_case invert.plate.inp.duplicate-node-id invert bad 2 "plate.inp: node 6 defined twice"
d=$(seed_pair plate.inp); edit_lines "$c/plate.inp" '{ print } $0 == "6, 2., 2." { print "6, 2., 3." }'; set_args -o out "$d"
new_case invert.plate.inp.duplicate-element-id invert bad 2 "plate.inp: element 1 defined twice"
d=$(seed_pair plate.inp); edit_lines "$c/plate.inp" '{ print } $0 == "1, 1, 2, 6, 5" { print "1, 2, 3, 7, 6" }'; set_args -o out "$d"
new_case invert.plate_q8.msh.mid-node-off-side invert bad 2 "plate_q8.msh: Q8 element 14 with mid nodes 9 and 23 swapped"
d=$(seed_pair plate_q8.msh); swap_fields plate_q8.msh '$1 == 14 && $2 == 16' 10 12; set_args -o out "$d"

# ---------------------------------------------------------------- meshfile
mesh_case() {  # mesh_case NAME DECK FILE-VALUE NOTE [FORMAT]
  new_case "meshfile.$1" meshfile bad 2 "$4"
  cp "$seeds/$2" "$seeds/$(mesh_of "$2")" "$c/"
  [ "$3" = "'$(mesh_of "$2")'" ] || set_key "$c/$2" file "$3"
  [ -z "${5:-}" ] || set_key "$c/$2" format "$5"
  set_args -o out "$2"
  v=$(echo "$3" | tr -d "'")
  [ -n "$v" ] && [ "$v" != . ] && set_names "$v"
}
mesh_case missing plate.nml "'no_such_mesh.msh'" "plate.nml: &mesh file names a file that does not exist"
mesh_case missing-inp plate_inp.nml "'no_such_mesh.inp'" "plate_inp.nml: &mesh file names a file that does not exist"
mesh_case missing-folder contact.nml "'no_such_dir/contact.msh'" "contact.nml: the mesh in a folder that does not exist"
mesh_case empty-name plate.nml "''" "plate.nml: &mesh file = ''"
mesh_case is-folder plate.nml "'.'" "plate.nml: &mesh file = '.' (a folder)"
mesh_case gmsh-as-abaqus plate.nml "'plate.msh'" "plate.nml: a Gmsh file read with format = 'abaqus'" "'abaqus'"
mesh_case abaqus-as-gmsh plate_inp.nml "'plate.inp'" "plate_inp.nml: an Abaqus file read with format = 'gmsh'" "'gmsh'"
mesh_case unknown-extension plate.nml "'plate.txt'" "plate.nml: mesh plate.txt (a copy of plate.msh) with format = 'auto'"
cp "$c/plate.msh" "$c/plate.txt"
mesh_case empty-file plate.nml "'empty.msh'" "plate.nml: the mesh file is empty"
: > "$c/empty.msh"
mesh_case deck-as-mesh plate.nml "'plate.nml'" "plate.nml: the deck itself as mesh, format = 'gmsh'" "'gmsh'"
mesh_case binary plate.nml "'binary.msh'" "plate.nml: a Gmsh 4.1 mesh that says it is binary (file-type 1)"
sed 's/^4\.1 0 8$/4.1 1 8/' "$c/plate.msh" > "$c/binary.msh"
mesh_case version-4.0 plate.nml "'v40.msh'" "plate.nml: a mesh that says MSH 4.0"
sed 's/^4\.1 0 8$/4 0 8/' "$c/plate.msh" > "$c/v40.msh"
new_case meshfile.deck-missing meshfile bad 2 "the deck itself does not exist"
set_args -o out no_such_deck.nml
new_case meshfile.deck-is-folder meshfile bad 2 "the deck is a folder"
mkdir "$c/deck.nml"
set_args -o out deck.nml
new_case meshfile.deck-empty meshfile bad 2 "the deck is an empty file"
: > "$c/empty.nml"
set_args -o out empty.nml
new_case meshfile.deck-binary meshfile bad 2 "the deck with the bytes NUL NUL 0xff 0xfe before the key young"
cp "$seeds/plate.msh" "$c/"
l=$(awk '/^  young = / { print NR; exit }' "$seeds/plate.nml")
{ head -n "$((l - 1))" "$seeds/plate.nml"; printf '\000\000\377\376'; tail -n "+$l" "$seeds/plate.nml"; } > "$c/nul.nml"
set_args -o out nul.nml

# ---------------------------------------------------------------- outdir
# The output folder under a regular file (cannot be created), an existing
# regular file as the folder, and a folder that is not writable (run by
# root, chmod does not stop writing: the runner then falls back to a path
# under a regular file, see setup=not_writable in the runner).
out_case() {  # out_case NAME DECK NOTE ARGS...
  new_case "outdir.$1" outdir bad 4 "$3"
  d=$2; shift 3
  cp "$seeds/$d" "$seeds/$(mesh_of "$d")" "$c/"
  : > "$c/plain_file"
  set_args "$@"
  set_names plain_file
}
out_case under-file plate.nml "--output plain_file/out" --output plain_file/out plate.nml
out_case under-file-deep contact.nml "-o plain_file/a/b/c" -o plain_file/a/b/c contact.nml
out_case is-file plate_q8.nml "-o plain_file (an existing regular file)" -o plain_file plate_q8.nml
out_case deck-under-file plate_inp.nml "&run output_dir = 'plain_file/out'" plate_inp.nml
set_key "$c/plate_inp.nml" title "'x', output_dir = 'plain_file/out'"
out_case deck-is-file plate.nml "&run output_dir = 'plain_file'" plate.nml
set_key "$c/plate.nml" title "'x', output_dir = 'plain_file'"
out_case not-writable plate.nml "-o ro/out where ro is mode 0555 (non-root), or under a regular file (root)" -o ro/out plate.nml
set_setup not_writable
sed -i 's/^names=.*/names=ro/' "$c/case.txt"
out_case not-writable-self contact.nml "-o ro where ro is mode 0555 (non-root), or a regular file (root)" -o ro contact.nml
set_setup not_writable
sed -i 's/^names=.*/names=ro/' "$c/case.txt"

# ---------------------------------------------------------------- diskfull
# The output folder is a 64 KiB tmpfs (mounted by the runner, as root only);
# 200 frames of the plate outgrow it during the run.
disk_case() {  # disk_case NAME DECK FRAMES NOTE
  new_case "diskfull.$1" diskfull bad 4 "$4"
  cp "$seeds/$2" "$seeds/$(mesh_of "$2")" "$c/"
  set_key "$c/$2" frames "$3"
  set_key "$c/$2" history_every 1
  set_args -o out "$2"
  set_setup disk_full
}
disk_case plate-frames plate.nml 14 "plate.nml, 14 frames and a history row per step into a 64 KiB tmpfs"
set_key "$c/plate.nml" t_end 4.0e-4
set_key "$c/plate.nml" frames 400
disk_case contact-frames contact.nml 43 "contact.nml, a frame per step into a 64 KiB tmpfs"
set_key "$c/contact.nml" t_end 1.5e-5
set_key "$c/contact.nml" frames 430
disk_case q8-history plate_q8.nml 0 "plate_q8.nml, no frames, a long history into a 64 KiB tmpfs"
set_key "$c/plate_q8.nml" t_end 2.0e-4

# ---------------------------------------------------------------- cmdline
cmd_case() {  # cmd_case NAME NOTE ARGS...
  new_case "cmdline.$1" cmdline bad 1 "$2"
  shift 2
  cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
  set_args "$@"
}
cmd_case no-scene "no scene" -o out
cmd_case unknown-option "an unknown option" --frobnicate plate.nml
cmd_case two-scenes "two scenes" plate.nml plate.nml
cmd_case output-without-folder "--output at the end" plate.nml --output
cmd_case o-without-folder "-o at the end" plate.nml -o
cmd_case bad-short-option "an unknown short option" -x plate.nml

# The hostile-input families (issue #18): sizes, overflow, paths, damage,
# meshmix, threads, validdeck, messages.
. "$(dirname "$0")/make_cases_hostile.sh"
# The families of the newer features (axisymmetric, finite strain, j2,
# mortar conditions, closed loops, mass scaling, CAX8 surfaces, Gmsh
# physical groups, restarts of frictional contact), described there.
. "$(dirname "$0")/make_cases_features.sh"
# The deck's names against the mesh's (case rules of each format, names of
# the wrong kind) and the bounds of the deck's numbers, described there.
. "$(dirname "$0")/make_cases_names.sh"
# Pipes, devices and folders in place of input files, texts of 100000
# characters, tens of thousands of sets, described there.
. "$(dirname "$0")/make_cases_files.sh"
# What the deck's text may hold: names the results cannot hold, described there.
. "$(dirname "$0")/make_cases_deck.sh"
# Ids and Gmsh 4.1 entities a mesh refers to, and inputs whose reading time
# grew with the square of their size, described there.
. "$(dirname "$0")/make_cases_tags.sh"
# Input rules a user could trip over without a word (contact pairs of two
# thicknesses, broken links, set ids beyond 2^31, a lone *End Part),
# described there.
. "$(dirname "$0")/make_cases_rules.sh"
# Faults the user cannot see where the message pointed (control
# characters, an Abaqus parameter given twice or without its value, a mesh
# too large for double precision, a folder or a broken link as an HDF5
# input), described there.
. "$(dirname "$0")/make_cases_text.sh"

echo "make_cases: $ncase cases in $cases"
