# Shared harness of the shell test cases (sourced by tests/*/..._cases.sh,
# which set case_name, raccord and work first): counters and checks, the
# hdf5-tools test, a fresh work folder, and the stop-and-restart comparison.

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
has() { grep -qF -- "$2" "$1"; }

# need_tools TOOL...: exit 77 (skipped) when one is missing.
need_tools() {
  for tool in "$@"; do
    command -v "$tool" > /dev/null 2>&1 || { echo "skipped: $tool (hdf5-tools) not found"; exit 77; }
  done
}

# fresh_work: an empty $work, entered, with no backtraces and no wall-clock limit.
fresh_work() {
  rm -rf "$work"
  mkdir -p "$work" || exit 1
  cd "$work" || exit 1
  export GFORTRAN_ERROR_BACKTRACE=0
  unset RACCORD_WALLCLOCK_SECONDS
}

# refused NAME BODY_KEYS TEXT...: the deck that the sourcing script's
# block DECK BODY_KEYS writes with these body keys is refused: exit 2,
# stderr names the body 'block' and each TEXT, no backtrace, no file written.
refused() {
  name=$1
  keys=$2
  shift 2
  mkdir -p "$name"
  block "$name/deck.nml" "$keys"
  "$raccord" -o "$name/out" "$name/deck.nml" > "$name/stdout.txt" 2> "$name/stderr.txt"
  code=$?
  check "$name: exit 2 (got $code)" test "$code" -eq 2
  check "$name: the message names the body" has "$name/stderr.txt" "&body 'block'"
  for t in "$@"; do
    check "$name: the message says '$t'" has "$name/stderr.txt" "$t"
  done
  check "$name: no Fortran runtime message or backtrace" sh -c "! grep -qiE 'backtrace|fortran runtime|error stop' '$name/stderr.txt'"
  check "$name: nothing written" test ! -e "$name/out"
}

# usr1_restart_equals STEM: cont/STEM.nml has run to its end into cont/;
# run usr1/STEM.nml (the same deck), freeze it past step 300, send SIGUSR1
# (exit 5 with a checkpoint), restart from the checkpoint, and check that
# the results equal the continuous run's bit for bit (text files byte for
# byte, the HDF5 file by h5diff without tolerance).
usr1_restart_equals() {
  stem=$1
  "$raccord" -q -o usr1 "usr1/$stem.nml" > usr1/run.out 2>&1 &
  pid=$!
  # Frozen at once and let go in slices of about 2 ms, the step checked
  # while it is frozen, so that a fast run cannot pass its end between polls.
  kill -STOP "$pid" 2>/dev/null
  n=0
  while [ "$(awk '!/^#/ && NF > 2 { s = $2 } END { print s + 0 }' "usr1/$stem.history.txt.part" 2>/dev/null || echo 0)" -lt 300 ]; do
    if ! kill -0 "$pid" 2>/dev/null || [ -e "usr1/$stem.h5" ]; then fail "raccord ended before it could be stopped"; finish; fi
    n=$((n + 1))
    [ "$n" -lt 30000 ] || { kill -9 "$pid"; fail "never reached step 300"; finish; }
    kill -CONT "$pid"
    sleep 0.002
    kill -STOP "$pid" 2>/dev/null
  done
  kill -USR1 "$pid"
  kill -CONT "$pid"
  wait "$pid"
  code=$?
  check "SIGUSR1: exit 5 (got $code)" test "$code" -eq 5
  check "SIGUSR1: checkpoint written" test -s "usr1/$stem.checkpoint.h5"
  "$raccord" -q --restart "usr1/$stem.checkpoint.h5" > usr1/restart.out 2>&1
  code=$?
  check "restart: exit 0 (got $code)" test "$code" -eq 0
  for f in "$stem.history.txt" "$stem.contact1.txt" "$stem.xmf"; do
    check "$f equals the continuous run's, byte for byte" cmp -s "cont/$f" "usr1/$f"
  done
  check "$stem.h5 equals the continuous run's (h5diff, no tolerance)" \
    h5diff --exclude-path /scene --exclude-path /scene_path "cont/$stem.h5" "usr1/$stem.h5"
}
