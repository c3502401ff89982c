#!/bin/sh
# Checkpoint and restart of the raccord program: one case per CTest entry
# (tests/restart/CMakeLists.txt).
#
#   sh restart_cases.sh CASE RACCORD SOURCE_DIR WORK_DIR
#
# CASE        signal, wall_clock, kill, refuse, mass_scaling
# RACCORD     the raccord executable
# SOURCE_DIR  the repository (the sliding mesh of input/verification/sliding)
# WORK_DIR    a folder of this case alone, emptied first
#
# The scene: a slider pressed on a base (mu = 0.3), then pulled right until
# it slides, and back until it slides the other way (stick, slip, reversal),
# 2029 steps, 14 frames, a history row every 7 steps. Each case runs it once
# without stopping (the reference, in cont/) and once stopped and restarted,
# and asserts that the restarted run's final files equal the reference's
# exactly: every HDF5 dataset (h5diff with no tolerance; only /scene and
# /scene_path, which name the output folder and deck, are left out), the
# history, the contact profile and the XDMF byte for byte. They are equal
# because the checkpoint holds the whole state the next step reads, as IEEE
# doubles, and the restarted step does the same operations in the same order.
#
# Timing-free: a running raccord is frozen with SIGSTOP before it is signalled
# or killed, so the tests do not depend on the machine's speed.
# Needs sh, awk, cmp, h5dump and h5diff (hdf5-tools).
set -u

case_name=$1
raccord=$2
src=$3
work=$4

. "$src/tests/support/cases.sh"

need_tools h5dump h5diff
fresh_work

# deck FOLDER [EXTRA_RUN_KEYS [FRICTION [METHOD [EXTRA_TIME_KEYS]]]]: FOLDER/slide.nml
deck() {
  mkdir -p "$1"
  cat > "$1/slide.nml" <<EOF
! Slider on a base, mu = ${3:-0.3}: pressed, pulled right, then back (stick, slip, reversal).
&run
  ${2:-}
/
&mesh
  file = '$src/input/verification/sliding/sliding_q4.msh'
/
&body
  name = 'base', elset = 'base', young = 200000.0, poisson = 0.3, density = 7.8e-9
/
&body
  name = 'slider', elset = 'slider', young = 200000.0, poisson = 0.3, density = 7.8e-9
/
&amplitude
  name = 'press', time = 0.0, 4.0e-6, value = 0.0, 1.0
/
&amplitude
  name = 'pull', time = 5.0e-6, 8.0e-6, 1.2e-5, value = 0.0, 1.0, -1.0
/
&boundary
  set = 'base_bottom', type = 'fixed', components = 'xy'
/
&boundary
  set = 'slider_top', type = 'pressure', pressure = 10.0, amplitude = 'press'
/
&boundary
  set = 'slider_right', type = 'traction', value = 12.0, 0.0, amplitude = 'pull'
/
&time
  t_end = 1.3e-5, damping = 1.2e7${5:+, $5}
/
&output
  frames = 13, history_every = 7
/
&contact_pair
  slave = 'slider_bottom', master = 'base_top', friction = ${3:-0.3}
  method = '${4:-node_to_segment}'
/
EOF
}

# run DIR ARGS...: raccord ARGS in the foreground, output in DIR/run.out; sets code.
run() {
  _d=$1
  shift
  "$raccord" -q "$@" > "$_d/run.out" 2>&1
  code=$?
}

# reference [METHOD]: the continuous run in cont/.
reference() {
  rm -rf cont
  deck cont '' 0.3 "${1:-node_to_segment}"
  run cont -o cont cont/slide.nml
  [ "$code" -eq 0 ] || { fail "reference run exit $code"; cat cont/run.out; finish; }
  # The scene does slide both ways: tangential force reaches -mu N and +mu N.
  awk -v c="$(awk '$1 == "#" && $3 == "contact1_T" { print $2 }' cont/slide.history.txt)" \
    '!/^#/ { t = $c + 0; if (t < lo) lo = t; if (t > hi) hi = t } END { exit !(lo < -2.9 && hi > 2.9) }' \
    cont/slide.history.txt && pass "reference run slides both ways (|T| reaches mu N = 3)" ||
    fail "reference run does not reach mu N both ways"
}

# same_results DIR: DIR's final files equal the reference's exactly.
same_results() {
  for f in slide.history.txt slide.contact1.txt slide.xmf; do
    check "$1/$f equals the continuous run's, byte for byte" cmp -s "cont/$f" "$1/$f"
  done
  check "$1/slide.h5 equals the continuous run's (h5diff, every dataset, no tolerance)" \
    h5diff --exclude-path /scene --exclude-path /scene_path cont/slide.h5 "$1/slide.h5"
  check "$1: no checkpoint left after completion" test ! -e "$1/slide.checkpoint.h5"
  check "$1: no .part file left" test -z "$(find "$1" -name '*.part')"
}

# stopped DIR: a run stopped at a checkpoint: the checkpoint, only .part
# result files, /status says suspended.
stopped() {
  check "$1: checkpoint written" test -s "$1/slide.checkpoint.h5"
  check "$1: no complete-looking result file" \
    test -z "$(find "$1" \( -name slide.h5 -o -name slide.xmf -o -name slide.history.txt \
      -o -name slide.contact1.txt -o -name '*.incomplete.*' \) -print)"
  check "$1: running files kept as .part" test -s "$1/slide.h5.part" -a -s "$1/slide.history.txt.part" \
    -a -s "$1/slide.contact1.txt.part"
  check "$1: /status of the .part results says suspended" \
    sh -c "h5dump -d /status '$1/slide.h5.part' | grep -q 'suspended at step'"
}

ckpt_step() { h5dump -d /state/counters "$1" 2>/dev/null | awk -F'[:,]' '/\(0\):/ { print $2 + 0; exit }'; }
last_row_step() { awk '!/^#/ && NF > 2 { s = $2 } END { print s + 0 }' "$1"; }

# start_frozen DIR COND ARGS...: start raccord ARGS in the background and
# freeze it (SIGSTOP) with the shell condition COND holding; sets pid. The
# run is frozen at once and let go in slices of about 2 ms (SIGCONT, sleep,
# SIGSTOP), COND being checked while it is frozen: a fast run (a few
# thousand steps per second) cannot slip past the condition while the poll
# itself takes time, as it could when raccord ran freely between polls.
# Fails when raccord ended first or COND never holds (about 2 minutes).
start_frozen() {
  _d=$1
  _cond=$2
  shift 2
  "$raccord" -q "$@" > "$_d/run.out" 2>&1 &
  pid=$!
  kill -STOP "$pid" 2>/dev/null
  _n=0
  while ! eval "$_cond"; do
    if ! kill -0 "$pid" 2>/dev/null || [ -e "$_d/slide.h5" ]; then
      fail "raccord ended before it could be stopped"
      finish
    fi
    _n=$((_n + 1))
    [ "$_n" -lt 30000 ] || { kill -9 "$pid"; fail "condition never met: $_cond"; finish; }
    kill -CONT "$pid"
    sleep 0.002
    kill -STOP "$pid" 2>/dev/null
  done
  if [ -e "$_d/slide.h5" ]; then fail "raccord completed before it was stopped"; finish; fi
}

# same_watch DIR: the watchers' closing lines of the restarted run (the
# quasi-static check's largest ratio, the energy given by contact) equal the
# uninterrupted run's in cont/: their record is in the checkpoint, so they
# report on the whole run, not on the part after the restart.
same_watch() {
  for key in 'quasi-static check: largest' 'energy given by contact' 'contact gave the bodies energy'; do
    ref=$(grep -F -- "$key" cont/slide.log | tail -1 | sed 's/^.*\] //')
    got=$(grep -F -- "$key" "$1/slide.log" | tail -1 | sed 's/^.*\] //')
    [ -z "$ref" ] && [ -z "$got" ] && continue
    check "restart reports '$key' as the uninterrupted run: $got" test "$ref" = "$got"
  done
}

case "$case_name" in
signal)
  # SIGUSR1 (what Slurm sends before the limit) in the middle of the run:
  # checkpoint, exit 5; then --restart completes it.
  reference
  deck usr1
  start_frozen usr1 '[ "$(last_row_step usr1/slide.history.txt.part 2>/dev/null || echo 0)" -ge 300 ]' \
    -o usr1 usr1/slide.nml
  kill -USR1 "$pid"
  kill -CONT "$pid"
  wait "$pid"
  code=$?
  check "SIGUSR1: exit 5" test "$code" -eq 5
  check "SIGUSR1 under -q: nothing on stdout or stderr (exit 5 is no error)" test ! -s usr1/run.out
  stopped usr1
  check "SIGUSR1: the log says why" has usr1/slide.log "SIGUSR1 received"
  check "SIGUSR1: checkpoint in mid-run (step > 300)" test "$(ckpt_step usr1/slide.checkpoint.h5)" -gt 300
  run usr1 --restart usr1/slide.checkpoint.h5
  check "restart (scene from the checkpoint): exit 0" test "$code" -eq 0
  check "the log of the restart continues the first one" has usr1/slide.log "restart from usr1/slide.checkpoint.h5"
  same_results usr1
  same_watch usr1
  # SIGTERM does the same; with mortar matching this time.
  reference mortar
  deck term '' 0.3 mortar
  start_frozen term '[ "$(last_row_step term/slide.history.txt.part 2>/dev/null || echo 0)" -ge 700 ]' \
    -o term term/slide.nml
  kill -TERM "$pid"
  kill -CONT "$pid"
  wait "$pid"
  code=$?
  check "SIGTERM: exit 5" test "$code" -eq 5
  stopped term
  run term --restart term/slide.checkpoint.h5 -o term term/slide.nml
  check "restart with --output and the deck: exit 0" test "$code" -eq 0
  same_results term
  ;;
wall_clock)
  reference
  # A limit shorter than the setup: checkpoint at the first step boundary.
  deck tiny
  RACCORD_WALLCLOCK_SECONDS=0.001 run tiny -o tiny tiny/slide.nml
  check "RACCORD_WALLCLOCK_SECONDS=0.001: exit 5" test "$code" -eq 5
  stopped tiny
  check "the log names the limit and its source" has tiny/slide.log "wall-clock limit 0.001 s (RACCORD_WALLCLOCK_SECONDS) near"
  check "checkpoint at step 1" test "$(ckpt_step tiny/slide.checkpoint.h5)" -eq 1
  # The restart has no limit: it completes.
  run tiny --restart tiny/slide.checkpoint.h5
  check "restart: exit 0" test "$code" -eq 0
  same_results tiny
  # --wall-clock beats the environment; &run wall_clock is the last resort.
  deck opt
  RACCORD_WALLCLOCK_SECONDS=1000 run opt --wall-clock 0.001 -o opt opt/slide.nml
  check "--wall-clock 0.001 over RACCORD_WALLCLOCK_SECONDS=1000: exit 5" test "$code" -eq 5
  check "the log names --wall-clock" has opt/slide.log "(--wall-clock) near"
  deck key 'wall_clock = 0.001'
  run key -o key key/slide.nml
  check "&run wall_clock = 0.001: exit 5" test "$code" -eq 5
  check "the log names &run wall_clock" has key/slide.log "(&run wall_clock) near"
  run key --restart key/slide.checkpoint.h5 --wall-clock 1000
  check "restart with --wall-clock 1000 over &run wall_clock: exit 0" test "$code" -eq 0
  same_results key
  # A generous limit changes nothing.
  deck long
  run long --wall-clock 1000 -o long long/slide.nml
  check "--wall-clock 1000: exit 0" test "$code" -eq 0
  same_results long
  ;;
kill)
  # Periodic checkpoints every 100 steps; the run is killed (SIGKILL, no
  # chance to clean up) after it has gone on past its last checkpoint. The
  # restart cuts the files back to the checkpoint and continues.
  reference
  deck k9 'checkpoint_every = 100'
  # Freeze on a condition that stays true once met (history past step 540,
  # read from a file raccord only appends to), so a fast machine cannot run
  # past the window between two polls; the checkpoint file is read only
  # while raccord is frozen (it is replaced by rename while it runs).
  start_frozen k9 '[ "$(last_row_step k9/slide.history.txt.part 2>/dev/null || echo 0)" -ge 540 ]' \
    -o k9 k9/slide.nml
  # A checkpoint may have come between the test and the freeze: let it run
  # a little more until it is again past its last checkpoint.
  n=0
  while :; do
    at=$(ckpt_step k9/slide.checkpoint.h5)
    beyond=$(last_row_step k9/slide.history.txt.part)
    [ "$beyond" -le "$at" ] && [ "$n" -lt 50 ] || break
    n=$((n + 1))
    kill -CONT "$pid"
    sleep 0.01
    kill -STOP "$pid"
  done
  if [ -e k9/slide.h5 ]; then fail "raccord completed before it was killed"; finish; fi
  kill -9 "$pid"
  wait "$pid" 2>/dev/null
  check "killed at step >= $beyond, past the checkpoint of step $at" test "$beyond" -gt "$at"
  check "periodic checkpoints are multiples of checkpoint_every" test $((at % 100)) -eq 0
  run k9 --restart k9/slide.checkpoint.h5
  check "restart after kill -9: exit 0" test "$code" -eq 0
  check "the log says where it went on from" has k9/slide.log "restart from k9/slide.checkpoint.h5 at step $at"
  same_results k9
  ;;
refuse)
  # What a restart refuses, each with exit 1 or 2 and a message; and the
  # checkpoint survives a refused restart.
  deck base
  RACCORD_WALLCLOCK_SECONDS=0.001 run base -o base base/slide.nml
  check "setup: stopped with a checkpoint" test "$code" -eq 5 -a -s base/slide.checkpoint.h5
  # A changed scene (mu 0.4 instead of 0.3), same deck name.
  deck changed '' 0.4
  run changed --restart base/slide.checkpoint.h5 changed/slide.nml
  check "changed scene: exit 2" test "$code" -eq 2
  check "changed scene: message names the difference" has changed/run.out "friction = 0.4"
  check "changed scene: message says what to do" has changed/run.out "without --restart"
  # Keys that do not change the results may change.
  deck free 'wall_clock = 500.0, checkpoint_every = 7, output_dir = "elsewhere"'
  mkdir -p freecopy && cp base/* freecopy/
  run freecopy --restart freecopy/slide.checkpoint.h5 free/slide.nml
  check "wall_clock, checkpoint_every, output_dir changed: accepted, exit 0" test "$code" -eq 0
  # A deck of another name.
  mkdir -p other && cp base/slide.nml other/other.nml
  run other --restart base/slide.checkpoint.h5 other/other.nml
  check "deck of another name: exit 2" test "$code" -eq 2
  check "deck of another name: message" has other/run.out "belongs to the run 'slide'"
  # Damaged checkpoints (in dmg/, named as the deck's run).
  mkdir -p dmg && cp base/slide.h5.part base/slide.history.txt.part base/slide.contact1.txt.part dmg/
  head -c 2000 base/slide.checkpoint.h5 > dmg/slide.checkpoint.h5
  run dmg --restart dmg/slide.checkpoint.h5 base/slide.nml
  check "truncated checkpoint: exit 2" test "$code" -eq 2
  check "truncated checkpoint: clear message" has dmg/run.out "truncated or damaged"
  echo "not a checkpoint" > dmg/slide.checkpoint.h5
  run dmg --restart dmg/slide.checkpoint.h5 base/slide.nml
  check "junk checkpoint: exit 2" test "$code" -eq 2
  check "junk checkpoint: clear message" has dmg/run.out "not an HDF5 file"
  cp base/slide.h5.part dmg/slide.checkpoint.h5
  run dmg --restart dmg/slide.checkpoint.h5 base/slide.nml
  check "a results file given as checkpoint: exit 2" test "$code" -eq 2
  check "a results file given as checkpoint: message" has dmg/run.out "not a raccord checkpoint"
  run . --restart missing/slide.checkpoint.h5 base/slide.nml
  check "missing checkpoint: exit 2" test "$code" -eq 2
  check "missing checkpoint: message" has run.out "no checkpoint"
  run . --restart base/slide.h5.part base/slide.nml
  check "--restart of a file not named *.checkpoint.h5: exit 1" test "$code" -eq 1
  mkdir -p lost && cp base/slide.checkpoint.h5 lost/
  run lost --restart lost/slide.checkpoint.h5 base/slide.nml
  check "results .part files gone: exit 2" test "$code" -eq 2
  check "results .part files gone: message" has lost/run.out "is missing"
  mkdir -p hl && cp base/* hl/ && rm hl/slide.history.txt.part
  run hl --restart hl/slide.checkpoint.h5 base/slide.nml
  check "history .part gone: exit 2" test "$code" -eq 2
  check "history .part gone: the other files untouched (still .part, no .incomplete)" \
    sh -c "[ -s hl/slide.h5.part ] && [ -s hl/slide.contact1.txt.part ] && [ -z \"\$(find hl -name '*.incomplete.*')\" ] && cmp -s hl/slide.h5.part base/slide.h5.part"
  # Bad options.
  run . --check --restart base/slide.checkpoint.h5
  check "--check with --restart: exit 1" test "$code" -eq 1
  run . --wall-clock soon base/slide.nml
  check "--wall-clock soon: exit 1" test "$code" -eq 1
  check "--wall-clock soon: message" has run.out "is not a number of seconds"
  RACCORD_WALLCLOCK_SECONDS=-5 run . base/slide.nml
  check "RACCORD_WALLCLOCK_SECONDS=-5: exit 1" test "$code" -eq 1
  deck badkey 'wall_clock = -1.0'
  run badkey -o badkey badkey/slide.nml
  check "&run wall_clock = -1: exit 2" test "$code" -eq 2
  check "&run wall_clock = -1: message names the key" has badkey/run.out "wall_clock"
  # The checkpoint was not harmed by the refusals: it still completes the run.
  run base --restart base/slide.checkpoint.h5
  check "after the refusals the checkpoint still completes the run: exit 0" test "$code" -eq 0
  check "--help lists --wall-clock and --restart (the hpc scripts look for it)" \
    sh -c "'$raccord' --help | grep -q -- --wall-clock && '$raccord' --help | grep -q -- --restart"
  # A fresh run removes a stale checkpoint of the same name.
  RACCORD_WALLCLOCK_SECONDS=0.001 run base -o base base/slide.nml
  run base -o base base/slide.nml
  check "fresh run: exit 0, stale checkpoint deleted" test "$code" -eq 0 -a ! -e base/slide.checkpoint.h5
  check "fresh run: the log says so" has base/slide.log "of an earlier run is deleted"
  ;;
mass_scaling)
  # A mass-scaled run (&time mass_scaling_factor = 3, issue #19): the scaled
  # masses are rebuilt from the scene on restart; stopped by SIGUSR1 past
  # step 460 of 677 (after the peak of the internal energy near step 400, so
  # that the quasi-static check's running maximum must come from the
  # checkpoint; a third of the run left, so that a poll does not miss it)
  # and restarted, it equals the uninterrupted scaled run exactly, and so do
  # the watchers' closing lines.
  rm -rf cont
  deck cont '' 0.3 mortar 'mass_scaling_factor = 3'
  run cont -o cont cont/slide.nml
  [ "$code" -eq 0 ] || { fail "mass-scaled reference run exit $code"; cat cont/run.out; finish; }
  check "the reference run is mass scaled (plan: scaled elements and added mass)" has cont/slide.log "elements scaled"
  check "the reference run takes 3 x fewer steps (677 for 2029)" has cont/slide.log "and 677 steps"
  deck ms '' 0.3 mortar 'mass_scaling_factor = 3'
  start_frozen ms '[ "$(last_row_step ms/slide.history.txt.part 2>/dev/null || echo 0)" -ge 460 ]' -o ms ms/slide.nml
  kill -USR1 "$pid"
  kill -CONT "$pid"
  wait "$pid"
  code=$?
  check "mass scaled, SIGUSR1: exit 5" test "$code" -eq 5
  stopped ms
  run ms --restart ms/slide.checkpoint.h5
  check "mass scaled, restart: exit 0" test "$code" -eq 0
  same_results ms
  same_watch ms
  ;;
*)
  echo "unknown case $case_name"
  exit 1
  ;;
esac
finish
