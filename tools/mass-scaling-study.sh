#!/bin/sh
# Mass-scaling section of the accuracy-cost study (issue #19,
# doc/accuracy-cost.md "Mass scaling"): the paper's scene (Fig. 2(a),
# loading half of the cycle, input/study/paper.nml) and the study's Hertz
# case (input/study/hertz.nml, Q4 nb = 24, mortar P1), each unscaled and
# with &time mass_scaling_factor = F for several F; errors of each scaled
# run against the unscaled one (raccord_study_eval) and run times.
#
#   sh tools/mass-scaling-study.sh [OUTDIR]       (default results/mass-scaling)
#
# Cases run one at a time (run times are compared), each skipped when done.
# Executables: $RACCORD and $RACCORD_STUDY_EVAL, else the Release build in
# $RACCORD_BUILD (default build/). Needs gmsh for the Hertz mesh.
# Output: OUTDIR/<problem>/<case>/ (run, eval.txt, time.txt) and the table
# OUTDIR/mass-scaling.txt; with gnuplot the plot OUTDIR/mass-scaling.png
# (postproc/accuracy-cost/mass-scaling.gp).
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-results/mass-scaling}
mkdir -p "$out/meshes" || exit 1
out=$(cd "$out" && pwd)
build=${RACCORD_BUILD:-$root/build}
case "$build" in /*) ;; *) build=$root/$build ;; esac
exe=${RACCORD:-$build/raccord}
ev=${RACCORD_STUDY_EVAL:-$build/postproc/raccord_study_eval}
for f in "$exe" "$ev"; do [ -x "$f" ] || { echo "mass-scaling-study: $f not found (build Release first)" >&2; exit 1; }; done
RACCORD_REAL=$exe
export RACCORD_REAL
timed=$root/postproc/accuracy-cost/timed-raccord.sh
factors=${FACTORS:-"2 3 4 5 6 7 8 10 12"}
status=0

# deck PROBLEM CASE TEMPLATE MESH METHOD MULT ELEM FACTOR: OUTDIR/PROBLEM/CASE/case.nml
deck() {
  d=$out/$1/$2
  mkdir -p "$d"
  ms=""
  [ "$8" = 0 ] || ms=", mass_scaling_factor = $8"
  sed -e "s|@CASE@|$2|g; s|@MESH@|'$4'|; s|@METHOD@|'$5'|; s|@MULT@|'$6'|; s|@ELEM@|$7|; s|@LEVEL@|0|; s|@H@|0|" \
      -e "s|@T_RAMP@|2.5e-4|; s|@T_END@|4.0e-4|; s|@DAMPING@|2.5e5|; s|@SAFETY@|0.9|" \
      -e "/^&time/,/^\//s|^\(  t_end = .*\)$|\1$ms|" "$root/input/study/$3" > "$d/case.nml"
}
# run PROBLEM CASE [EVAL ARGS...]
run() {
  d=$out/$1/$2
  shift 2
  if [ ! -f "$d/case.h5" ]; then
    (cd "$d" && sh "$timed" -q -o . case.nml > run.out 2>&1) || { echo "mass-scaling-study: $d failed" >&2; status=1; return; }
  fi
  [ $# -gt 0 ] && { "$ev" "$@" > "$d/eval.txt" 2> "$d/eval.err" || { echo "evaluation failed: $d" >&2; status=1; }; }
}

hmesh=$out/meshes/hertz_q4_nb24.msh
[ -f "$hmesh" ] || gmsh "$root/input/verification/hertz/hertz.geo" -2 -format msh41 -setnumber nb 24 -setnumber nc 28 \
  -setnumber hmax 4.0 -setnumber order 1 -o "$hmesh" > /dev/null 2>&1 || { echo "gmsh failed" >&2; exit 1; }

# problem template mesh method mult elem: unscaled reference, then each factor
series() {
  p=$1
  deck "$p" F1 "$2" "$3" "$4" "$5" "$6" 0
  run "$p" F1
  for f in $factors; do
    deck "$p" "F$f" "$2" "$3" "$4" "$5" "$6" "$f"
    case "$2" in
      paper.nml) run "$p" "F$f" paper "$out/$p/F$f" "$out/$p/F1" ;;
      hertz.nml) run "$p" "F$f" hertz "$out/$p/F$f" 2.5e-4 "$out/$p/F1" ;;
    esac
  done
  case "$2" in hertz.nml) "$ev" hertz "$out/$p/F1" 2.5e-4 > "$out/$p/F1/eval.txt" ;; esac
}
series paper_q4_p1 paper.nml "$root/input/paper/paper_q4_fine.msh" mortar P1 Q4
series paper_q4_nts paper.nml "$root/input/paper/paper_q4_fine.msh" node_to_segment P1 Q4
series paper_q8_p1 paper.nml "$root/input/paper/paper_q8.msh" mortar P1 Q8
series hertz_q4_p1 hertz.nml "$hmesh" mortar P1 Q4

# Table: problem factor steps cpu_s cpu_ratio err_peak err_force err_l2 (Hertz: change of peak and force
# against the unscaled run, profile change), largest KE/IE of the quasi-static check, added mass % per body
{
  echo "# problem factor steps cpu_s cpu_ratio err_peak err_force err_l2 ke_ratio_max added_mass_pct"
  for p in paper_q4_p1 paper_q4_nts paper_q8_p1 hertz_q4_p1; do
    # CPU time (user + system) of the raccord process: the fair measure on a
    # shared machine (doc/accuracy-cost.md section 12)
    w1=$(awk '{ print $2 + $3 }' "$out/$p/F1/time.txt" 2>/dev/null)
    for f in 1 $factors; do
      d=$out/$p/F$f
      [ -f "$d/time.txt" ] || continue
      st=$(grep -o '[0-9]* steps in' "$d/case.log" | tail -n 1 | awk '{ print $1 }')
      w=$(awk '{ print $2 + $3 }' "$d/time.txt")
      get() { awk -v k="$1" '$1 == k { print $2 }' "$d/eval.txt" 2>/dev/null; }
      if [ "$f" = 1 ]; then ep=0; ef=0; el=0; else
        # Hertz: errors are against the closed form; the change against the
        # unscaled run is (1 + e_F)/(1 + e_1) - 1, the profile change change_ref.
        case "$p" in hertz*)
          g1() { awk -v k="$1" '$1 == k { print $2 }' "$out/$p/F1/eval.txt"; }
          ep=$(awk -v a="$(get err_peak)" -v b="$(g1 err_peak)" 'BEGIN { printf "%.6e", (1 + a) / (1 + b) - 1 }')
          ef=$(awk -v a="$(get err_force)" -v b="$(g1 err_force)" 'BEGIN { printf "%.6e", (1 + a) / (1 + b) - 1 }')
          el=$(get change_ref) ;;
                     *) ep=$(get err_peak); ef=$(get err_force); el=$(get err_l2) ;; esac
      fi
      ke=$(grep -o 'largest kinetic / internal energy [^ ]*' "$d/case.log" | awk '{ print $NF }')
      am=$(grep '^mass    body' "$d/case.log" | grep -o 'added mass [^ ]*' | awk '{ print $3 }' | paste -sd/ -)
      echo "$p $f ${st:-?} $w $(awk -v a="$w" -v b="$w1" 'BEGIN { printf "%.3f", a / b }') ${ep:-?} ${ef:-?} ${el:-?} ${ke:--} ${am:--}"
    done
  done
} > "$out/mass-scaling.txt"
cat "$out/mass-scaling.txt"
if command -v gnuplot > /dev/null 2>&1; then
  gnuplot -e "table='$out/mass-scaling.txt'; output='$out/mass-scaling.png'" "$root/postproc/accuracy-cost/mass-scaling.gp" || status=1
fi
exit $status
