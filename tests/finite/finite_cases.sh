#!/bin/sh
# The raccord program with finite-strain bodies, end to end: one case per
# CTest entry finite_<case>.
#
#   sh finite_cases.sh CASE RACCORD SOURCE_DIR WORK_DIR
#
# CASE        refuse, invert, restart
# refuse      decks whose kinematics and material do not go together exit 2
#             before anything is written, naming the body and what to write
# invert      a block driven through its support inverts: exit 3, the message
#             names the element, the body and the time, and nothing looks complete
# restart     a neo-Hooke slider pressed and dragged on a steel base (mixed
#             scene, friction, variable step): stopped by SIGUSR1 in mid-run
#             and restarted, its results equal the continuous run's bit for bit
# history     the block squeezed to 40 %: its step shrinks with the mesh, so
#             the run takes far more steps than planned; /history of the
#             results file has every row of the text history (issue #18: the
#             rows past the planned count were missing), value for value
# Needs sh, awk, cmp, h5dump and h5diff (hdf5-tools); 77 = skipped.
set -u

case_name=$1
raccord=$2
src=$3
work=$4

. "$src/tests/support/cases.sh"

need_tools h5dump h5diff
fresh_work

# block DECK BODY_KEYS [TOP_DISPLACEMENT]: the unit block of tests/finite/data,
# bottom held in y, sides in x, top driven down.
block() {
  cat > "$1" <<EOD
&mesh file = '$src/tests/finite/data/block.msh' /
&body name = 'block', young = 7000.0, poisson = 0.3, density = 1.0e-9, $2 /
&amplitude name = 'ramp', time = 0.0, 1.0e-4, value = 0.0, 1.0 /
&boundary set = 'bottom', type = 'fixed', components = 'y' /
&boundary set = 'left', type = 'fixed', components = 'x' /
&boundary set = 'right', type = 'fixed', components = 'x' /
&boundary set = 'top', type = 'displacement', components = 'y', value = 0.0, ${3:--0.5}, amplitude = 'ramp' /
&time t_end = 1.2e-4, damping = 1.0e6 /
EOD
}

# same_history H5 TEXT: /history of H5 holds the rows of the text history
# TEXT, value for value (the text prints 17 digits: a double exactly).
same_history() {
  h5dump -d /history -m %.17g -y -w 0 "$1" 2> /dev/null |
    awk '/^ *DATA \{/ && !seen { on = 1; seen = 1; next } on && /^ *\}/ { on = 0 } on { print }' > "$1.rows"
  awk -F'[ ,]+' 'FNR == NR { n++; for (i = 1; i <= NF; i++) if ($i != "") { k[n]++; v[n, k[n]] = $i + 0 }; next }
    /^#/ { next }
    { m++; nf = 0
      for (i = 1; i <= NF; i++) if ($i != "") { nf++; if (!((m, nf) in v) || v[m, nf] != $i + 0) bad++ }
      if (nf != k[m]) bad++ }
    END { if (m != n || bad) { print "text rows " m ", HDF5 rows " n ", differing values " bad + 0; exit 1 } }' \
    "$1.rows" "$2"
}

case "$case_name" in
history)
  block sq.nml "kinematics = 'finite', material = 'neo_hooke'" -0.6
  echo "&output frames = 5, history_every = 1 /" >> sq.nml
  "$raccord" -q -o out sq.nml > run.out 2>&1
  code=$?
  check "squeezed block: exit 0 (got $code)" test "$code" -eq 0
  [ "$code" -eq 0 ] || { cat run.out; finish; }
  planned=$(awk '/^time .* steps$/ { print $(NF - 1); exit }' out/sq.log)
  done_steps=$(awk '/done: [0-9]+ steps/ { for (i = 1; i < NF; i++) if ($i == "done:") print $(i + 1) }' out/sq.log)
  rows=$(grep -vc '^#' out/sq.history.txt)
  check "the step shrank: $done_steps steps done, $planned planned (at least 20 % more)" \
    test "$done_steps" -gt $((planned + planned / 5))
  check "the text history has a row per step ($rows rows)" test "$rows" -eq $((done_steps + 1))
  check "/history has every row of the text history, value for value (more than one append block)" \
    same_history out/sq.h5 out/sq.history.txt
  check "/history is chunked, unlimited and checksummed" sh -c \
    "h5dump -H -p -d /history out/sq.h5 | grep -q H5S_UNLIMITED && h5dump -H -p -d /history out/sq.h5 | grep -q FLETCHER32"
  "$raccord" --verify out/sq.h5 > verify.out 2>&1
  code=$?
  check "raccord --verify of the results: exit 0 (got $code)" test "$code" -eq 0
  ;;
refuse)
  refused finite_linear "kinematics = 'finite'" "material = 'neo_hooke'" "kinematics = 'small'"
  refused small_neo "material = 'neo_hooke'" "kinematics = 'finite'" "material = 'linear_elastic'"
  refused small_svk "kinematics = 'small', material = 'svk'" "kinematics = 'finite'"
  refused finite_plane_stress "kinematics = 'finite', material = 'neo_hooke', hypothesis = 'plane_stress'" \
    "plane strain only" "hypothesis = 'plane_strain'"
  refused unknown_material "kinematics = 'finite', material = 'mooney'" "unknown material 'mooney'" "'neo_hooke'"
  refused unknown_kinematics "kinematics = 'large'" "unknown kinematics 'large'" "'finite'"
  refused svk_mean "kinematics = 'finite', material = 'svk', volumetric = 'mean_dilatation'" \
    "mean dilatation is built for neo_hooke only"
  refused small_volumetric "volumetric = 'full'" "finite-strain option"
  # and the accepted pairs are named in the plan
  block ok.nml "kinematics = 'finite', material = 'neo_hooke'"
  "$raccord" --check ok.nml > check.txt 2>&1
  code=$?
  check "--check of a finite body: exit 0 (got $code)" test "$code" -eq 0
  check "--check names kinematics, material and the Q4 treatment" has check.txt \
    "plane strain, finite strain, neo_hooke (Q4 mean_dilatation)"
  check "--check writes the keys back" has check.txt "kinematics = 'finite'"
  ;;
invert)
  block inv.nml "kinematics = 'finite', material = 'neo_hooke'" -1.3
  "$raccord" -o out inv.nml > stdout.txt 2> stderr.txt
  code=$?
  check "driven through its support: exit 3 (got $code)" test "$code" -eq 3
  check "the message names the body" has stderr.txt "of body 'block'"
  check "the message names an element" sh -c "grep -qE 'element [0-9]+ of body' stderr.txt"
  check "the message gives the time" has stderr.txt "at t = "
  check "no Fortran runtime message or backtrace" sh -c "! grep -qiE 'backtrace|fortran runtime|error stop' stderr.txt"
  check "nothing looks complete" test -z "$(find out \( -name inv.h5 -o -name inv.xmf -o -name inv.history.txt \) -print)"
  check "the results are marked incomplete" test -n "$(find out -name '*.incomplete.*' -print)"
  ;;
restart)
  deck() {
    mkdir -p "$1"
    cat > "$1/slide.nml" <<EOD
! A neo-Hooke slider on a steel base, mu = 0.3: pressed, pulled right, then back.
&mesh file = '$src/input/verification/sliding/sliding_q4.msh' /
&body name = 'base', elset = 'base', young = 200000.0, poisson = 0.3, density = 7.8e-9 /
&body name = 'slider', elset = 'slider', young = 2000.0, poisson = 0.45, density = 1.2e-9,
  kinematics = 'finite', material = 'neo_hooke' /
&amplitude name = 'press', time = 0.0, 4.0e-5, value = 0.0, 1.0 /
&amplitude name = 'pull', time = 5.0e-5, 8.0e-5, 1.2e-4, value = 0.0, 1.0, -1.0 /
&boundary set = 'base_bottom', type = 'fixed', components = 'xy' /
&boundary set = 'slider_top', type = 'pressure', pressure = 100.0, amplitude = 'press' /
&boundary set = 'slider_right', type = 'traction', value = 120.0, 0.0, amplitude = 'pull' /
&time t_end = 1.3e-4, damping = 2.0e6 /
&output frames = 13, history_every = 7 /
&contact_pair slave = 'slider_bottom', master = 'base_top', friction = 0.3, method = 'mortar' /
EOD
  }
  deck cont
  "$raccord" -q -o cont cont/slide.nml > cont/run.out 2>&1
  code=$?
  check "continuous run: exit 0 (got $code)" test "$code" -eq 0
  [ "$code" -eq 0 ] || { cat cont/run.out; finish; }
  check "the slider is finite strain with a variable step" has cont/slide.log "finite strain, neo_hooke"
  deck usr1
  usr1_restart_equals slide
  ;;
*)
  echo "unknown case $case_name" >&2
  exit 2
  ;;
esac
finish
