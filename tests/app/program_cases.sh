#!/bin/sh
# Integration tests of the raccord program: one case per CTest entry.
#
#   sh program_cases.sh CASE RACCORD DATA_DIR WORK_DIR [EXTRA]
#
# CASE      one of the names in the `case` at the bottom
# RACCORD   the raccord executable
# DATA_DIR  tests/data/app (scene decks and the coarse bar mesh)
# WORK_DIR  a folder of this case alone; emptied first, the run's current directory
# EXTRA     case `version`: the expected version; case `check`: the bar deck;
#           case `plot_history`: the postproc folder
#
# Needs only POSIX sh, awk, find, grep and h5dump (Debian hdf5-tools).
# Exit 0 = pass, 1 = fail (every failed check is printed), 77 = skipped.
set -u

case_name=$1
raccord=$2
data=$3
work=$4
extra=${5:-}

failures=0
fail() {
  echo "FAIL [$case_name]: $*" >&2
  failures=$((failures + 1))
}
pass() { echo "ok   [$case_name]: $*"; }

# Run raccord with the given arguments in $work; keep exit code, stdout, stderr.
run() {
  (cd "$work" && "$raccord" "$@" > "$work/stdout.txt" 2> "$work/stderr.txt")
  code=$?
}

expect_code() {
  if [ "$code" -eq "$1" ]; then pass "exit code $code"; else fail "exit code $code, expected $1"; fi
}

# expect_text FILE TEXT [what]: FILE contains TEXT (fixed string).
expect_text() {
  if grep -qF -- "$2" "$1"; then pass "${3:-$(basename "$1")} has '$2'"
  else fail "${3:-$(basename "$1")} lacks '$2'"; fi
}

expect_file() {
  if [ -s "$1" ]; then pass "file $(basename "$1") written"; else fail "file $1 missing or empty"; fi
}

# No result file of any kind (final, .part or .incomplete) anywhere in $work.
expect_no_results() {
  found=$(find "$work" -type f \( -name '*.h5' -o -name '*.h5.part' -o -name '*.xmf' \
    -o -name '*.history.txt' -o -name '*.history.txt.part' -o -name '*.incomplete.*' \) -print)
  if [ -z "$found" ]; then pass "no result file written"; else fail "result files written: $found"; fi
}

# No file whose name says "complete": no final .h5, .xmf or .history.txt.
expect_nothing_complete() {
  found=$(find "$work" -type f \( -name '*.h5' -o -name '*.xmf' -o -name '*.history.txt' \) \
    ! -name '*.incomplete.*' -print)
  if [ -z "$found" ]; then pass "no complete-looking result file"; else fail "complete-looking files left: $found"; fi
}

# h5_status FILE: the string of the dataset /status.
h5_status() {
  h5dump -d /status "$1" 2>/dev/null | awk -F'"' '/\(0\):/ { print $2; exit }'
}

# history_column FILE NAME: the column number of NAME in a history header ('# N name').
history_column() {
  awk -v name="$2" '$1 == "#" && $3 == name { print $2; exit }' "$1"
}

# bad_deck DECK TEXT...: exit 2, each TEXT (where: deck and line, or file;
# what: key, group, set) on stderr, no result file.
bad_deck() {
  deck=$1
  shift
  cp "$data/$deck" "$data/bar_coarse.msh" "$work/"
  run -o out "$deck"
  expect_code 2
  for what in "$@"; do expect_text "$work/stderr.txt" "$what" "stderr"; done
  expect_no_results
}

rm -rf "$work"
mkdir -p "$work" || { echo "cannot create $work" >&2; exit 1; }

case "$case_name" in
help)
  for opt in --help -h; do
    run "$opt"
    expect_code 0
    expect_text "$work/stdout.txt" 'usage: raccord [options] SCENE' "stdout of $opt"
    for word in --check --output --quiet --verbose --version --wall-clock --restart 'exit codes: 0 success, 1 bad command line, 2 bad scene or mesh, 3 numerical failure' \
        OMP_NUM_THREADS RACCORD_WALLCLOCK_SECONDS 'default' 'results/NAME' '5 stopped at the wall-clock limit'; do
      expect_text "$work/stdout.txt" "$word" "stdout of $opt"
    done
  done
  ;;

version)
  for opt in --version -V; do
    run "$opt"
    expect_code 0
    line=$(cat "$work/stdout.txt")
    if [ "$line" = "raccord $extra" ]; then pass "$opt prints '$line'"
    else fail "$opt prints '$line', expected 'raccord $extra'"; fi
  done
  ;;

usage_errors)
  # Each bad command line exits 1, names the problem on stderr and writes nothing.
  run
  expect_code 1
  expect_text "$work/stderr.txt" 'no scene given' "stderr (no argument)"
  run --frobnicate "$data/bar_coarse.nml"
  expect_code 1
  expect_text "$work/stderr.txt" "unknown option '--frobnicate'" "stderr (unknown option)"
  run "$data/bar_coarse.nml" "$data/bar_coarse.nml"
  expect_code 1
  expect_text "$work/stderr.txt" 'one scene per run' "stderr (two scenes)"
  run "$data/bar_coarse.nml" --output
  expect_code 1
  expect_text "$work/stderr.txt" "option --output needs a folder" "stderr (--output without folder)"
  # an option with a value given twice (a job script's -o beside a user's)
  run -o "$work/a" --output "$work/b" "$data/bar_coarse.nml"
  expect_code 1
  expect_text "$work/stderr.txt" "option --output is given twice (the first: '$work/a')" "stderr (-o twice)"
  run --wall-clock 100 --wall-clock 200 "$data/bar_coarse.nml"
  expect_code 1
  expect_text "$work/stderr.txt" "option --wall-clock is given twice" "stderr (--wall-clock twice)"
  run --restart "$work/a/x.checkpoint.h5" --restart "$work/b/x.checkpoint.h5"
  expect_code 1
  expect_text "$work/stderr.txt" "option --restart is given twice" "stderr (--restart twice)"
  left=$(find "$work" -mindepth 1 ! -name stdout.txt ! -name stderr.txt -print)
  if [ -z "$left" ]; then pass "nothing written"; else fail "files written: $left"; fi
  ;;

check)
  # --check on the shipped bar example, run from an empty folder: the plan,
  # the effects, the cost and the resolved scene on stdout; no result file
  # and no output folder (the deck's default output_dir is results/bar_wave).
  run --check "$extra"
  expect_code 0
  out=$work/stdout.txt
  expect_text "$out" 'mesh    '
  expect_text "$out" '505 nodes, 400 elements'
  expect_text "$out" 'body    bar: 400 elements (Q4)'
  expect_text "$out" 'effects elasticity (400 Q4 + 0 Q8), supports (10 dofs), surface loads (1), contact pairs: none'
  expect_text "$out" 'cost    about '
  expect_text "$out" 'estimated run time'
  # The resolved scene: every key with its value, the mesh path made absolute.
  expect_text "$out" '! Scene resolved by raccord'
  expect_text "$out" "output_dir = 'results/bar_wave'"
  expect_text "$out" 'input/examples/bar.msh'
  expect_text "$out" "pressure = 100.0"
  expect_text "$out" 'safety = 0.9'
  expect_text "$out" 'frames = 30'
  # The time line: stable dt = h/c for this 1D mesh (h = 1 mm, c = sqrt(E/rho)),
  # dt = t_end/steps with steps = ceil(t_end/(0.9 dt_stable)) (doc/theory.md, 3).
  awk '
    /^time / {
      for (i = 1; i <= NF; i++) {
        if ($i == "t_end") t_end = $(i + 2) + 0
        if ($i == "stable" && $(i + 1) == "dt") dts = $(i + 3) + 0
        if ($i == "dt" && $(i - 1) != "stable") dt = $(i + 2) + 0
        if ($i == "steps") steps = $(i - 1) + 0
      }
      found = 1
    }
    END {
      if (!found) { print "FAIL: no time line"; exit 1 }
      bad = 0
      h_over_c = 1.0 / sqrt(200000.0 / 7.8e-9)
      if ((dts - h_over_c) ^ 2 > (1e-5 * h_over_c) ^ 2) { print "FAIL: stable dt " dts " is not h/c = " h_over_c; bad = 1 }
      n = t_end / (0.9 * dts); want = (n == int(n)) ? n : int(n) + 1
      if (steps != want) { print "FAIL: " steps " steps, expected ceil(t_end/(0.9 dt_stable)) = " want; bad = 1 }
      if ((dt - t_end / steps) ^ 2 > (1e-5 * dt) ^ 2) { print "FAIL: dt " dt " is not t_end/steps = " t_end / steps; bad = 1 }
      if (!bad) print "stable dt " dts " = h/c " h_over_c ", " steps " steps, dt " dt
      exit bad
    }' "$out" && pass "time line consistent" || fail "time line inconsistent"
  left=$(find "$work" -mindepth 1 ! -name stdout.txt ! -name stderr.txt -print)
  if [ -z "$left" ]; then pass "--check wrote nothing"; else fail "--check wrote: $left"; fi
  ;;

run)
  # A real run of the coarse bar into a folder given with --output.
  run --output out "$data/bar_coarse.nml"
  expect_code 0
  stem=$work/out/bar_coarse
  for ext in h5 xmf history.txt log; do expect_file "$stem.$ext"; done
  left=$(find "$work" -name '*.part' -o -name '*.incomplete*')
  if [ -z "$left" ]; then pass "no .part or .incomplete file"; else fail "left behind: $left"; fi
  status=$(h5_status "$stem.h5")
  if [ "$status" = complete ]; then pass "/status is '$status'"; else fail "/status is '$status', expected 'complete'"; fi
  expect_text "$stem.xmf" 'bar_coarse.h5:/mesh/x' "the XDMF"
  expect_text "$stem.log" 'time    t_end = 3e-05' "the log"
  expect_text "$stem.log" 'info [raccord] done: 34 steps' "the log"
  expect_text "$work/stdout.txt" "results: out/bar_coarse.h5" "stdout"
  # History: one row per step (history_every = 1), 34 steps, last time = t_end,
  # |energy_balance_rel| < 1e-10 on every row, applied force right_Fx = -p H = -1000.
  hist=$stem.history.txt
  cb=$(history_column "$hist" energy_balance_rel)
  ct=$(history_column "$hist" time)
  cf=$(history_column "$hist" right_Fx)
  if [ -z "$cb" ] || [ -z "$ct" ] || [ -z "$cf" ]; then
    fail "history header lacks time, energy_balance_rel or right_Fx"
  else
    awk -v cb="$cb" -v ct="$ct" -v cf="$cf" '
      /^#/ { next }
      {
        rows++
        b = $cb < 0 ? -$cb : $cb
        if (b > worst) worst = b
        if (($cf + 1000) ^ 2 > (1e-12 * 1000) ^ 2) badf++
        last = $ct
      }
      END {
        bad = 0
        if (rows != 35) { print "FAIL: " rows " history rows, expected 35"; bad = 1 }
        if (worst >= 1e-10) { print "FAIL: |energy_balance_rel| reaches " worst; bad = 1 }
        if (badf) { print "FAIL: right_Fx differs from -1000 on " badf " rows"; bad = 1 }
        if ((last - 3e-5) ^ 2 > (1e-12 * 3e-5) ^ 2) { print "FAIL: last time " last ", expected 3e-5"; bad = 1 }
        if (!bad) print rows " rows, max |energy_balance_rel| = " worst ", last time " last
        exit bad
      }' "$hist" && pass "history checks" || fail "history checks"
  fi
  # The HDF5 copy of the history has as many rows as the text file.
  rows=$(h5dump -H -d /history "$stem.h5" 2>/dev/null | awk -F'[(),]' '/DATASPACE/ { gsub(/ /, "", $2); print $2; exit }')
  if [ "$rows" = 35 ]; then pass "/history has 35 rows"; else fail "/history has '$rows' rows, expected 35"; fi
  ;;

quasi_static)
  # Damped quasi-static compression (bar_static.nml): after the ramp the
  # bar settles to the static solution, exact for Q4 in uniaxial stress:
  # internal energy p^2 A L / (2 E) = 25 N mm, clamp reaction p H = 1000 N.
  # The held load lasts 31.8/omega_1 with every mode decaying at least like
  # exp(-omega_1 t), so what is left of the vibration is ~1e-13: assert 1e-9.
  run --quiet --output out "$data/bar_static.nml"
  expect_code 0
  hist=$work/out/bar_static.history.txt
  ck=$(history_column "$hist" kinetic)
  ci=$(history_column "$hist" internal)
  cd=$(history_column "$hist" damping_work)
  cb=$(history_column "$hist" energy_balance_rel)
  cr=$(history_column "$hist" left_Rx)
  awk -v ck="$ck" -v ci="$ci" -v cd="$cd" -v cb="$cb" -v cr="$cr" '
    function rel(a, e) { return (a - e) < 0 ? (e - a) / e : (a - e) / e }
    /^#/ { next }
    { b = $cb < 0 ? -$cb : $cb; if (b > worst) worst = b; k = $ck; u = $ci; d = $cd; r = $cr }
    END {
      bad = 0
      if (rel(u, 25) > 1e-9) { print "FAIL: internal energy " u ", expected 25"; bad = 1 }
      if (rel(r, 1000) > 1e-9) { print "FAIL: clamp reaction " r ", expected 1000"; bad = 1 }
      if ((k < 0 ? -k : k) > 1e-12 * u) { print "FAIL: kinetic energy " k " not negligible"; bad = 1 }
      if (d <= 0) { print "FAIL: damping dissipated " d; bad = 1 }
      if (worst >= 1e-10) { print "FAIL: |energy_balance_rel| reaches " worst; bad = 1 }
      if (!bad) print "internal " u ", reaction " r ", kinetic " k ", damping " d ", max |balance rel| " worst
      exit bad
    }' "$hist" && pass "static state reached" || fail "static state not reached"
  ;;

quiet)
  # --quiet: nothing on stdout or stderr; the log still has everything.
  run --quiet --output out "$data/bar_coarse.nml"
  expect_code 0
  if [ ! -s "$work/stdout.txt" ] && [ ! -s "$work/stderr.txt" ]; then pass "silent"
  else fail "--quiet printed: $(cat "$work/stdout.txt" "$work/stderr.txt")"; fi
  expect_text "$work/out/bar_coarse.log" 'effects elasticity' "the log"
  expect_text "$work/out/bar_coarse.log" 'info [raccord] done:' "the log"
  ;;

bad_unknown_key)   bad_deck bad_unknown_key.nml 'bad_unknown_key.nml:10:' "unknown key 'yong'" ;;
bad_unknown_group) bad_deck bad_unknown_group.nml 'bad_unknown_group.nml:19:' "unknown group '&material'" ;;
bad_missing_mesh)  bad_deck bad_missing_mesh.nml "$work/no_such_mesh.msh" 'does not exist' ;;
bad_unknown_set)   bad_deck bad_unknown_set.nml 'bad_unknown_set.nml' "&boundary #1 (set 'lefft')" 'bar_coarse.msh' ;;
bad_dt_unstable)   bad_deck bad_dt_unstable.nml 'bad_dt_unstable.nml' '&time dt = 1e-05 exceeds the stable time step' ;;

output_not_creatable)
  # The output folder would lie under a regular file: exit 4, nothing that
  # looks like a result (root can write anywhere, so no permission test).
  : > "$work/plain_file"
  run --output plain_file/out "$data/bar_coarse.nml"
  expect_code 4
  expect_text "$work/stderr.txt" 'plain_file/out' "stderr"
  expect_nothing_complete
  expect_no_results
  ;;

nonfinite)
  # An amplitude that ramps the pressure to 1e300 within the run: the
  # displacements overflow. Without floating-point traps the energy guard
  # stops the run: exit 3, *.incomplete.* files, the reason in /status.
  cp "$data/nonfinite.nml" "$data/bar_coarse.msh" "$work/"
  run --output out nonfinite.nml
  expect_code 3
  expect_text "$work/stderr.txt" 'non-finite energy at step' "stderr"
  stem=$work/out/nonfinite
  for f in "$stem.incomplete.h5" "$stem.incomplete.xmf" "$stem.history.incomplete.txt"; do expect_file "$f"; done
  expect_nothing_complete
  left=$(find "$work" -name '*.part')
  if [ -z "$left" ]; then pass "no .part file"; else fail "left behind: $left"; fi
  status=$(h5_status "$stem.incomplete.h5")
  case "$status" in
    'incomplete: non-finite energy at step'*) pass "/status is '$status'" ;;
    *) fail "/status is '$status', expected 'incomplete: non-finite energy at step ...'" ;;
  esac
  ;;

nonfinite_initial)
  # A finite but absurd initial velocity (1e300 mm/s) squares to Inf in the
  # kinetic energy of t = 0: exit 3, and the message blames the scene's
  # magnitudes (nothing was integrated yet), not the time step.
  cp "$data/nonfinite.nml" "$data/bar_coarse.msh" "$work/"
  sed -e 's/^&amplitude.*$//' -e 's/, amplitude = .blow_up.//' \
    -e "s/hypothesis = 'plane_stress'/hypothesis = 'plane_stress', velocity = 1.0e300, 0.0/" \
    "$work/nonfinite.nml" > "$work/initial.nml"
  run --output out initial.nml
  expect_code 3
  expect_text "$work/stderr.txt" 'non-finite energy at step 0' "stderr"
  expect_text "$work/stderr.txt" 'initial state already overflows' "stderr"
  expect_nothing_complete
  ;;

nonfinite_trapped)
  # The same scene in a build that traps overflow (Debug): the process dies
  # on SIGFPE where the overflow happens; it must not leave a file that
  # looks complete, and what it wrote stays under the .part names.
  cp "$data/nonfinite.nml" "$data/bar_coarse.msh" "$work/"
  run --output out nonfinite.nml
  if [ "$code" -ne 0 ]; then pass "exit code $code (non-zero)"; else fail "exit code 0 for an overflowing run"; fi
  expect_nothing_complete
  expect_file "$work/out/nonfinite.h5.part"
  ;;

plot_history)
  # postproc/plot-history.sh on the coarse bar's history: non-empty PNG and
  # PDF files (checked by their magic bytes); a bad format is refused.
  command -v gnuplot > /dev/null 2>&1 || { echo "gnuplot not installed: skipped"; exit 77; }
  run --quiet --output out "$data/bar_coarse.nml"
  expect_code 0
  for format in png pdf; do
    (cd "$work" && sh "$extra/plot-history.sh" out/bar_coarse "$format" > plot.txt 2>&1)
    code=$?
    expect_code 0
    for plot in energy reactions; do
      f=$work/out/bar_coarse.$plot.$format
      expect_file "$f"
      magic=$(od -An -c -N4 "$f" 2>/dev/null | tr -d ' ')
      case "$format:$magic" in
        png:211PNG|pdf:%PDF) pass "$(basename "$f") is a $format file" ;;
        *) fail "$(basename "$f") does not start like a $format file: '$magic'" ;;
      esac
    done
  done
  (cd "$work" && sh "$extra/plot-history.sh" out/bar_coarse svg > plot.txt 2>&1)
  code=$?
  expect_code 2
  ;;

check_history)
  # The cost line counts the history rows (raccord_step_trial
  # time_history_row): on the coarse bar over 3e-3 s (3400 steps),
  # written every step, the history share of the
  # estimate is the rows' ratio (steps + 2 against steps/100 + 2) times
  # that of history_every = 100, within a factor 3 (two separate timings
  # of a row). Before, the estimate had no history share at all, and a
  # scene writing 10^6 rows ran ten times its estimate.
  cp "$data/bar_coarse.nml" "$data/bar_coarse.msh" "$work/"
  for every in 1 100; do
    sed -e "s/history_every = 1\$/history_every = $every/" -e "s/t_end = 3.0e-5/t_end = 3.0e-3/" \
      "$work/bar_coarse.nml" > "$work/bar_$every.nml"
    run --check "bar_$every.nml"
    expect_code 0
    awk '/^cost    estimated/ { for (i = 1; i < NF; i++) if ($i == "history") print $(i+1) }' "$work/stdout.txt" \
      > "$work/history_$every.txt"
    awk '/^time / { for (i = 1; i < NF; i++) if ($(i+1) == "steps") print $i }' "$work/stdout.txt" > "$work/steps.txt"
  done
  h1=$(cat "$work/history_1.txt"); h100=$(cat "$work/history_100.txt"); n=$(cat "$work/steps.txt")
  if awk -v a="${h1:-0}" -v b="${h100:-0}" -v n="${n:-0}" 'BEGIN {
      r = (n + 2)/(int(n/100) + 2); q = (b > 0) ? a/b : 0
      printf "history %s s (every step), %s s (every 100), %d steps: ratio %.3g, rows %.3g\n", a, b, n, q, r
      exit !(n > 1000 && a > 0 && b > 0 && q > r/3 && q < 3*r) }'; then
    pass "the history share scales with the rows: $h1 s and $h100 s over $n steps"
  else fail "history share '$h1' s (every step), '$h100' s (every 100), $n steps: $(grep '^cost    estimated' "$work/stdout.txt")"; fi
  ;;

check_contact)
  # --check on a contact deck (EXTRA): the plan names the matching and the
  # multiplier space without padding, and the cost line times the contact
  # work of the real step (a positive contact share in the estimate).
  run --check "$extra"
  expect_code 0
  expect_text "$work/stdout.txt" ', mortar matching, P1 multipliers (linear, at the slave nodes), mu = 0,' "the plan"
  if grep -q 'mortar  ' "$work/stdout.txt"; then fail "blank padding after the method: $(grep 'mortar  ' "$work/stdout.txt")"
  else pass "no blank padding in the plan"; fi
  contact=$(awk '/^cost/ { for (i = 1; i < NF; i++) if ($i == "contact" && $(i+2) == "s,") print $(i+1) }' "$work/stdout.txt")
  total=$(awk '/^cost/ { for (i = 1; i < NF; i++) if ($i == "time" && $(i-1) == "run") print $(i+1) }' "$work/stdout.txt")
  if awk -v c="${contact:-0}" -v t="${total:-0}" 'BEGIN { exit !(c > 0 && t > c) }'; then
    pass "estimate $total s includes contact $contact s"
  else fail "cost line without a contact share: $(grep '^cost' "$work/stdout.txt")"; fi
  # The estimate lies in its range (contact zone of t = 0 .. engaged).
  if awk '/^cost    estimated/ { for (i = 1; i < NF; i++) { if ($i == "time") e = $(i+1); if ($i == "between") lo = $(i+1); if ($i == "and") hi = $(i+1) } }
      END { exit !(lo > 0 && lo <= e && e <= hi && hi > lo) }' "$work/stdout.txt"; then
    pass "estimate within its range: $(grep '^cost    estimated' "$work/stdout.txt" | sed 's/.*between/between/')"
  else fail "estimate outside its range: $(grep '^cost    estimated' "$work/stdout.txt")"; fi
  # The contact work is also timed with the slave nodes the prescribed
  # motion can reach placed on the master (raccord_step_trial). The disc
  # (R = 1 mm, centre (0, 1)) touches the block top y = 0 at x = 0; driven
  # down by d, a block-top node at x (spacing 0.05 mm for |x| < 0.7) is
  # within reach when its distance to the arc, sqrt(x^2 + R^2) - R, is at
  # most d + the search distance. The node at x = 0 already touches (timed
  # at t = 0). For d = 0.05 and d = 0 the nearest node outside the bound is
  # 0.02 mm beyond it, the nearest inside 0.006 mm: ten times the chords'
  # sagitta (7.5e-4 mm on this mesh).
  deck=$(basename "$extra")
  cp "$(dirname "$extra")"/paper_q4*.msh "$work/"
  # A mortar multiplier space asked of node-to-segment: said, not ignored.
  sed -e "s/method = 'mortar', multiplier = 'P1'/method = 'node_to_segment', multiplier = 'P0'/" "$extra" > "$work/$deck"
  run --check "$deck"
  expect_code 0
  expect_text "$work/stderr.txt" "multiplier = 'P0' has no effect with node-to-segment" "the warning on P0 with node-to-segment"
  for d in 0.05 0.0; do
    sed "s/value = 0.0, -0.1581/value = 0.0, -$d/" "$extra" > "$work/$deck"
    run --check "$deck"
    expect_code 0
    engaged=$(awk '/^cost    contact/ { for (i = 1; i < NF; i++) if ($i == "with") print $(i+1) }' "$work/stdout.txt")
    reach=$(awk '/search distance/ { print $NF }' "$work/stdout.txt")
    if awk -v n="${engaged:--1}" -v r="${reach:-0}" -v d="$d" 'BEGIN {
        D = d + r; m = 0
        for (k = -13; k <= 13; k++) { x = 0.05*k; if (k != 0 && sqrt(x*x + 1) - 1 <= D) m++ }
        printf "drive %s: engaged %d, closed form %d (search distance %g)\n", d, n, m, r
        exit !(r > 0 && n == m && sqrt(0.7^2 + 1) - 1 > D) }'; then
      pass "drive $d: $engaged slave nodes engaged, as the closed form"
    else fail "drive $d: engaged '$engaged', search distance '$reach': $(grep '^cost    contact' "$work/stdout.txt")"; fi
  done
  ;;

edge_multipliers)
  # &contact_pair edge_multipliers (EXTRA: the Fig. 4(b) Q8 deck, which
  # selects 'tangential_corners'; base: the same deck with the key
  # removed): 'corners' and 'tangential_corners' reach the pair (the plan
  # says so), and are refused with node-to-segment, with the weighted
  # conditions, 'tangential_corners' with the dual basis, and an unknown
  # value, naming the key; on a Q4 slave they are said to have no effect,
  # and 'tangential_corners' without friction too.
  deck=$(basename "$extra")
  cp "$(dirname "$extra")"/paper_q8.msh "$(dirname "$extra")"/paper_q4.msh "$work/"
  grep -q "edge_multipliers = 'tangential_corners'" "$extra" && pass "the Fig. 4(b) deck selects tangential_corners" \
    || fail "the Fig. 4(b) deck does not select tangential_corners"
  base="$work/base.nml"
  sed -e "/edge_multipliers = 'tangential_corners'/d" "$extra" > "$base"
  sed -e "s/method = 'mortar', multiplier = 'P1'/method = 'mortar', multiplier = 'P1', edge_multipliers = 'corners'/" "$base" > "$work/$deck"
  run --check "$deck"
  expect_code 0
  expect_text "$work/stdout.txt" "P1 multipliers (linear over each quadratic slave edge, at its corners)" "the plan names the corner multipliers"
  cp "$base" "$work/$deck"
  run --check "$deck"
  expect_code 0
  if grep -q "at its corners\|at the corners" "$work/stdout.txt"; then fail "the default plan speaks of corner multipliers"
  else pass "the default keeps a multiplier at every edge node"; fi
  cp "$extra" "$work/$deck"
  run --check "$deck"
  expect_code 0
  expect_text "$work/stdout.txt" "P1 multipliers (linear, at the slave nodes), the tangential ones at the corners of each quadratic slave edge only" "the plan names the tangential corner multipliers"
  for bad in "method = 'node_to_segment', multiplier = 'P1', edge_multipliers = 'corners'" \
             "method = 'mortar', multiplier = 'P1', conditions = 'weighted', edge_multipliers = 'corners'" \
             "method = 'node_to_segment', multiplier = 'P1', edge_multipliers = 'tangential_corners'" \
             "method = 'mortar', multiplier = 'P1', conditions = 'weighted', edge_multipliers = 'tangential_corners'" \
             "method = 'mortar', multiplier = 'dual', edge_multipliers = 'tangential_corners'" \
             "method = 'mortar', multiplier = 'P1', edge_multipliers = 'middle'"; do
    sed -e "s/method = 'mortar', multiplier = 'P1'/$bad/" "$base" > "$work/$deck"
    run --check "$deck"
    expect_code 2
    expect_text "$work/stderr.txt" "edge_multipliers" "refused naming the key: $bad"
  done
  sed -e "s/method = 'mortar', multiplier = 'P1'/method = 'mortar', multiplier = 'P1', edge_multipliers = 'corners'/" \
    -e "s/paper_q8.msh/paper_q4.msh/" "$base" > "$work/$deck"
  run --check "$deck"
  expect_code 0
  expect_text "$work/stderr.txt" "edge_multipliers = 'corners' has no effect on a slave of 2-node edges" "the warning on a Q4 slave"
  sed -e "s/paper_q8.msh/paper_q4.msh/" "$extra" > "$work/$deck"
  run --check "$deck"
  expect_code 0
  expect_text "$work/stderr.txt" "edge_multipliers = 'tangential_corners' has no effect on a slave of 2-node edges" "the warning on a Q4 slave (tangential)"
  sed -e "s/friction = 0.2/friction = 0.0/" "$extra" > "$work/$deck"
  run --check "$deck"
  expect_code 0
  expect_text "$work/stderr.txt" "edge_multipliers = 'tangential_corners' has no effect without friction" "the warning without friction"
  ;;

progress_live)
  # Progress lines reach a redirected stdout while the run goes on (stdout
  # is flushed line by line), and the log lines carry a time stamp and the
  # host. EXTRA: a paper deck that runs for several seconds; it is stopped
  # as soon as its log shows a progress line.
  deck=$(basename "$extra")
  cp "$extra" "$work/$deck"
  cp "$(dirname "$extra")"/paper_q4*.msh "$work/"
  if grep -q '^&output' "$work/$deck"; then
    sed -i 's/^&output/\&output progress_seconds = 0.2,/' "$work/$deck"
  else
    printf '&output progress_seconds = 0.2 /\n' >> "$work/$deck"
  fi
  log=$work/out/${deck%.nml}.log
  (cd "$work" && exec "$raccord" --output out "$deck" > "$work/stdout.txt" 2> "$work/stderr.txt") &
  pid=$!
  n=0
  while [ $n -lt 300 ] && ! grep -q 'info \[progress\]' "$log" 2>/dev/null; do
    sleep 0.1
    n=$((n + 1))
  done
  # The log line is written after the stdout line: both must be there now.
  if grep -q 'info \[progress\]' "$log" 2>/dev/null; then pass "the log shows a progress line"
  else fail "no progress line in the log after 30 s"; fi
  if kill -0 "$pid" 2>/dev/null; then pass "the run is still going"; else fail "the run ended before the check"; fi
  expect_text "$work/stdout.txt" 'info [progress] step ' "the redirected stdout while running"
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  if grep -qE '^[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2} info \[raccord\] raccord .*, host ' "$log"; then
    pass "the first log line has a time stamp and the host"
  else fail "first log line: $(head -n 1 "$log")"; fi
  ;;

huge_values)
  # Values of 1e100 and above are legal reals in a deck; the report must
  # print them (the plan's load line shows -1e+151 for this scene).
  cp "$data/huge_pressure.nml" "$data/bar_coarse.msh" "$work/"
  run --check huge_pressure.nml
  expect_code 0
  if grep -qE 'total force at amplitude 1 = \(-1(\.0*)?e\+151, 0\)' "$work/stdout.txt"; then pass "load line shows -1e+151"
  else fail "load line: $(grep '^load' "$work/stdout.txt")"; fi
  expect_text "$work/stdout.txt" 'pressure = 1.0E+150' "stdout"
  ;;

verify)
  # raccord --verify: a complete results file reads back intact (exit 0);
  # one byte changed in the stored text of /scene (found by its content) is
  # caught by that text's crc32 attribute (exit 2, the dataset named); a
  # file that is not HDF5, a missing file and --verify with a scene are
  # refused.
  run --output out "$data/bar_coarse.nml"
  expect_code 0
  h5=$work/out/bar_coarse.h5
  run --verify out/bar_coarse.h5
  expect_code 0
  expect_text "$work/stdout.txt" "raccord results, intact" "stdout"
  off=$(grep -a -b -o 'bar_coarse.msh' "$h5" | head -n 1 | cut -d: -f1)
  if [ -n "$off" ]; then
    cp "$h5" "$work/damaged.h5"
    printf 'X' | dd of="$work/damaged.h5" bs=1 seek="$off" conv=notrunc 2> /dev/null
    run --verify damaged.h5
    expect_code 2
    expect_text "$work/stderr.txt" "damaged: the dataset /scene" "stderr"
  else
    fail "the deck's mesh name is not stored in $h5"
  fi
  run --verify "$data/bar_coarse.nml"
  expect_code 2
  expect_text "$work/stderr.txt" "cannot be opened as HDF5" "stderr"
  run --verify no_such.h5
  expect_code 2
  run --verify out/bar_coarse.h5 "$data/bar_coarse.nml"
  expect_code 1
  ;;

mixed_order_load)
  # A pressure on one surface over a Q4 body and a Q8 body (the surface
  # has 3-node edges, and the Q4 edge's mid node is 0): 10 MPa on two
  # unit edges, total force (0, -20) in every history row. The Q4 edge
  # used to be integrated as a 3-node edge through node 0 (out of bounds;
  # the Check build stops on it).
  cat > "$work/mix.inp" <<'EOF_INP'
*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
11, 2, 0
12, 3, 0
13, 3, 1
14, 2, 1
15, 2.5, 0
16, 3, 0.5
17, 2.5, 1
18, 2, 0.5
*ELEMENT, TYPE=CPE4, ELSET=a
1, 1, 2, 3, 4
*ELEMENT, TYPE=CPE8, ELSET=b
2, 11, 12, 13, 14, 15, 16, 17, 18
*NSET, NSET=base
1, 2, 11, 12, 15
*SURFACE, NAME=top
1, S3
2, S3
EOF_INP
  cat > "$work/mix.nml" <<'EOF_NML'
&mesh file = 'mix.inp' /
&body name = 'a', young = 1000.0, poisson = 0.3, density = 1e-9 /
&body name = 'b', young = 1000.0, poisson = 0.3, density = 1e-9 /
&boundary set = 'base', type = 'fixed' /
&boundary set = 'top', type = 'pressure', pressure = 10.0 /
&time t_end = 1e-6 /
EOF_NML
  run --quiet --output out mix.nml
  expect_code 0
  hist=$work/out/mix.history.txt
  cx=$(history_column "$hist" top_Fx)
  cy=$(history_column "$hist" top_Fy)
  if [ -z "$cx" ] || [ -z "$cy" ]; then
    fail "no top_Fx/top_Fy column in $hist"
  else
    awk -v cx="$cx" -v cy="$cy" '
      /^#/ { next }
      { n++; ax = $cx < 0 ? -$cx : $cx; ay = $cy + 20; ay = ay < 0 ? -ay : ay
        if (ax > 1e-12 || ay > 1e-12) { print "FAIL: row " n ": top force (" $cx ", " $cy "), expected (0, -20)"; bad = 1 } }
      END { if (!n) { print "FAIL: no history rows"; bad = 1 }
            if (!bad) print n " rows, top force (0, -20) in each"; exit bad }' "$hist" \
      && pass "load total over Q4 and Q8 edges" || fail "load total over Q4 and Q8 edges"
  fi
  ;;

*)
  echo "unknown case '$case_name'" >&2
  exit 1
  ;;
esac

if [ "$failures" -gt 0 ]; then
  echo "$case_name: $failures check(s) failed (work folder $work)" >&2
  exit 1
fi
echo "$case_name: all checks passed"
exit 0
