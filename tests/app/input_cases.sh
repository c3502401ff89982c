#!/bin/sh
# Input handling of the raccord program: the deck's names against the
# mesh's (each format's case rule, names of the wrong kind, pairs that
# resolve to one surface) and the bounds of friction and tolerance, with
# the messages and exit codes users see. One case per CTest entry.
#
#   sh input_cases.sh CASE RACCORD SEED_DIR SLIDING_DIR WORK_DIR
#
# CASE         names_abaqus, names_gmsh, names_kind, friction_bound, friction_large
# RACCORD      the raccord executable
# SEED_DIR     tests/fuzz/seeds (axi.nml + axi.inp: Abaqus, loop.nml +
#              loop.msh: Gmsh)
# SLIDING_DIR  input/verification/sliding (a block pulled on a block)
# WORK_DIR     this case's folder, emptied first
#
# Exit 0 = pass, 1 = fail (every failed check is printed).
set -u

case_name=$1
raccord=$2
seeds=$3
sliding=$4
work=$5

failures=0
fail() { echo "FAIL [$case_name]: $*" >&2; failures=$((failures + 1)); }
pass() { echo "ok   [$case_name]: $*"; }

rm -rf "$work"
mkdir -p "$work" || exit 1

# try NAME DECK EXPECTED-EXIT ARGS...: run raccord on DECK (in $work/NAME,
# with the files copied there by the caller) and check the exit code.
try() {
  _dir=$work/$1
  _deck=$2
  _want=$3
  shift 3
  (cd "$_dir" && "$raccord" "$@" "$_deck" > stdout.txt 2> stderr.txt)
  code=$?
  if [ "$code" -eq "$_want" ]; then pass "$1: exit $code"
  else fail "$1: exit $code, expected $_want"; sed 's/^/    /' "$_dir/stderr.txt" >&2; fi
}

# says NAME TEXT...: the ERROR (or WARNING) lines of NAME hold every TEXT.
says() {
  _dir=$work/$1
  shift
  for _t in "$@"; do
    if grep -E '^(ERROR|WARNING)' "$_dir/stderr.txt" | grep -qF -- "$_t"; then pass "$(basename "$_dir") says '$_t'"
    else fail "$(basename "$_dir"): message lacks '$_t'"; sed 's/^/    /' "$_dir/stderr.txt" >&2; fi
  done
}

# seed NAME DECK MESH: a case folder with a copy of a seed deck and its mesh.
seed() {
  mkdir -p "$work/$1"
  cp "$seeds/$2" "$seeds/$3" "$work/$1/"
  d=$work/$1/$2
  m=$work/$1/$3
}

case $case_name in
names_abaqus)
  # An Abaqus mesh's unquoted labels are found in any case (Abaqus's rule).
  seed upper axi.nml axi.inp
  sed -i "s/elset = 'disc'/elset = 'DISC'/; s/set = 'disc_bottom'/set = 'Disc_Bottom'/; s/set = 'punch_top'/set = 'PUNCH_TOP'/; s/slave = 'punch_bottom'/slave = 'Punch_Bottom'/; s/master = 'disc_top'/master = 'DISC_TOP'/" "$d"
  try upper axi.nml 0 --check
  if grep -qi "contact pair 1: slave punch_bottom" "$work/upper/stdout.txt"; then pass "the pair is built"
  else fail "no contact pair line in the plan"; fi
  # The same surface in two spellings: one surface, refused as self-contact.
  seed self axi.nml axi.inp
  sed -i "s/slave = 'punch_bottom'/slave = 'disc_top'/; s/master = 'disc_top'/master = 'Disc_Top'/" "$d"
  try self axi.nml 2 --check
  says self "&contact_pair #1" "slave and master are the same surface 'disc_top'" "finds an unquoted label in any case"
  # A second pair that is the first one in other spellings.
  seed twice axi.nml axi.inp
  echo "&contact_pair slave = 'PUNCH_BOTTOM', master = 'Disc_Top', method = 'mortar' /" >> "$d"
  try twice axi.nml 2 --check
  says twice "&contact_pair #2" "as &contact_pair #1"
  # Abaqus keeps a quoted label's case (doc/mesh-formats.md): ELSET="disc"
  # and ELSET=disc (the label DISC) are two sets; the deck's 'disc' is the
  # quoted one (both disc elements), its 'Disc' the unquoted one (element
  # 1 only, so element 2 is in no body).
  seed quoted axi.nml axi.inp
  sed -i 's/^\*ELEMENT, TYPE=CAX8, ELSET=disc$/*ELEMENT, TYPE=CAX8, ELSET="disc"/' "$m"
  printf '*ELSET, ELSET=disc\n1\n' >> "$m"
  try quoted axi.nml 0 --check
  if ! grep -q "no &body" "$work/quoted/stderr.txt"; then
    pass "'disc' is the quoted set of both elements"
  else fail "'disc' did not find the quoted set \"disc\""; fi
  seed unquoted axi.nml axi.inp
  sed -i 's/^\*ELEMENT, TYPE=CAX8, ELSET=disc$/*ELEMENT, TYPE=CAX8, ELSET="disc"/' "$m"
  printf '*ELSET, ELSET=disc\n1\n' >> "$m"
  sed -i "s/elset = 'disc'/elset = 'Disc'/" "$d"
  try unquoted axi.nml 2 --check
  says unquoted "1 mesh elements belong to no &body" "which is in no &body"
  # A quoted label keeps its case: the deck's other case is refused with
  # the mesh's spelling.
  seed case axi.nml axi.inp
  sed -i 's/^\*SURFACE, NAME=punch_top,/*SURFACE, NAME="Punch_Top",/' "$m"
  try case axi.nml 2 --check
  says case "&boundary #2" "set 'punch_top' not found" 'the mesh has "Punch_Top"' "double quotes" \
    "surfaces there: disc_top, disc_bottom, disc_right, punch_bottom, \"Punch_Top\""
  ;;
names_gmsh)
  # A Gmsh mesh's names compare exactly; the near miss is named.
  seed slave loop.nml loop.msh
  sed -i "s/slave = 'pin_surface'/slave = 'Pin_Surface'/" "$d"
  try slave loop.nml 2 --check
  says slave "&contact_pair #1" "'Pin_Surface' not found in mesh" "case-sensitive" "'pin_surface'" \
    "surfaces there: plate_edge, hole, pin_surface"
  seed elset loop.nml loop.msh
  sed -i "s/elset = 'pin'/elset = 'PIN'/" "$d"
  try elset loop.nml 2 --check
  says elset "&body 'pin'" "'PIN' not found" "the mesh has 'pin', an element set"
  # Two groups whose names differ only by case are two groups.
  seed two loop.nml loop.msh
  sed -i 's/^1 1 "plate_edge"$/1 1 "HOLE"/' "$m"
  sed -i "s/set = 'plate_edge'/set = 'HOLE'/" "$d"
  try two loop.nml 0 --check
  ;;
names_kind)
  # A name of the wrong kind: the message says what it is.
  seed elset_slave axi.nml axi.inp
  sed -i "s/slave = 'punch_bottom'/slave = 'disc_row'/" "$d"
  try elset_slave axi.nml 2 --check
  says elset_slave "'disc_row' is not a surface in mesh" "it is an element set (Abaqus: *ELSET" \
    "surfaces there: disc_top, disc_bottom, disc_right, punch_bottom, punch_top"
  seed nset_load axi.nml axi.inp
  sed -i "s/set = 'punch_top'/set = 'punch_axis'/" "$d"
  try nset_load axi.nml 2 --check
  says nset_load "&boundary #2" "'punch_axis' is not a surface" "it is a node set (Abaqus: *NSET"
  seed phys_surface loop.nml loop.msh
  sed -i "s/master = 'hole'/master = 'plate'/" "$d"
  try phys_surface loop.nml 2 --check
  says phys_surface "'plate' is not a surface" "element set (Gmsh: a physical surface, dimension 2)" \
    "a Gmsh physical curve"
  seed phys_point loop.nml loop.msh
  sed -i "s/elset = 'plate'/elset = 'pin_center'/" "$d"
  try phys_point loop.nml 2 --check
  says phys_point "&body 'plate'" "'pin_center' is not an element set" "node set (Gmsh: a physical point"
  # More than 20 surfaces: the list is cut and the others counted.
  seed many axi.nml axi.inp
  i=0
  while [ $i -lt 30 ]; do
    i=$((i + 1))
    printf '*SURFACE, NAME=extra_%02d, TYPE=ELEMENT\n11, S2\n' "$i" >> "$m"
  done
  sed -i "s/slave = 'punch_bottom'/slave = 'punch_side'/" "$d"
  try many axi.nml 2 --check
  says many "extra_14, extra_15, ... (15 more)"
  if grep -q "extra_16" "$work/many/stderr.txt"; then fail "the list is not cut after 20 names"
  else pass "the list stops at 20 names"; fi
  ;;
friction_bound)
  # friction and tolerance out of bounds: exit 2, file, line and key named.
  seed above axi.nml axi.inp
  sed -i "s/friction = 0.2/friction = 1000.5/" "$d"
  try above axi.nml 2 --check
  says above "axi.nml:39: &contact_pair" "key 'friction' = 1000.5" "at most 1000.0" "friction = 1000.0 for contact"
  seed inf axi.nml axi.inp
  sed -i "s/friction = 0.2/friction = 1e300/" "$d"
  try inf axi.nml 2 --check
  says inf "key 'friction'"
  seed tol axi.nml axi.inp
  sed -i "s/friction = 0.2/friction = 0.2, tolerance = 1.0/" "$d"
  try tol axi.nml 2 --check
  says tol "axi.nml:39" "key 'tolerance' = 1.0" "> 0 and < 1"
  # A tolerance in range is taken without a warning (it bounds the residual
  # of (19) at which a solve whose sets do not settle ends) and --check
  # echoes it.
  seed tol_ok axi.nml axi.inp
  sed -i "s/friction = 0.2/friction = 0.2, tolerance = 1e-8/" "$d"
  try tol_ok axi.nml 0 --check
  if grep -q "tolerance" "$work/tol_ok/stderr.txt"; then fail "tol_ok: a message about the tolerance"; \
    sed 's/^/    /' "$work/tol_ok/stderr.txt" >&2
  else pass "tol_ok: no message about the tolerance"; fi
  if grep -q "tolerance = 1.0*E-0*8\|tolerance = 1e-0*8\|tolerance = 1.0e-0*8" "$work/tol_ok/stdout.txt"; then
    pass "tol_ok: --check echoes the tolerance"
  else fail "tol_ok: --check does not echo tolerance = 1e-8"; grep -i tolerance "$work/tol_ok/stdout.txt" >&2; fi
  ;;
friction_large)
  # friction = 1000 (the bound) is accepted with a warning and runs: the
  # slider, pulled by 4 N/mm under 10 N/mm, sticks (no slipping node,
  # tangential force = the pull, every solve converged), node-to-segment
  # and mortar P1 alike.
  for deck in q4_nts_mu030 q4_mortar_p1_mu030; do
    mkdir -p "$work/$deck"
    cp "$sliding/sliding_q4.msh" "$work/$deck/"
    sed 's/friction = 0.3/friction = 1000.0/' "$sliding/$deck.nml" > "$work/$deck/$deck.nml"
    try "$deck" "$deck.nml" 0 -o out
    says "$deck" "friction = 1000.0 is above the Coulomb coefficients"
    if grep -q ", 0 unconverged steps" "$work/$deck/out/$deck.log"; then pass "$deck: every solve converged"
    else fail "$deck: unconverged contact solves"; fi
    h=$work/$deck/out/$deck.history.txt
    tcol=$(awk '$1 == "#" && $3 == "contact1_T" { print $2; exit }' "$h")
    scol=$(awk '$1 == "#" && $3 == "contact1_slip" { print $2; exit }' "$h")
    if [ -z "$tcol" ] || [ -z "$scol" ]; then fail "$deck: no contact1_T / contact1_slip column"; continue; fi
    # from the end of the pull (t = 2e-5) on: no slip; at the end T = -4 +- 1e-3
    awk -v t="$tcol" -v s="$scol" '$1 !~ /^#/ && $1 >= 2.0e-5 && $s != 0 { bad = 1 }
      $1 !~ /^#/ { last = $t } END { exit !(bad == 0 && last + 4.0 < 1.0e-3 && last + 4.0 > -1.0e-3) }' "$h" \
      && pass "$deck: sticks, T = -4 at the end" || fail "$deck: slips or T is not the pull (-4)"
  done
  ;;
*)
  echo "input_cases.sh: unknown case $case_name" >&2
  exit 2
  ;;
esac

[ "$failures" -eq 0 ] || exit 1
exit 0
