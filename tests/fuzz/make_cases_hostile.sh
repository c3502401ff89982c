# Hostile-input families of the fuzz set (issue #18), sourced by
# make_cases.sh after its own families: it uses that script's helpers
# (new_case, set_args, set_setup, set_names, set_key, add_to_group,
# edit_lines, rng) and variables (seeds, cases, c).
#
#   sizes     counts that would size an allocation: Gmsh header and block
#             counts, Abaqus GENERATE ranges of billions; a history of
#             trillions of rows (more than the disk holds), millions of
#             result frames (a frame per step is fine on a short run)     2, valid
#   overflow  t_end / dt beyond what a step counter can count            2
#   paths     empty -o or scene argument (1); the output stem locked by
#             another run (4)                                             1, 4
#   damage    a stopped run's checkpoint, .h5.part or text .part files
#             with a bit flipped, bytes zeroed or the file cut, then
#             --restart: refused (2 or 4) or, if the damage hit unused
#             bytes, results equal to an uninterrupted run                 2 4 (maybe)
#   meshmix   Q4 beside Q8 (hanging mid-side node), two mid-side nodes on
#             one side, Abaqus *Part / *Instance                           2
#   threads   absurd or oversubscribed OMP_NUM_THREADS on a mesh large
#             enough to thread: must run through (a warning), no hang    valid
#   validdeck valid decks once refused: two &boundary groups on one set,
#             a UTF-8 byte-order mark                                     valid
#   messages  inputs that were reported misleadingly: the ERROR line must
#             name the real problem                                       2, 4

# ---------------------------------------------------------------- sizes
size_case() {  # size_case NAME MESH NOTE NAMES AWK
  new_case "sizes.$2.$1" sizes bad 2 "$3"
  d=$(seed_pair "$2")
  edit_lines "$c/$2" "$5"
  set_args -o out "$d"
  set_names "$4"
}
size_case physnames-2e9 plate.msh "\$PhysicalNames count 2000000000" 2000000000 \
  'p == 1 { $0 = "2000000000"; p = 2 } $0 == "$PhysicalNames" && !p { p = 1 } { print }'
size_case physnames-max contact.msh "\$PhysicalNames count 2147483647" 2147483647 \
  'p == 1 { $0 = "2147483647"; p = 2 } $0 == "$PhysicalNames" && !p { p = 1 } { print }'
size_case node-block-1.5e9 plate.msh "nodes in the block of curve 1 = 1500000000" 1500000000 \
  '$0 == "1 1 0 4" && !h { $4 = 1500000000; h = 1 } { print }'
size_case elem-block-2e9 plate.msh "elements in the surface block = 2000000000" 2000000000 \
  '$0 == "2 1 3 5" && !h { $4 = 2000000000; h = 1 } { print }'
size_case node-block-max contact.msh "first node block count 2147483647" 2147483647 \
  'p == 2 && NF == 4 && !h { $4 = 2147483647; h = 1 } p == 1 { p = 2 } $0 == "$Nodes" && !p { p = 1 } { print }'
size_case nodes22-2e9 plate_q8.msh "MSH 2.2 \$Nodes count 2000000000" 2000000000 \
  'p == 1 { $0 = "2000000000"; p = 2 } $0 == "$Nodes" && !p { p = 1 } { print }'
size_case elements22-2e9 plate_q8.msh "MSH 2.2 \$Elements count 2000000000" 2000000000 \
  'p == 1 { $0 = "2000000000"; p = 2 } $0 == "$Elements" && !p { p = 1 } { print }'
size_case physnames22-1e9 plate_q8.msh "MSH 2.2 \$PhysicalNames count 1000000000" 1000000000 \
  'p == 1 { $0 = "1000000000"; p = 2 } $0 == "$PhysicalNames" && !p { p = 1 } { print }'
size_case generate-elset-2e9 plate.inp "ELSET GENERATE 1, 2000000000, 1" GENERATE \
  '$0 == "1, 3, 1" { $0 = "1, 2000000000, 1" } { print }'
size_case generate-elset-step plate.inp "ELSET GENERATE 1, 2147483647, 3" GENERATE \
  '$0 == "1, 3, 1" { $0 = "1, 2147483647, 3" } { print }'
size_case generate-nset-2e9 plate.inp "an NSET GENERATE 1, 2000000000" GENERATE \
  '{ print } $0 == "1, 5" { print "*NSET, NSET=huge, GENERATE"; print "1, 2000000000" }'
# A history row per step of a run of trillions of steps: the history is
# streamed to disk (no memory grows with the steps), but its files would
# not fit on any disk: refused before the run starts.
for d in plate.nml contact.nml; do
  new_case "sizes.$d.history-every-step" sizes bad 2 "$d: t_end = 1e6 (trillions of steps) with history_every = 1"
  cp "$seeds/$d" "$seeds/$(mesh_of "$d")" "$c/"
  set_key "$c/$d" t_end 1.0e6
  set_key "$c/$d" history_every 1
  set_args -o out "$d"
  set_names history_every
done

# Result frames are numbered with six digits and each keeps a record for
# the XDMF: frames = 2e9 over millions of steps is refused naming frames;
# over the seed's few steps it is a frame per step (valid).
for d in plate.nml contact.nml; do
  new_case "sizes.$d.frames-2e9-long" sizes bad 2 "$d: t_end = 1 (millions of steps), frames = 2000000000"
  cp "$seeds/$d" "$seeds/$(mesh_of "$d")" "$c/"
  set_key "$c/$d" t_end 1.0
  set_key "$c/$d" frames 2000000000
  set_args -o out "$d"
  set_names frames
  new_case "sizes.$d.frames-2e9-short" sizes valid 0 "$d: frames = 2000000000 over its few steps (a frame per step)"
  cp "$seeds/$d" "$seeds/$(mesh_of "$d")" "$c/"
  set_key "$c/$d" frames 2000000000
  set_args -o out "$d"
done

# Files without end of line: /dev/zero as the deck and as the mesh, now
# refused as a device before it is read (make_cases_files.sh has the same
# with regular files of a line longer than the readers take).
new_case sizes.deck-dev-zero sizes bad 2 "the deck is /dev/zero (one endless line)"
set_args -o out /dev/zero
set_names "pipe or device"
new_case sizes.mesh-dev-zero sizes bad 2 "&mesh file = '/dev/zero', format = 'gmsh'"
cp "$seeds/plate.nml" "$c/"
set_key "$c/plate.nml" file "'/dev/zero'"
set_key "$c/plate.nml" format "'gmsh'"
set_args -o out plate.nml
set_names "pipe or device"

# ---------------------------------------------------------------- overflow
over_case() {  # over_case NAME DECK KEY VALUE
  new_case "overflow.$2.$1" overflow bad 2 "$2: $3 = $4"
  cp "$seeds/$2" "$seeds/$(mesh_of "$2")" "$c/"
  set_key "$c/$2" "$3" "$4"
  set_args -o out "$2"
  set_names t_end
}
over_case t_end-1e13 plate.nml t_end 1.0e13
over_case t_end-1e300 plate.nml t_end 1.0e300
over_case t_end-3e9 plate_inp.nml t_end 3.0e9
over_case t_end-1e15 contact.nml t_end 1.0e15
over_case t_end-1e20 plate_q8.nml t_end 1.0e20
new_case overflow.plate_inp.nml.dt-1e-300 overflow bad 2 "plate_inp.nml: dt = 1e-300 for t_end = 4e-6"
cp "$seeds/plate_inp.nml" "$seeds/plate.inp" "$c/"
set_key "$c/plate_inp.nml" dt 1.0e-300
set_args -o out plate_inp.nml
set_names t_end

# ---------------------------------------------------------------- paths
# args are split by the runner as the shell would (eval): '' is an empty argument.
path_case() {  # path_case NAME EXPECT NOTE ARGS...
  new_case "paths.$1" paths bad "$2" "$3"
  shift 3
  cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
  set_args "$@"
}
path_case o-empty 1 "-o ''" -o "''" plate.nml
set_names "-o"
path_case output-empty 1 "--output ''" --output "''" plate.nml
set_names "--output"
path_case o-blank 1 "-o '   '" -o "'   '" plate.nml
path_case scene-empty 1 "an empty scene argument" -o out "''"
path_case restart-empty 1 "--restart ''" --restart "''"
# The stem locked by another run (the runner holds out/<stem>.lock with flock(1)).
for d in plate.nml contact.nml plate_q8.nml; do
  new_case "paths.locked.$d" paths bad 4 "$d into out/, whose stem lock another process holds"
  cp "$seeds/$d" "$seeds/$(mesh_of "$d")" "$c/"
  set_args -o out "$d"
  set_setup locked
  set_names "another raccord run"
done

# ---------------------------------------------------------------- damage
# The runner first runs the deck with --wall-clock 0.001 into out/ (exit 5,
# a checkpoint and the running .part files), then damages one of them
# (damage=SUFFIX R MODE: the file out/<stem>SUFFIX, at the byte R/1e6 of its
# size; MODE flip (one bit), zero (16 bytes) or cut (the file ends there)),
# then runs the case: --restart out/<stem>.checkpoint.h5. Exit 0 is taken
# only with results equal to an uninterrupted run (h5diff, cmp).
fam_seed=900
for d in plate.nml contact.nml; do
  stem=${d%.nml}
  targets=".checkpoint.h5 .h5.part .history.txt.part"
  [ "$d" = contact.nml ] && targets="$targets .contact1.txt.part"
  for t in $targets; do
    fam_seed=$((fam_seed + 1))
    case $t in *.h5*) n=8 ;; *) n=3 ;; esac
    i=0
    for r in $(rng "$fam_seed" "$n" 1000000); do
      i=$((i + 1))
      if [ "$i" -le $((n - 3)) ]; then mode=flip; elif [ "$i" -le $((n - 1)) ]; then mode=zero; else mode=cut; fi
      new_case "damage.$stem$t.$mode.$r" damage maybe "2 4" "$d: $stem$t $mode at $r ppm of its size, then --restart"
      cp "$seeds/$d" "$seeds/$(mesh_of "$d")" "$c/"
      # long enough that the wall-clock stop comes well before the end
      set_key "$c/$d" t_end 4.0e-4
      set_key "$c/$d" history_every 1
      set_args --restart "out/$stem.checkpoint.h5"
      set_setup damage
      printf 'damage=%s %s %s\ndeck=%s\n' "$t" "$r" "$mode" "$d" >> "$c/case.txt"
    done
  done
done

# ---------------------------------------------------------------- meshmix
new_case meshmix.plate_q8.msh.q4-beside-q8 meshmix bad 2 "plate_q8.msh: element 15 made a Q4 (its mid-side node 25 on element 14's side hangs)"
d=$(seed_pair plate_q8.msh)
edit_lines "$c/plate_q8.msh" '$1 == 15 && $2 == 16 { print $1, 3, $3, $4, $5, $6, $7, $8, $9; next } { print }'
set_args -o out "$d"
set_names "hangs"
new_case meshmix.plate_q8.msh.q4-first meshmix bad 2 "plate_q8.msh: element 14 made a Q4"
d=$(seed_pair plate_q8.msh)
edit_lines "$c/plate_q8.msh" '$1 == 14 && $2 == 16 { print $1, 3, $3, $4, $5, $6, $7, $8, $9; next } { print }'
set_args -o out "$d"
set_names "hangs"
new_case meshmix.plate_q8.msh.two-mid-nodes meshmix bad 2 "plate_q8.msh: element 15 uses a copy (node 29) of the mid-side node 25 it shares with element 14"
d=$(seed_pair plate_q8.msh)
edit_lines "$c/plate_q8.msh" 'p == 1 { print $0 + 1; p = 2; next } $0 == "$Nodes" && !p { p = 1 }
  $0 == "$EndNodes" { print "29 1.999999999998411 1 0" }
  $1 == 15 && $2 == 16 { $13 = 29 } { print }'
set_args -o out "$d"
set_names "mid-side"
# A 2:1 refinement without transition: node 5 lies on the right side of
# the coarse element 1, and is a corner of the two fine elements only.
new_case meshmix.hanging-q4 meshmix bad 2 "a coarse Q4 beside two fine ones: node 5 hangs on its side 2-3"
cat > "$c/hang.msh" << 'EOF'
$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 2 "left"
2 1 "body"
$EndPhysicalNames
$Nodes
8
1 0 0 0
2 2 0 0
3 2 2 0
4 0 2 0
5 2 1 0
6 3 0 0
7 3 1 0
8 3 2 0
$EndNodes
$Elements
4
1 3 2 1 1 1 2 3 4
2 3 2 1 1 2 6 7 5
3 3 2 1 1 5 7 8 3
4 1 2 2 4 4 1
$EndElements
EOF
cat > "$c/hang.nml" << 'EOF'
&mesh file = 'hang.msh' /
&body name = 'body', elset = 'body', young = 200000.0, poisson = 0.3, density = 7.8e-9 /
&boundary set = 'left', type = 'fixed', components = 'xy' /
&time t_end = 1.0e-6 /
EOF
set_args -o out hang.nml
set_names "hangs"

part_case() {  # part_case NAME NOTE AWK
  new_case "meshmix.plate.inp.$1" meshmix bad 2 "$2"
  d=$(seed_pair plate.inp)
  edit_lines "$c/plate.inp" "$3"
  set_args -o out "$d"
  set_names "*Part"
}
part_case part-instance-translated "plate.inp inside *Part, placed by a translated *Instance" \
  'NR == 3 { print "*Part, name=P" } /^\*MATERIAL/ && !e { print "*End Part"; print "*Assembly, name=A"; print "*Instance, name=I, part=P"; print "10., 0., 0."; print "*End Instance"; print "*End Assembly"; e = 1 } { print }'
part_case part-only "plate.inp inside *Part / *End Part" \
  'NR == 3 { print "*Part, name=P" } /^\*MATERIAL/ && !e { print "*End Part"; e = 1 } { print }'
new_case meshmix.plate.inp.instance-only meshmix bad 2 "plate.inp followed by an *Assembly with a rotated *Instance"
d=$(seed_pair plate.inp)
printf '*Assembly, name=A\n*Instance, name=I, part=P\n0., 0., 0.\n0., 0., 0., 0., 0., 1., 90.\n*End Instance\n*End Assembly\n' >> "$c/plate.inp"
set_args -o out "$d"
set_names "*Assembly"

# ---------------------------------------------------------------- threads
# A 48 x 48 Q4 block (2304 elements: enough chunks to thread), 30 steps.
make_block() {  # make_block DIR
  awk 'BEGIN {
    n = 48; h = 1.0
    print "$MeshFormat"; print "2.2 0 8"; print "$EndMeshFormat"
    print "$PhysicalNames"; print 3; print "1 2 \"left\""; print "1 3 \"right\""; print "2 1 \"block\""; print "$EndPhysicalNames"
    print "$Nodes"; print (n + 1) * (n + 1)
    for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) print j * (n + 1) + i + 1, i * h, j * h, 0
    print "$EndNodes"
    print "$Elements"; print n * n + 2 * n
    id = 0
    for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
      a = j * (n + 1) + i + 1
      print ++id, 3, 2, 1, 1, a, a + 1, a + n + 2, a + n + 1
    }
    for (j = 0; j < n; j++) { a = j * (n + 1) + 1; print ++id, 1, 2, 2, 4, a + n + 1, a }
    for (j = 0; j < n; j++) { a = j * (n + 1) + n + 1; print ++id, 1, 2, 3, 2, a, a + n + 1 }
    print "$EndElements"
  }' > "$1/block.msh"
  cat > "$1/block.nml" << 'EOF'
! Fuzz: a 48 x 48 Q4 block, clamped left, pulled right; 30 steps.
&mesh file = 'block.msh' /
&body name = 'block', elset = 'block', young = 200000.0, poisson = 0.3, density = 7.8e-9 /
&boundary set = 'left', type = 'fixed', components = 'xy' /
&boundary set = 'right', type = 'pressure', pressure = -10.0 /
&time t_end = 5.0e-6 /
&output frames = 1 /
EOF
}
for v in 99999999999 18446744073709551617 1000 abc 0 "8,4" 2.5; do
  tag=$(echo "$v" | tr ', .' '__p')
  new_case "threads.omp-$tag" threads valid 0 "OMP_NUM_THREADS='$v' on a 2304-element block"
  make_block "$c"
  set_args -o out block.nml
  printf 'env=OMP_NUM_THREADS=%s\n' "$v" >> "$c/case.txt"
done

# ---------------------------------------------------------------- validdeck
new_case validdeck.plate.nml.split-clamp validdeck valid 0 "plate.nml: the clamp of 'left' as two groups, x and y"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
set_key "$c/plate.nml" components "'x'"
printf "&boundary\n  set = 'left', type = 'fixed', components = 'y'\n/\n" >> "$c/plate.nml"
set_args -o out plate.nml
new_case validdeck.plate_inp.nml.split-clamp validdeck valid 0 "plate_inp.nml: 'left' fixed as two groups, x and y"
cp "$seeds/plate_inp.nml" "$seeds/plate.inp" "$c/"
edit_lines "$c/plate_inp.nml" -v q="'" '$0 ~ /set = .left., type = .fixed./ {
  print "  set = " q "left" q ", type = " q "fixed" q ", components = " q "x" q; print "/"
  print "&boundary set = " q "left" q ", type = " q "fixed" q ", components = " q "y" q; next } { print }'
set_args -o out plate_inp.nml
for d in plate.nml contact.nml plate_q8.nml; do
  new_case "validdeck.$d.utf8-bom" validdeck valid 0 "$d saved with a UTF-8 byte-order mark"
  cp "$seeds/$(mesh_of "$d")" "$c/"
  { printf '\357\273\277'; cat "$seeds/$d"; } > "$c/$d"
  set_args -o out "$d"
done

# ---------------------------------------------------------------- messages
msg_case() {  # msg_case NAME DECK NAMES NOTE
  new_case "messages.$2.$1" messages bad 2 "$4"
  cp "$seeds/$2" "$seeds/$(mesh_of "$2")" "$c/"
  set_args -o out "$2"
  set_names "$3"
}
msg_case scale-1e200 plate.nml scale "&mesh scale = 1e200 (every area infinite)"
set_key "$c/plate.nml" scale 1.0e200
msg_case scale-1e-200 plate.nml scale "&mesh scale = 1e-200 (every area zero)"
set_key "$c/plate.nml" scale 1.0e-200
msg_case scale-1e150 plate_inp.nml scale "&mesh scale = 1e150"
add_to_group "$c/plate_inp.nml" mesh "scale = 1.0e150"
msg_case both-prescribed contact.nml prescribed "both contact surfaces fully prescribed"
edit_lines "$c/contact.nml" '/^&boundary/ { skip = 1 } skip && /^\// { skip = 0; next } !skip { print }'
printf "&boundary set = 'lower_top', type = 'fixed', components = 'xy' /\n&boundary set = 'upper_bottom', type = 'fixed', components = 'xy' /\n" >> "$c/contact.nml"
new_case messages.deck-folder messages bad 2 "a folder given as the deck"
mkdir "$c/scene.nml"
set_args -o out scene.nml
set_names folder
new_case messages.plate.inp.trailing-comma messages maybe 2 "plate.inp ending in a data line with a trailing comma and no newline"
d=$(seed_pair plate.inp)
printf '*NSET, NSET=extra\n1, 2,' >> "$c/plate.inp"
set_args -o out "$d"
new_case messages.plate.inp.trailing-comma-element messages bad 2 "plate.inp ending in an element line cut after a trailing comma"
d=$(seed_pair plate.inp)
printf '*ELEMENT, TYPE=CPS4, ELSET=plate\n4, 3, 4,' >> "$c/plate.inp"
set_args -o out "$d"
new_case messages.full-disk messages bad 4 "the output folder is a full tmpfs from the start"
cp "$seeds/plate.nml" "$seeds/plate.msh" "$c/"
set_args -o out plate.nml
set_setup disk_full_now
set_names "No space left"
# An *INCLUDE cycle: named as such, not as the runtime's "File already opened".
new_case messages.plate.inp.include-self messages bad 2 "plate.inp includes itself"
d=$(seed_pair plate.inp)
{ echo "*INCLUDE, INPUT=plate.inp"; cat "$seeds/plate.inp"; } > "$c/plate.inp"
set_args -o out "$d"
set_names "includes itself"
new_case messages.plate.inp.include-cycle messages bad 2 "plate.inp includes b.inp, which includes ./plate.inp"
d=$(seed_pair plate.inp)
{ echo "*INCLUDE, INPUT=b.inp"; cat "$seeds/plate.inp"; } > "$c/plate.inp"
echo "*INCLUDE, INPUT=./plate.inp" > "$c/b.inp"
set_args -o out "$d"
set_names "includes itself"
# An integer key beyond 32 bits: the hint names a whole number and its range.
msg_case checkpoint-every-2e19 plate.nml "whole number from 0 to 2147483647" "&run checkpoint_every = 99999999999999999999"
add_to_group "$c/plate.nml" run "checkpoint_every = 99999999999999999999"
msg_case frames-3e9 plate.nml "whole number from 0 to 2147483647" "&output frames = 3000000000"
set_key "$c/plate.nml" frames 3000000000
