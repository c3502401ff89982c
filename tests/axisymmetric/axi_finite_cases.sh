#!/bin/sh
# The raccord program with axisymmetric finite-strain bodies, end to end:
# one case per CTest entry axi_finite_<case>.
#
#   sh axi_finite_cases.sh CASE RACCORD SOURCE_DIR WORK_DIR
#
# CASE        restart, check, nts_friction, weighted_friction
# restart     a neo-Hooke hollow ball (Q8) squashed by a j2 plate in finite
#             strain, mortar with friction, variable step: stopped by SIGUSR1
#             in mid-run and restarted, its results equal the continuous
#             run's bit for bit
# check       --check of that scene names both bodies' kinematics, and the
#             run's log the variable step
# nts_friction the same scene with node-to-segment and friction, the pole
#             pushed down 0.25 (a quarter of the radius): the multipliers
#             converge at every step on this coarse curved master (they
#             did not once), and contact gives at most 1e-3 of the energy
# weighted_friction the ball as the (Q8, curved) slave under mortar with
#             conditions = 'weighted' and friction, held to t = 0.25 (3500
#             steps): every step's multipliers converge (4 steps cycled
#             stick/slip until max_iterations before the least-index rule
#             of raccord_multiplier_solver), no energy from contact
# Needs sh, awk, cmp, h5dump and h5diff (hdf5-tools); 77 = skipped.
set -u

case_name=$1
raccord=$2
src=$3
work=$4

. "$src/tests/support/cases.sh"

need_tools h5dump h5diff
fresh_work

deck() {
  mkdir -p "$1"
  cat > "$1/ball.nml" <<EOD
! A neo-Hooke hollow ball squashed by a j2 plate, both finite strain, axisymmetric.
&mesh file = '$src/tests/axisymmetric/data/ball_q8.inp' /
&body name = 'ball', elset = 'ball', young = 10.0, poisson = 0.45, density = 1.0e-3,
  hypothesis = 'axisymmetric', kinematics = 'finite', material = 'neo_hooke' /
&body name = 'plate', elset = 'plate', young = 200.0, poisson = 0.3, density = 1.0e-3,
  hypothesis = 'axisymmetric', kinematics = 'finite', material = 'j2', yield_stress = 0.5 /
&amplitude name = 'ramp', time = 0.0, 0.15, value = 0.0, 1.0 /
&boundary set = 'b_bottom', type = 'fixed', components = 'y' /
&boundary set = 'p_top', type = 'displacement', components = 'xy', value = 0.0, -0.16, amplitude = 'ramp' /
&time t_end = 0.2, damping = 20.0 /
&output frames = 5, history_every = 7 /
&contact_pair slave = 'p_bottom', master = 'b_right', friction = 0.2, method = 'mortar' /
EOD
}

case "$case_name" in
restart)
  deck cont
  "$raccord" -q -o cont cont/ball.nml > cont/run.out 2>&1
  code=$?
  check "continuous run: exit 0 (got $code)" test "$code" -eq 0
  [ "$code" -eq 0 ] || { cat cont/run.out; finish; }
  deck usr1
  usr1_restart_equals ball
  ;;
check)
  deck chk
  "$raccord" --check chk/ball.nml > chk/check.txt 2>&1
  code=$?
  check "--check: exit 0 (got $code)" test "$code" -eq 0
  check "--check names the ball's kinematics and law" has chk/check.txt "finite strain, neo_hooke"
  check "--check names the plate's" has chk/check.txt "finite strain, j2"
  "$raccord" -q -o chk chk/ball.nml > chk/run.out 2>&1
  code=$?
  check "run: exit 0 (got $code)" test "$code" -eq 0
  check "the log says the step follows the deforming mesh" has chk/ball.log "the step follows the deforming mesh"
  ;;
nts_friction)
  deck nts
  sed -e "s/method = 'mortar'/method = 'node_to_segment'/" -e "s/value = 0.0, -0.16,/value = 0.0, -0.25,/" \
    nts/ball.nml > nts/ball_nts.nml
  check "the deck is node-to-segment, pole pushed 0.25" has nts/ball_nts.nml "node_to_segment"
  "$raccord" -q -o nts nts/ball_nts.nml > nts/run.out 2>&1
  code=$?
  check "run: exit 0 (got $code)" test "$code" -eq 0
  check "every step's multipliers converged" has nts/ball_nts.log ", 0 unconverged steps"
  given=$(awk '/energy given by contact: at most/ { for (i = 1; i < NF; i++) if ($i == "most") print $(i + 1) }' nts/ball_nts.log)
  check "contact gave at most 1e-3 of the energy scale (got ${given:-none})" \
    awk -v g="${given:-1}" 'BEGIN { exit !(g + 0 <= 1.0e-3) }'
  ;;
weighted_friction)
  deck wf
  sed -e "s/slave = 'p_bottom', master = 'b_right'/slave = 'b_right', master = 'p_bottom'/" \
    -e "s/method = 'mortar'/method = 'mortar', conditions = 'weighted'/" -e "s/t_end = 0.2,/t_end = 0.25,/" \
    wf/ball.nml > wf/ball_wf.nml
  check "the deck is the ball as slave, weighted, to t = 0.25" has wf/ball_wf.nml "slave = 'b_right', master = 'p_bottom', friction = 0.2, method = 'mortar', conditions = 'weighted'"
  "$raccord" -q -o wf wf/ball_wf.nml > wf/run.out 2>&1
  code=$?
  check "run: exit 0 (got $code)" test "$code" -eq 0
  check "every step's multipliers converged" has wf/ball_wf.log ", 0 unconverged steps"
  given=$(awk '/energy given by contact: at most/ { for (i = 1; i < NF; i++) if ($i == "most") print $(i + 1) }' wf/ball_wf.log)
  check "contact gave at most 1e-3 of the energy scale (got ${given:-none})" \
    awk -v g="${given:-1}" 'BEGIN { exit !(g + 0 <= 1.0e-3) }'
  ;;
*)
  echo "unknown case $case_name"
  exit 2
  ;;
esac
finish
