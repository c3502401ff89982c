#!/bin/sh
# Tests of the batch scripts in hpc/: one case per CTest entry (tests/hpc/CMakeLists.txt).
#
#   sh hpc_cases.sh CASE RACCORD SOURCE_DIR WORK_DIR
#
# CASE        subst, errors, local, bad_case (and sweep-collect.sh), kill, array, exit_codes, restart
# RACCORD     the raccord executable (real runs and --check)
# SOURCE_DIR  the repository (hpc/ and tests/data/app/bar_coarse.msh)
# WORK_DIR    a folder of this case alone, emptied first
#
# Some cases use a stub raccord (a sh script written here) that exits with
# chosen codes, and stub scontrol/sbatch that log their arguments: Slurm is not
# needed. Prints every check and a closing "N passed, M failed" line; exit 0
# when none failed.
set -u

case_name=$1
raccord=$2
src=$3
work=$4
hpc=$src/hpc

npass=0
nfail=0
pass() { npass=$((npass + 1)); echo "ok   [$case_name] $*"; }
fail() { nfail=$((nfail + 1)); echo "FAIL [$case_name] $*"; }
check() { # description command...
  what=$1
  shift
  if "$@"; then pass "$what"; else fail "$what"; fi
}
finish() {
  echo "$npass passed, $nfail failed"
  [ "$nfail" -eq 0 ]
  exit $?
}
# has FILE TEXT: FILE has a line containing TEXT (fixed string)
has() { grep -qF -- "$2" "$1"; }
hasnt() { ! grep -qF -- "$2" "$1"; }
# line FILE TEXT: FILE has exactly the line TEXT, leading blanks ignored
line() { awk -v t="$2" '{ sub(/^[ \t]+/, "") } $0 == t { f = 1 } END { exit !f }' "$1"; }
newer_than_marker() { [ -n "$(find "$1" -newer "$work/marker" -print)" ]; }

rm -rf "$work"
mkdir -p "$work/data" "$work/bin" || exit 1
cp "$src/tests/data/app/bar_coarse.msh" "$work/data/" || exit 1
cd "$work" || exit 1

# The coarse bar with placeholders: 20 x 2 Q4, 169 steps, well under a second.
bar_template() {
  cat > "$work/data/bar.nml" <<'EOF'
! coarse bar, case @CASE@ (@INDEX@) @SPEED@
&run
  title = @TITLE@
/
&mesh
  file = @MESH@
/
&body
  name = 'bar', elset = 'bar'
  young = @YOUNG@, poisson = @NU@, density = @RHO@
  hypothesis = @HYP@, velocity = @VEL@
/
&boundary
  set = 'left', type = 'fixed', components = 'xy'
/
&boundary
  set = 'right', type = 'pressure', pressure = @PRESSURE@
/
&time
  t_end = 3.0e-5
/
&output
  frames = @FRAMES@, stress = @STRESS@, history_every = 1
/
EOF
}

# A sweep file of the bar: constants first, then the lines given as arguments.
bar_sweep() { # file line...
  f=$1
  shift
  {
    echo "template bar.nml"
    echo "set MESH:path bar_coarse.msh   # relative to the sweep file"
    echo "set RHO 7.8d-9"
    echo "set VEL:raw '0.0, 0.0'"
    echo "set SPEED fast"
    for l in "$@"; do echo "$l"; done
  } > "$work/data/$f"
}

# A stub raccord: --help (lists --wall-clock when STUB_CHECKPOINT=1), --check
# (exit STUB_CHECK_EXIT), and runs that write <stem>.h5.part, then rename it
# to <stem>.h5 (exit 0) or <stem>.incomplete.h5. The exit code of run k of a
# folder is word k of STUB_EXIT (the last word for later runs). A deck
# containing SLOW sleeps STUB_SLEEP s first; with STUB_CHECKPOINT=1 it takes
# USR1 and TERM as "write <stem>.checkpoint.h5 and exit 5", as raccord does.
stub_raccord() {
  cat > "$work/bin/raccord" <<'EOF'
#!/bin/sh
case "$1" in
--help) echo "usage: raccord [options] SCENE"; [ "${STUB_CHECKPOINT:-0}" != 1 ] || echo "  --wall-clock S"; exit 0 ;;
--check) exit "${STUB_CHECK_EXIT:-0}" ;;
esac
args="$*"
out=
while [ $# -gt 1 ]; do case "$1" in --output) out=$2; shift 2 ;; *) shift ;; esac; done
deck=$1
stem=$(basename "$deck" .nml)
n=$(cat "$out/stub.count" 2>/dev/null || echo 0)
n=$((n + 1))
echo "$n" > "$out/stub.count"
echo "run $n: $args wall=${RACCORD_WALLCLOCK_SECONDS:-none} omp=${OMP_NUM_THREADS:-none}" >> "$out/stub.log"
code=$(echo "${STUB_EXIT:-0}" | awk -v n="$n" '{ print (n <= NF ? $n : $NF) }')
: > "$out/$stem.h5.part"
if grep -q SLOW "$deck"; then
  # Traps first, then the pid file the tests wait for: a signal sent once
  # the pid file exists finds the traps in place.
  s=
  trap 'kill $s 2>/dev/null; exit 143' TERM
  if [ "${STUB_CHECKPOINT:-0}" = 1 ]; then
    trap 'echo usr1 >> "$out/stub.signals"; kill $s 2>/dev/null; : > "$out/$stem.checkpoint.h5"; exit 5' USR1
    trap 'echo term >> "$out/stub.signals"; kill $s 2>/dev/null; : > "$out/$stem.checkpoint.h5"; exit 5' TERM
  fi
  sleep "${STUB_SLEEP:-0}" &
  s=$!
  echo $$ > "$out/stub.pid"
  wait $s
else
  echo $$ > "$out/stub.pid"
fi
if [ "$code" = 0 ]; then mv "$out/$stem.h5.part" "$out/$stem.h5"; else mv "$out/$stem.h5.part" "$out/$stem.incomplete.h5"; fi
exit "$code"
EOF
  chmod +x "$work/bin/raccord"
  for tool in scontrol sbatch; do
    printf '#!/bin/sh\necho "$*" >> "%s/%s.calls"\n' "$work" "$tool" > "$work/bin/$tool"
    chmod +x "$work/bin/$tool"
  done
}

# wait_for FILE SECONDS: until FILE exists
wait_for() {
  k=0
  while [ ! -e "$1" ] && [ "$k" -lt $(($2 * 10)) ]; do sleep 0.1; k=$((k + 1)); done
  [ -e "$1" ]
}

# wait_for_line FILE TEXT SECONDS: until FILE has a line containing TEXT.
wait_for_line() {
  k=0
  while ! grep -qF -- "$2" "$1" 2>/dev/null && [ "$k" -lt $(($3 * 10)) ]; do sleep 0.1; k=$((k + 1)); done
  grep -qF -- "$2" "$1" 2>/dev/null
}

case "$case_name" in

subst)
  # Deck values: numbers bare, texts quoted (a quote doubled), logicals bare,
  # paths made absolute, raw values as written; case lines times vary values.
  bar_template
  bar_sweep sub.sweep \
    "columns TITLE YOUNG:number NU HYP STRESS PRESSURE" \
    "case soft   \"it's soft\"  70000.0  0.0  plane_stress  .false.  100.0" \
    "case stiff  'stiff bar'  2.0e5    0.25 plane_strain  .true.   50" \
    "vary FRAMES 2 3"
  sh "$hpc/sweep-gen.sh" -r "$raccord" -o sw "$work/data/sub.sweep" > gen.out 2>&1
  code=$?
  cat gen.out
  check "sweep-gen exit 0 (every deck accepted by raccord --check)" [ "$code" -eq 0 ]
  check "4 cases (2 case lines x 2 vary values)" [ "$(grep -c '^[0-9]' sw/cases.txt)" -eq 4 ]
  check "cases.txt numbers the cases in order" line sw/cases.txt "$(printf '3\tstiff_frames-2\tMESH = '"'$work/data/bar_coarse.msh'"'  RHO = 7.8d-9  VEL = 0.0, 0.0  SPEED = '"'fast'"'  TITLE = '"'stiff bar'"'  YOUNG = 2.0e5  NU = 0.25  HYP = '"'plane_strain'"'  STRESS = .true.  PRESSURE = 50  FRAMES = 2')"
  d=sw/soft_frames-3/case.nml
  check "text with a quote: title = 'it''s soft'" line "$d" "title = 'it''s soft'"
  check "path made absolute and quoted" line "$d" "file = '$work/data/bar_coarse.msh'"
  check "numbers bare (young, poisson, d exponent)" line "$d" "young = 70000.0, poisson = 0.0, density = 7.8d-9"
  check "text quoted, raw vector as written" line "$d" "hypothesis = 'plane_stress', velocity = 0.0, 0.0"
  check "integer and logical bare" line "$d" "frames = 3, stress = .false., history_every = 1"
  check "built-in @CASE@ and @INDEX@" line "$d" "! coarse bar, case soft_frames-3 (2) 'fast'"
  d=sw/stiff_frames-2/case.nml
  check "stiff: young = 2.0e5, poisson = 0.25" line "$d" "young = 2.0e5, poisson = 0.25, density = 7.8d-9"
  check "stiff: title 'stiff bar', pressure 50" sh -c "grep -qxF \"  title = 'stiff bar'\" $d && grep -qxF '  set = '\"'right'\"', type = '\"'pressure'\"', pressure = 50' $d"
  check "no placeholder left in any deck" sh -c "! grep -n '@[A-Z]' sw/*/case.nml"
  check "raccord --check resolved the quoted text" has sw/soft_frames-3/check.txt "hypothesis = 'plane_stress'"
  # Generating again rewrites nothing; changing one value rewrites only its decks.
  touch marker
  sleep 1
  sh "$hpc/sweep-gen.sh" -r "$raccord" -o sw "$work/data/sub.sweep" > gen2.out 2>&1
  check "second generation: every deck unchanged" has gen2.out "4 cases (0 decks written, 4 unchanged)"
  check "second generation: deck time stamps kept" sh -c "[ -z \"\$(find sw -name case.nml -newer marker)\" ]"
  sed 's/  50$/  60/' "$work/data/sub.sweep" > "$work/data/sub.tmp" && mv "$work/data/sub.tmp" "$work/data/sub.sweep"
  sh "$hpc/sweep-gen.sh" -r "$raccord" -o sw "$work/data/sub.sweep" > gen3.out 2>&1
  check "changed value: the 2 decks of that case line rewritten" has gen3.out "4 cases (2 decks written, 2 unchanged)"
  check "changed value: stiff_frames-3 reads pressure = 60" has sw/stiff_frames-3/case.nml "pressure = 60"
  ;;

errors)
  # A placeholder without a value is an error naming it (template and line);
  # so are bad sweep lines. Nothing is written.
  bar_template
  sed 's/@PRESSURE@/@PRESURE@/' data/bar.nml > data/typo.nml
  bar_sweep typo.sweep "vary PRESSURE 1 2" "set TITLE t" "set YOUNG 1" "set NU 0" "set HYP h" "set FRAMES 1" "set STRESS .true."
  sed 's/^template bar.nml/template typo.nml/' data/typo.sweep > data/t.tmp && mv data/t.tmp data/typo.sweep
  sh "$hpc/sweep-gen.sh" --no-check -o typo data/typo.sweep > typo.out 2>&1
  code=$?
  cat typo.out
  check "unknown placeholder: exit 2" [ "$code" -eq 2 ]
  n=$(grep -n '@PRESURE@' data/typo.nml | cut -d: -f1)
  check "unknown placeholder named with template and line" has typo.out "$work/data/typo.nml:$n: @PRESURE@"
  check "unknown placeholder: the defined parameters are listed" has typo.out "parameters defined: MESH, RHO, VEL, SPEED, PRESSURE"
  check "unknown placeholder: the unused parameter is warned about" has typo.out "parameter PRESSURE is not used in the template"
  check "unknown placeholder: no case folder written" [ -z "$(find typo -name 'case.nml*')" ]
  for bad in "columns YOUNG:number|case a stiff|not a number" \
    "columns YOUNG|case a 1 2|has 2 values for 1 columns" \
    "vary young 1 2|must be upper case" \
    "vary CASE 1 2|set by sweep-gen.sh for every case" \
    "vary X:float 1|unknown type 'float'" \
    "frobnicate X|unknown line 'frobnicate'" \
    "set T 'unterminated|unterminated quote" \
    "columns X|case a 1|case a 2|a second case a (the first is on line 3)"; do
    msg=${bad##*|}
    lines=${bad%|*}
    printf 'template bar.nml\n%s\n' "$lines" | tr '|' '\n' > data/bad.sweep
    sh "$hpc/sweep-gen.sh" --no-check -o bad data/bad.sweep > bad.out 2>&1
    code=$?
    check "bad sweep ($msg): exit 2 and says so" sh -c "[ $code -eq 2 ] && grep -qF -- \"$msg\" bad.out"
  done
  ;;

local)
  # 4 quick cases on both cores; a rerun skips them; a killed case (its
  # .part left) runs again alone.
  bar_template
  bar_sweep four.sweep "set TITLE 'four'" "set NU 0.0" "set HYP plane_stress" "set FRAMES 2" "set STRESS .true." \
    "vary YOUNG 200000.0 70000.0" "vary PRESSURE 50.0 100.0"
  t0=$(date +%s)
  sh "$hpc/sweep-local.sh" -j 2 -r "$raccord" -o sw data/four.sweep > run1.out 2>&1
  code=$?
  t1=$(date +%s)
  cat run1.out
  echo "first sweep: $((t1 - t0)) s"
  check "first sweep: exit 0" [ "$code" -eq 0 ]
  check "first sweep: summary 4 done" has run1.out "4 cases: 4 done, 0 skipped, 0 failed"
  check "first sweep: 2 at a time" has run1.out "4 cases, 2 at a time"
  for c in young-200000.0_pressure-50.0 young-200000.0_pressure-100.0 young-70000.0_pressure-50.0 young-70000.0_pressure-100.0; do
    check "$c: case.h5, case.xmf and case.history.txt written" \
      sh -c "[ -s sw/$c/case.h5 ] && [ -s sw/$c/case.xmf ] && [ -s sw/$c/case.history.txt ]"
  done
  check "no .part or .incomplete file left" [ -z "$(find sw -name '*.part' -o -name '*.incomplete.*')" ]
  if command -v h5dump > /dev/null 2>&1; then
    st=$(h5dump -d /status sw/young-70000.0_pressure-100.0/case.h5 | awk -F'"' '/\(0\):/ { print $2; exit }')
    check "h5 /status is complete" [ "$st" = complete ]
  fi
  check "the deck's pressure reached the run (history: right_Fx = -1000 N at 100 MPa)" \
    sh -c "awk '\$1 == \"#\" && \$3 == \"right_Fx\" { c = \$2 } \$1 !~ /^#/ && c { v = \$c } END { d = v + 1000; exit !(d < 1e-6 && d > -1e-6) }' sw/young-70000.0_pressure-100.0/case.history.txt"
  check "summary.txt written" has sw/summary.txt "4 done"
  touch marker
  sleep 1
  sh "$hpc/sweep-local.sh" -j 2 -r "$raccord" -o sw data/four.sweep > run2.out 2>&1
  code=$?
  cat run2.out
  check "rerun: exit 0" [ "$code" -eq 0 ]
  check "rerun: summary 4 skipped" has run2.out "4 cases: 0 done, 4 skipped, 0 failed"
  check "rerun: no result file rewritten" [ -z "$(find sw -name 'case.*' -newer marker)" ]
  # A killed run: its .part files, no case.h5.
  k=sw/young-200000.0_pressure-100.0
  mv "$k/case.h5" "$k/case.h5.part"
  rm -f "$k/case.xmf"
  touch marker
  sleep 1
  sh "$hpc/sweep-local.sh" -r "$raccord" sw > run3.out 2>&1
  code=$?
  cat run3.out
  check "after a killed case: exit 0, 1 done 3 skipped" sh -c "[ $code -eq 0 ] && grep -qF '4 cases: 1 done, 3 skipped, 0 failed' run3.out"
  check "after a killed case: only that case rewritten" \
    sh -c "newer=\$(find sw -name case.h5 -newer marker); [ \"\$newer\" = $k/case.h5 ]"
  check "after a killed case: its .part is gone" [ ! -e "$k/case.h5.part" ]
  ;;

bad_case)
  # One case with poisson = 0.7: refused by --check, reported with exit 2 and
  # its folder, not run; the others complete.
  bar_template
  bar_sweep three.sweep "set TITLE 't'" "set YOUNG 200000.0" "set HYP plane_stress" "set FRAMES 2" "set STRESS .false." \
    "set PRESSURE 100.0" "columns NU" "case good1 0.0" "case bad 0.7" "case good2 0.25"
  sh "$hpc/sweep-gen.sh" -r "$raccord" -o sw data/three.sweep > gen.out 2>&1
  code=$?
  cat gen.out
  check "sweep-gen: exit 10 (a deck refused)" [ "$code" -eq 10 ]
  check "sweep-gen names the refused case" has gen.out "BAD   2 bad (written): raccord --check exit 2"
  sh "$hpc/sweep-local.sh" -r "$raccord" sw > run.out 2>&1
  code=$?
  cat run.out
  check "sweep: exit 10 (a case failed)" [ "$code" -eq 10 ]
  check "summary: 2 done, 1 failed" has run.out "3 cases: 2 done, 0 skipped, 1 failed"
  check "summary: the failed case with exit 2, stage and folder" \
    sh -c "grep -E '^  failed +2  bad +$work/sw/bad  exit 2 \\(check\\)$' run.out"
  check "the bad case was not run (no result, no run.out)" sh -c "[ ! -e sw/bad/case.h5 ] && [ ! -e sw/bad/run.out ] && [ -z \"\$(find sw/bad -name '*.h5*')\" ]"
  check "the bad case's check.txt says why" has sw/bad/check.txt "poisson"
  check "good1 and good2 complete" sh -c "[ -s sw/good1/case.h5 ] && [ -s sw/good2/case.h5 ]"
  sh "$hpc/sweep-collect.sh" sw right_Fx > collect.out
  cat collect.out
  check "sweep-collect: good1 done, right_Fx = -1000" awk -F '\t' '
    $2 == "good1" && $3 == "done" && $4 + 1000 < 1e-6 && $4 + 1000 > -1e-6 { f = 1 } END { exit !f }' collect.out
  check "sweep-collect: bad refused" awk -F '\t' '$2 == "bad" && $3 == "refused" { f = 1 } END { exit !f }' collect.out
  ;;

kill)
  # A sweep stopped by TERM while a slow case runs: the slow case's raccord is
  # stopped, the complete cases stay complete, a rerun only runs the slow one.
  stub_raccord
  bar_template
  bar_sweep k.sweep "set TITLE 't'" "set YOUNG 1" "set HYP h" "set FRAMES 2" "set STRESS .false." "set PRESSURE 1" "set NU 0" \
    "columns SPEED:raw" "case fast1 fast" "case slow SLOW" "case fast2 fast"
  sed '/^set SPEED/d' data/k.sweep > data/k.tmp && mv data/k.tmp data/k.sweep
  STUB_SLEEP=60 sh "$hpc/sweep-local.sh" -j 2 -r "$work/bin/raccord" -o sw data/k.sweep > run1.out 2>&1 &
  sweep_pid=$!
  # Wait for the runner's own record of the fast cases: their case.h5 is
  # there a moment before the runner has seen them end, and a TERM in that
  # moment stops a case that was in fact complete.
  wait_for_line run1.out 'case fast1: done' 20 && wait_for_line run1.out 'case fast2: done' 20 && \
    wait_for sw/slow/stub.pid 20
  check "fast cases complete while the slow one runs" [ -e sw/fast2/case.h5 ]
  stub_pid=$(cat sw/slow/stub.pid 2>/dev/null)
  kill -TERM "$sweep_pid"
  wait "$sweep_pid"
  code=$?
  cat run1.out
  check "stopped sweep: exit 143" [ "$code" -eq 143 ]
  check "stopped sweep: summary lists slow as stopped" sh -c "grep -E '^  stopped +2  slow ' run1.out"
  check "stopped sweep: summary says interrupted" has run1.out "2 done, 0 skipped, 0 failed, 1 stopped (interrupted)"
  sleep 0.5
  check "stopped sweep: the slow case's raccord is gone" sh -c "! kill -0 $stub_pid 2>/dev/null"
  check "stopped sweep: the slow case has no case.h5, its .part is left" sh -c "[ ! -e sw/slow/case.h5 ] && [ -e sw/slow/case.h5.part ]"
  check "stopped sweep: no claim folder left" [ -z "$(find sw -name '.sweep-local.*')" ]
  touch marker
  sleep 1
  STUB_SLEEP=0 sh "$hpc/sweep-local.sh" -j 2 -r "$work/bin/raccord" sw > run2.out 2>&1
  code=$?
  cat run2.out
  check "rerun: exit 0, slow done, fast ones skipped" sh -c "[ $code -eq 0 ] && grep -qF '3 cases: 1 done, 2 skipped, 0 failed' run2.out"
  check "rerun: the fast results untouched" sh -c "[ -z \"\$(find sw/fast1 sw/fast2 -newer marker -name 'case.h5')\" ]"
  check "rerun: OMP_NUM_THREADS=1 per case" has sw/slow/stub.log "omp=1"
  ;;

array)
  # The array template runs case SLURM_ARRAY_TASK_ID of cases.txt, and only it;
  # #SBATCH lines come before the first command; sweep-slurm.sh submits the
  # cases not complete.
  stub_raccord
  for f in raccord-array.sbatch raccord-one.sbatch; do
    t=$hpc/slurm/$f
    check "$f: every #SBATCH line before the first command" awk '
      /^#SBATCH/ { if (cmd) bad = 1; next } /^#/ || /^[ \t]*$/ { next } { cmd = 1 } END { exit bad }' "$t"
    for opt in --time= --mem= --cpus-per-task= --signal=B:USR1@120 --requeue; do
      check "$f: #SBATCH $opt" grep -q "^#SBATCH $opt" "$t"
    done
  done
  bar_template
  bar_sweep four.sweep "set TITLE 'four'" "set NU 0.0" "set HYP plane_stress" "set FRAMES 2" "set STRESS .true." \
    "vary YOUNG 200000.0 70000.0" "vary PRESSURE 50.0 100.0"
  sh "$hpc/sweep-gen.sh" -r "$raccord" -o sw data/four.sweep > gen.out 2>&1
  check "sweep-gen: exit 0" [ $? -eq 0 ]
  env PATH="$work/bin:$PATH" SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_JOB_ID=500 SLURM_JOB_ID=503 SLURM_CPUS_PER_TASK=1 \
    RACCORD="$raccord" sh "$hpc/slurm/raccord-array.sbatch" sw > task3.out 2>&1
  code=$?
  cat task3.out
  check "task 3: exit 0" [ "$code" -eq 0 ]
  check "task 3 runs case 3 = young-70000.0_pressure-50.0" has task3.out "case 3 young-70000.0_pressure-50.0"
  check "task 3: case 3 complete" [ -s sw/young-70000.0_pressure-50.0/case.h5 ]
  check "task 3: case 3's deck has young 70000, pressure 50" sh -c "grep -q 'young = 70000.0' sw/young-70000.0_pressure-50.0/case.nml && grep -q 'pressure = 50.0' sw/young-70000.0_pressure-50.0/case.nml"
  check "task 3: no other case run" [ "$(find sw -name case.h5 | wc -l)" -eq 1 ]
  check "task 3: attempts.txt names job and task" has sw/young-70000.0_pressure-50.0/attempts.txt "job=503 task=3 stage=run exit=0"
  check "task 3: no requeue" [ ! -e scontrol.calls ]
  # The same script as sbatch runs it: a copy elsewhere, hpc/ found from SLURM_SUBMIT_DIR.
  mkdir spool
  cp "$hpc/slurm/raccord-array.sbatch" spool/slurm_script
  (cd spool && env SLURM_ARRAY_TASK_ID=1 SLURM_JOB_ID=501 SLURM_SUBMIT_DIR="$src" RACCORD="$raccord" \
    sh ./slurm_script "$work/sw") > task1.out 2>&1
  code=$?
  cat task1.out
  check "copied script (as sbatch runs it): task 1 runs case 1" sh -c "[ $code -eq 0 ] && [ -s sw/young-200000.0_pressure-50.0/case.h5 ]"
  for t in 0 5 x; do
    SLURM_ARRAY_TASK_ID=$t RACCORD="$raccord" sh "$hpc/slurm/raccord-array.sbatch" sw > bad.out 2>&1
    code=$?
    check "task '$t': exit 1 with a message" sh -c "[ $code -eq 1 ] && grep -q 'not a case number\|no case $t' bad.out"
  done
  sh "$hpc/sweep-slurm.sh" -n -m 2 sw --time=1:00:00 > submit.out 2>&1
  cat submit.out
  check "sweep-slurm -n: the 2 cases not complete as --array=2,4%2" has submit.out "sbatch --array=2,4%2 --job-name=raccord-sw --output=$work/sw/slurm-%A_%a.out --export=ALL,RACCORD_HPC=$hpc --time=1:00:00 $hpc/slurm/raccord-array.sbatch $work/sw"
  PATH="$work/bin:$PATH" sh "$hpc/sweep-slurm.sh" sw > submit2.out 2>&1
  check "sweep-slurm: sbatch called with --array=2,4" has sbatch.calls "--array=2,4 "
  ;;

exit_codes)
  # What the job templates do with each exit code of raccord (stub raccord,
  # stub scontrol), the wall-clock seconds handed over, and SIGUSR1.
  stub_raccord
  printf '! deck\n' > fast.nml
  printf '! deck SLOW\n' > slow.nml
  PATH=$work/bin:$PATH
  RACCORD=$work/bin/raccord
  RACCORD_RETRY_DELAY=0
  export PATH RACCORD RACCORD_RETRY_DELAY
  job() { # name deck [VAR=value...]: run raccord-one.sbatch into out-NAME
    n=$1 d=$2
    shift 2
    rm -f scontrol.calls
    env SLURM_JOB_ID=4242 "$@" sh "$hpc/slurm/raccord-one.sbatch" "$d" "out-$n" > "$n.out" 2>&1
    code=$?
    cat "$n.out"
  }
  job ok fast.nml
  check "exit 0: job exit 0, complete, no requeue" sh -c "[ $code -eq 0 ] && [ -e out-ok/fast.h5 ] && [ ! -e scontrol.calls ]"
  job ok fast.nml
  check "exit 0, second job: skipped, raccord not run again" sh -c "[ $code -eq 0 ] && grep -q skipped ok.out && [ \$(cat out-ok/stub.count) -eq 1 ]"
  job input fast.nml STUB_CHECK_EXIT=2
  check "exit 2 at --check: job exit 2, not run, not requeued" sh -c "[ $code -eq 2 ] && [ ! -e out-input/stub.count ] && [ ! -e scontrol.calls ] && grep -q 'fix the input' input.out"
  job input2 fast.nml STUB_EXIT=2
  check "exit 2 at run: job exit 2, run once, not requeued" sh -c "[ $code -eq 2 ] && [ \$(cat out-input2/stub.count) -eq 1 ] && [ ! -e scontrol.calls ]"
  job num fast.nml STUB_EXIT=3
  check "exit 3: job exit 3, run once, not requeued, reported" sh -c "[ $code -eq 3 ] && [ \$(cat out-num/stub.count) -eq 1 ] && [ ! -e scontrol.calls ] && grep -q 'numerical failure' num.out"
  job fs fast.nml STUB_EXIT=4
  check "exit 4 twice: run twice, job exit 4, not requeued" sh -c "[ $code -eq 4 ] && [ \$(cat out-fs/stub.count) -eq 2 ] && [ ! -e scontrol.calls ]"
  job fs1 fast.nml "STUB_EXIT=4 0"
  check "exit 4 then 0: retried once, job exit 0, complete" sh -c "[ $code -eq 0 ] && [ \$(cat out-fs1/stub.count) -eq 2 ] && [ -e out-fs1/fast.h5 ]"
  job ckpt fast.nml STUB_EXIT=5
  check "exit 5: scontrol requeue 4242, job exit 5" sh -c "[ $code -eq 5 ] && grep -qx 'requeue 4242' scontrol.calls && grep -q requeued ckpt.out"
  job ckpt_max fast.nml STUB_EXIT=5 SLURM_RESTART_COUNT=20
  check "exit 5 after 20 restarts: not requeued" sh -c "[ $code -eq 5 ] && [ ! -e scontrol.calls ] && grep -q 'not requeued' ckpt_max.out"
  rm -f scontrol.calls
  STUB_EXIT=5 sh "$hpc/slurm/raccord-one.sbatch" fast.nml out-noslurm > noslurm.out 2>&1
  code=$?
  check "exit 5 without Slurm: exit 5, says to run again, no scontrol" sh -c "[ $code -eq 5 ] && [ ! -e scontrol.calls ] && grep -q 'run the same command again' noslurm.out"
  # Wall-clock seconds: job end minus the 300 s margin.
  now=$(date +%s)
  job wall fast.nml SLURM_JOB_END_TIME=$((now + 3600))
  w=$(sed -n 's/.* wall=\([0-9]*\) .*/\1/p' out-wall/stub.log)
  check "SLURM_JOB_END_TIME = now + 3600: RACCORD_WALLCLOCK_SECONDS = $w (3290..3300)" sh -c "[ '$w' -ge 3290 ] && [ '$w' -le 3300 ]"
  check "raccord without --wall-clock in --help: no --wall-clock option passed" hasnt out-wall/stub.log "--wall-clock"
  job wall2 fast.nml RACCORD_TIME_LIMIT=1-00:00:00 SLURM_JOB_START_TIME=$now RACCORD_WALLCLOCK_MARGIN=600 STUB_CHECKPOINT=1
  w=$(sed -n 's/.* wall=\([0-9]*\) .*/\1/p' out-wall2/stub.log)
  check "RACCORD_TIME_LIMIT = 1 day, margin 600: $w (85790..85800)" sh -c "[ '$w' -ge 85790 ] && [ '$w' -le 85800 ]"
  check "raccord with --wall-clock: passed as an option" has out-wall2/stub.log "--wall-clock $w --output"
  job nowall fast.nml
  check "no limit known: RACCORD_WALLCLOCK_SECONDS not set" has out-nowall/stub.log "wall=none"
  # SIGUSR1 to the job shell (#SBATCH --signal=B:USR1@...): passed on to a
  # raccord that writes checkpoints (it exits 5, the job is requeued) ...
  rm -f scontrol.calls
  env SLURM_JOB_ID=4343 STUB_CHECKPOINT=1 STUB_SLEEP=30 sh "$hpc/slurm/raccord-one.sbatch" slow.nml out-usr1 > usr1.out 2>&1 &
  jpid=$!
  wait_for out-usr1/stub.pid 20
  sleep 0.3
  kill -USR1 "$jpid"
  wait "$jpid"
  code=$?
  cat usr1.out
  check "USR1 with checkpoint support: raccord got it, job exit 5, requeued" \
    sh -c "[ $code -eq 5 ] && grep -q usr1 out-usr1/stub.signals && [ -e out-usr1/slow.checkpoint.h5 ] && grep -qx 'requeue 4343' scontrol.calls"
  # The requeued job goes on from the checkpoint (raccord --restart).
  env SLURM_JOB_ID=4343 SLURM_RESTART_COUNT=1 STUB_CHECKPOINT=1 sh "$hpc/slurm/raccord-one.sbatch" slow.nml out-usr1 > usr1b.out 2>&1
  code=$?
  cat usr1b.out
  check "requeued job: raccord --restart out-usr1/slow.checkpoint.h5, complete" \
    sh -c "[ $code -eq 0 ] && grep -q 'run 2: .*--restart out-usr1/slow.checkpoint.h5 --output' out-usr1/stub.log && [ -e out-usr1/slow.h5 ]"
  # A deck rewritten after the checkpoint starts the case again.
  mkdir -p out-newer && : > out-newer/slow.checkpoint.h5 && sleep 1 && printf '! deck SLOW, rewritten\n' > newer.nml
  cp out-newer/slow.checkpoint.h5 out-newer/keep && touch -r out-newer/keep out-newer/slow.checkpoint.h5
  env SLURM_JOB_ID=4545 STUB_CHECKPOINT=1 sh "$hpc/slurm/raccord-one.sbatch" newer.nml out-newer > newer.out 2>&1
  check "checkpoint older than the deck: no --restart" hasnt out-newer/stub.log "--restart"
  # SIGTERM (Slurm at the time limit) to the job shell: passed on; a raccord
  # with checkpoints writes one and exits 5, and the job is requeued.
  rm -f scontrol.calls
  env SLURM_JOB_ID=4646 STUB_CHECKPOINT=1 STUB_SLEEP=30 sh "$hpc/slurm/raccord-one.sbatch" slow.nml out-term > term.out 2>&1 &
  jpid=$!
  wait_for out-term/stub.pid 20
  sleep 0.3
  kill -TERM "$jpid"
  wait "$jpid"
  code=$?
  cat term.out
  check "TERM with checkpoint support: job exit 5, checkpoint, requeued" \
    sh -c "[ $code -eq 5 ] && grep -q term out-term/stub.signals && [ -e out-term/slow.checkpoint.h5 ] && grep -qx 'requeue 4646' scontrol.calls"
  # ... and not to an older raccord, which would die of it.
  env SLURM_JOB_ID=4444 STUB_SLEEP=2 sh "$hpc/slurm/raccord-one.sbatch" slow.nml out-usr1old > usr1old.out 2>&1 &
  jpid=$!
  wait_for out-usr1old/stub.pid 20
  sleep 0.3
  kill -USR1 "$jpid"
  wait "$jpid"
  code=$?
  cat usr1old.out
  check "USR1 without checkpoint support: ignored, the run completes" \
    sh -c "[ $code -eq 0 ] && [ -e out-usr1old/slow.h5 ] && grep -q 'SIGUSR1 ignored' usr1old.out"
  ;;

restart)
  # The real raccord through run-case.sh: a limit shorter than the setup
  # stops it at the first step with a checkpoint (exit 5); the next attempt
  # goes on from it and completes, with the results of an uninterrupted run.
  sed "s|'bar_coarse.msh'|'$work/data/bar_coarse.msh'|" "$src/tests/data/app/bar_coarse.nml" > bar.nml
  RACCORD_WALLCLOCK_SECONDS=0.001 sh "$hpc/run-case.sh" -r "$raccord" -d bar.nml out-a > a1.out 2>&1
  code=$?
  cat a1.out
  check "run-case with a 0.001 s limit: exit 5, checkpoint, not complete" \
    sh -c "[ $code -eq 5 ] && [ -e out-a/bar.checkpoint.h5 ] && [ ! -e out-a/bar.h5 ] && grep -q 'checkpoint written' a1.out"
  sh "$hpc/run-case.sh" -r "$raccord" -d bar.nml out-a > a2.out 2>&1
  code=$?
  cat a2.out
  check "next attempt: goes on from the checkpoint, done" \
    sh -c "[ $code -eq 0 ] && grep -q 'going on from out-a/bar.checkpoint.h5' a2.out && grep -q 'done' a2.out"
  check "attempts.txt records run 5 then restart 0" \
    sh -c "grep -q 'stage=run exit=5' out-a/attempts.txt && grep -q 'stage=restart exit=0' out-a/attempts.txt"
  sh "$hpc/run-case.sh" -r "$raccord" -d bar.nml out-b > b.out 2>&1
  check "the same case without a stop: done" grep -q done b.out
  for f in bar.history.txt bar.xmf; do
    check "$f of the restarted case equals the uninterrupted one's" cmp -s out-a/$f out-b/$f
  done
  if command -v h5diff > /dev/null 2>&1; then
    check "bar.h5 of the restarted case equals the uninterrupted one's (h5diff)" \
      h5diff --exclude-path /scene --exclude-path /scene_path out-a/bar.h5 out-b/bar.h5
  fi
  ;;

*)
  echo "unknown case '$case_name'" >&2
  exit 2
  ;;
esac
finish
