#!/bin/sh
# The accuracy-cost study (issue #6, doc/accuracy-cost.md): what each choice
# (node-to-segment / mortar P0 / mortar P1, Q4 / Q8, mesh size, loading time,
# damping, time-step factor) buys in accuracy and costs in run time.
#
#   sh tools/accuracy-cost.sh [--quick] [-j N] [OUTDIR]
#
# --quick   2-3 coarse levels of Hertz, Cattaneo-Mindlin and the patch test,
#           a few methods (the CI version, tests/study); default: the full
#           study (4-5 levels, every method, the paper's scene, the knobs)
# -j N      cases at once (default 2)
# OUTDIR    default results/accuracy-cost (results/accuracy-cost-quick)
#
# Steps, each skipping what is already done (a killed study loses nothing;
# a rerun does only what is missing):
#  1. meshes with gmsh into OUTDIR/meshes (input/verification/*/hertz.geo,
#     patch.geo, input/paper/paper.geo, several levels);
#  2. one sweep per problem, OUTDIR/sweeps/<problem>.sweep (templates in
#     input/study/), run by hpc/sweep-local.sh, each case its own raccord
#     process in OUTDIR/<problem>/<case>/ under GNU time
#     (postproc/accuracy-cost/timed-raccord.sh -> time.txt);
#  3. CalculiX on the paper's Q4 meshes when ccx is installed (full study);
#  4. errors per case, <case>/eval.txt, by raccord_study_eval
#     (postproc/accuracy-cost/study_eval.f90);
#  5. tables OUTDIR/<problem>.txt, rates OUTDIR/rates.txt, plots
#     OUTDIR/figures/<problem>.png (postproc/accuracy-cost/error-time.gp).
#
# Executables: $RACCORD and $RACCORD_STUDY_EVAL when set, else those of the
# Release build in $RACCORD_BUILD (default build/), built when missing.
# Exit 0 when every case ran and was evaluated, 1 otherwise, 2 on bad usage.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
quick=0
jobs=2
out=
while [ $# -gt 0 ]; do
  case "$1" in
  --quick) quick=1; shift ;;
  -j) [ $# -ge 2 ] || { echo "accuracy-cost: -j needs a number" >&2; exit 2; }; jobs=$2; shift 2 ;;
  -j[0-9]*) jobs=${1#-j}; shift ;;
  -h | --help) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
  -*) echo "accuracy-cost: unknown option '$1' (usage: accuracy-cost.sh [--quick] [-j N] [OUTDIR])" >&2; exit 2 ;;
  *) [ -z "$out" ] || { echo "accuracy-cost: one OUTDIR only" >&2; exit 2; }; out=$1; shift ;;
  esac
done
case "$jobs" in '' | *[!0-9]* | 0) echo "accuracy-cost: -j wants a positive number, not '$jobs'" >&2; exit 2 ;; esac
[ -n "$out" ] || { if [ "$quick" = 1 ]; then out=results/accuracy-cost-quick; else out=results/accuracy-cost; fi; }
case "$out" in *[\'\"\ ]*) echo "accuracy-cost: OUTDIR may not contain quotes or blanks" >&2; exit 2 ;; esac
mkdir -p "$out/meshes" "$out/sweeps" "$out/figures" || exit 1
out=$(cd "$out" && pwd)
command -v gmsh > /dev/null 2>&1 || { echo "accuracy-cost: gmsh is not installed (sh tools/install-packages.sh)" >&2; exit 1; }

# ---- executables ----
build=${RACCORD_BUILD:-$root/build}
case "$build" in /*) ;; *) build=$root/$build ;; esac
exe=${RACCORD:-}
ev=${RACCORD_STUDY_EVAL:-}
if [ -z "$exe" ] || [ -z "$ev" ]; then
  if [ ! -x "$build/raccord" ] || [ ! -x "$build/postproc/raccord_study_eval" ] || \
     [ -n "$(find "$root/src" "$root/postproc" "$root/CMakeLists.txt" -newer "$build/raccord" -name '*.f90' -print 2>/dev/null | head -n 1)" ]; then
    echo "accuracy-cost: building raccord and raccord_study_eval (Release) in $build"
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null &&
      cmake --build "$build" --target raccord raccord_study_eval -j "$jobs" > /dev/null ||
      { echo "accuracy-cost: build failed" >&2; exit 1; }
  fi
  [ -n "$exe" ] || exe=$build/raccord
  [ -n "$ev" ] || ev=$build/postproc/raccord_study_eval
fi
RACCORD_REAL=$exe
export RACCORD_REAL
timed=$root/postproc/accuracy-cost/timed-raccord.sh

# ---- the study's plan ----
if [ "$quick" = 1 ]; then
  hertz_q4="12 18 24"; hertz_q8=""; hertz_methods="nts p1"
  catt_q4="12 18 24"; catt_q8=""; catt_methods="p1"
  patch_q4="5 10 20"; patch_q8="5"; patch_methods="nts p1"
  paper_q4=""; paper_q8=""; knobs=0
else
  hertz_q4="12 18 24 36 48"; hertz_q8="6 10 12 18"; hertz_methods="nts p0 p1"
  catt_q4="12 18 24 36"; catt_q8="6 8 10 12"; catt_methods="nts p0 p1"
  patch_q4="5 10 20 30"; patch_q8="5 10 12 15"; patch_methods="nts p0 p1"
  paper_q4="0.04 0.028 0.02 0.014 0.01"; paper_q8="0.08 0.056 0.04 0.028 0.02"; knobs=1
fi
PAPER_REF=q8_p1_L5   # the finest mortar P1 Q8 run: the paper scene's reference

method_values() { # short name -> METHOD MULT
  case "$1" in nts) echo "node_to_segment P1" ;; p0) echo "mortar P0" ;; p1) echo "mortar P1" ;; esac
}
even_round() { awk -v v="$1" 'BEGIN { printf "%d\n", 2 * int(v / 2 + 0.5) }'; }

# gmsh NAME GEO ARGS...: OUTDIR/meshes/NAME.msh unless it exists.
mesh() {
  _n=$1; _g=$2; shift 2
  [ -f "$out/meshes/$_n.msh" ] && return 0
  if gmsh "$_g" -2 -format msh41 "$@" -o "$out/meshes/$_n.part.msh" > "$out/meshes/$_n.log" 2>&1 &&
     ! grep "Blossom recombination completed" "$out/meshes/$_n.log" | grep -qv " 0 triangles"; then
    mv "$out/meshes/$_n.part.msh" "$out/meshes/$_n.msh" && rm -f "$out/meshes/$_n.log"
  else
    echo "accuracy-cost: gmsh failed for $_n (see $out/meshes/$_n.log)" >&2
    rm -f "$out/meshes/$_n.part.msh"
    return 1
  fi
}

# ---- 1. meshes and sweep files ----
status=0
# Each sweep file gets a meta file: case elem method level h t_load.
new_sweep() { # problem template
  printf 'template %s\ncolumns MESH:path METHOD MULT ELEM:text LEVEL H%s\n' "$root/input/study/$2" "${3:-}" > "$out/sweeps/$1.sweep.new"
  printf '# case elem method level h t_load\n' > "$out/sweeps/$1.meta.new"
}
end_sweep() { # problem: replace the files only when their text changed (keeps decks' time stamps)
  for f in sweep meta; do
    if cmp -s "$out/sweeps/$1.$f.new" "$out/sweeps/$1.$f"; then rm -f "$out/sweeps/$1.$f.new"
    else mv "$out/sweeps/$1.$f.new" "$out/sweeps/$1.$f"; fi
  done
}

# Hertz and Cattaneo share the Hertz meshes. Q4 level: nb block elements in
# |x| < 2 mm, nc = nearest even to 7 nb/6 on the cylinder (ratio of the
# verification meshes); Q8: the same with nb/2 elements (same node spacing).
hertz_mesh() { # elem nb -> mesh name
  _nc=$(even_round "$(awk -v n="$2" 'BEGIN { print 7 * n / 6 }')")
  _o=1; [ "$1" = q8 ] && _o=2
  mesh "hertz_$1_nb$2" "$root/input/verification/hertz/hertz.geo" -setnumber nb "$2" -setnumber nc "$_nc" \
    -setnumber hmax 4.0 -setnumber order "$_o" || status=1
  echo "hertz_$1_nb$2"
}
for prob in hertz cattaneo; do
  if [ "$prob" = hertz ]; then methods=$hertz_methods; l4=$hertz_q4; l8=$hertz_q8
  else methods=$catt_methods; l4=$catt_q4; l8=$catt_q8; fi
  new_sweep $prob $prob.nml
  [ "$prob" = hertz ] && { echo "set T_RAMP 2.5e-4"; echo "set T_END 4.0e-4"; echo "set DAMPING 2.5e5"; echo "set SAFETY 0.9"; } >> "$out/sweeps/$prob.sweep.new"
  for elem in q4 q8; do
    if [ $elem = q4 ]; then levels=$l4; else levels=$l8; fi
    lev=0
    for nb in $levels; do
      lev=$((lev + 1))
      m=$(hertz_mesh $elem "$nb")
      [ $elem = q8 ] && h=$(awk -v n="$nb" 'BEGIN { printf "%.6g\n", 2 / n }')
      [ $elem = q4 ] && h=$(awk -v n="$nb" 'BEGIN { printf "%.6g\n", 4 / n }')
      for meth in $methods; do
        echo "case ${elem}_${meth}_L$lev ../meshes/$m.msh $(method_values $meth) $(echo $elem | tr q Q) $lev $h" >> "$out/sweeps/$prob.sweep.new"
        echo "${elem}_${meth}_L$lev $elem $meth $lev $h 2.5e-4" >> "$out/sweeps/$prob.meta.new"
      done
    done
  done
  end_sweep $prob
done

# Patch test: nl lower : 4 nl upper elements; the upper grading g = 1.0076^(20/nu)
# keeps the verification mesh's spacing ratio; h = upper (slave) mean spacing.
new_sweep patch patch.nml
for elem in q4 q8; do
  if [ $elem = q4 ]; then levels=$patch_q4; o=1; else levels=$patch_q8; o=2; fi
  lev=0
  for nl in $levels; do
    lev=$((lev + 1)); nu=$((4 * nl))
    g=$(awk -v n=$nu 'BEGIN { printf "%.10f\n", 1.0076 ^ (20 / n) }')
    mesh "patch_${elem}_nl$nl" "$root/input/verification/patch/patch.geo" -setnumber nl "$nl" -setnumber nu "$nu" \
      -setnumber g "$g" -setnumber order $o || status=1
    h=$(awk -v n=$nu -v o=$o 'BEGIN { printf "%.6g\n", 1 / (n * o) }')
    for meth in $patch_methods; do
      echo "case ${elem}_${meth}_L$lev ../meshes/patch_${elem}_nl$nl.msh $(method_values $meth) $(echo $elem | tr q Q) $lev $h" >> "$out/sweeps/patch.sweep.new"
      echo "${elem}_${meth}_L$lev $elem $meth $lev $h 4e-6" >> "$out/sweeps/patch.meta.new"
    done
  done
done
end_sweep patch

# The paper's scene: hb block element size in |x| < 0.7 (Q8: twice the Q4
# value, same node spacing), nd = nearest even to 1.12/hb disc elements,
# hcd = 4 hb at the disc top (at most 0.3); h = slave node spacing.
if [ -n "$paper_q4$paper_q8" ]; then
  new_sweep paper paper.nml
  for elem in q4 q8; do
    if [ $elem = q4 ]; then levels=$paper_q4; o=1; else levels=$paper_q8; o=2; fi
    lev=0
    for hb in $levels; do
      lev=$((lev + 1))
      nd=$(even_round "$(awk -v h="$hb" 'BEGIN { print 1.12 / h }')")
      hcd=$(awk -v h="$hb" 'BEGIN { v = 4 * h; if (v > 0.3) v = 0.3; printf "%.4g\n", v }')
      mesh "paper_${elem}_hb$hb" "$root/input/paper/paper.geo" -setnumber hb "$hb" -setnumber nd "$nd" \
        -setnumber hcd "$hcd" -setnumber order $o || status=1
      h=$(awk -v v="$hb" -v o=$o 'BEGIN { printf "%.6g\n", v / o }')
      for meth in nts p0 p1; do
        echo "case ${elem}_${meth}_L$lev ../meshes/paper_${elem}_hb$hb.msh $(method_values $meth) $(echo $elem | tr q Q) $lev $h" >> "$out/sweeps/paper.sweep.new"
        echo "${elem}_${meth}_L$lev $elem $meth $lev $h 2e-5" >> "$out/sweeps/paper.meta.new"
      done
    done
  done
  end_sweep paper
fi

# Quasi-static knobs on Hertz, Q4 mortar P1, nb = 24: loading time T x 0.5 .. 4
# (hold to 1.6 T), damping alpha x 0, 0.5, 2, time-step safety 0.5 .. 0.95.
if [ "$knobs" = 1 ]; then
  m=$(hertz_mesh q4 24)
  new_sweep knobs hertz.nml " T_RAMP T_END DAMPING SAFETY"
  knob() { # name t_ramp damping safety
    echo "case $1 ../meshes/$m.msh mortar P1 Q4 3 0.166667 $2 $(awk -v t="$2" 'BEGIN { printf "%.6g\n", 1.6 * t }') $3 $4" >> "$out/sweeps/knobs.sweep.new"
    echo "$1 q4 p1 3 0.166667 $2" >> "$out/sweeps/knobs.meta.new"
  }
  knob T0.5 1.25e-4 2.5e5 0.9; knob T1 2.5e-4 2.5e5 0.9; knob T2 5.0e-4 2.5e5 0.9; knob T4 1.0e-3 2.5e5 0.9
  knob alpha0 2.5e-4 0.0 0.9; knob alpha0.5 2.5e-4 1.25e5 0.9; knob alpha2 2.5e-4 5.0e5 0.9
  knob safety0.5 2.5e-4 2.5e5 0.5; knob safety0.7 2.5e-4 2.5e5 0.7; knob safety0.95 2.5e-4 2.5e5 0.95
  end_sweep knobs
fi
problems="hertz cattaneo patch"
[ -f "$out/sweeps/paper.sweep" ] && [ -n "$paper_q4$paper_q8" ] && problems="$problems paper"
[ "$knobs" = 1 ] && problems="$problems knobs"

# ---- 2. runs ----
for prob in $problems; do
  echo "accuracy-cost: $prob: $(grep -c '^case ' "$out/sweeps/$prob.sweep") cases, $jobs at a time"
  # Decks are written without sweep-gen's --check of every deck (a model
  # build each, minutes for a complete sweep on a loaded machine): the runner
  # checks each case it runs, and complete cases need no check.
  sh "$root/hpc/sweep-gen.sh" --no-check -r "$timed" -o "$out/$prob" "$out/sweeps/$prob.sweep" > "$out/$prob.sweep-log.txt" 2>&1
  code=$?
  if [ "$code" -eq 0 ]; then
    sh "$root/hpc/sweep-local.sh" -j "$jobs" -r "$timed" "$out/$prob" >> "$out/$prob.sweep-log.txt" 2>&1
    code=$?
  fi
  tail -n 1 "$out/$prob.sweep-log.txt"
  case "$code" in 0) ;; 130 | 143) exit "$code" ;; *) status=1 ;; esac
done

# ---- 3. CalculiX (full study, when installed): the paper's Q4 meshes ----
if [ -n "$paper_q4" ] && command -v "${CCX:-ccx}" > /dev/null 2>&1; then
  lev=0
  for hb in $paper_q4; do
    lev=$((lev + 1))
    d=$out/paper/ccx_L$lev
    [ -f "$d/ccx_pressure.txt" ] && [ -f "$d/time.txt" ] && continue
    mkdir -p "$d"
    if /usr/bin/time -f '%e %U %S %M' -o "$d/time.txt.part" sh "$root/tools/calculix/fig1b-ccx.sh" "$d" \
        "$out/meshes/paper_q4_hb$hb.msh" > "$d/run.out" 2>&1 && [ -f "$d/ccx_pressure.txt" ]; then
      tail -n 1 "$d/time.txt.part" > "$d/time.txt"
      echo "accuracy-cost: CalculiX on level $lev done"
    else
      echo "accuracy-cost: CalculiX on level $lev failed (see $d/run.out)" >&2
      status=1
    fi
    rm -f "$d/time.txt.part"
  done
fi

# ---- 4. errors per case ----
evaluate() { # prob case t_load
  d=$out/$1/$2
  case "$2" in
    ccx_*) src=$d/ccx_pressure.txt ;;
    *) src=$d/case.h5 ;;
  esac
  [ -f "$src" ] || return 0
  if [ -f "$d/eval.txt" ] && [ ! "$src" -nt "$d/eval.txt" ]; then
    case "$1" in paper | knobs) ;; *) return 0 ;; esac
    # Reference-based errors are redone when the reference is newer.
    [ ! "$refsrc" -nt "$d/eval.txt" ] && return 0
  fi
  case "$1" in
    hertz) set -- hertz "$d" "$3" ;;
    knobs) set -- hertz "$d" "$3" "$out/knobs/T4" ;;
    cattaneo) set -- cattaneo "$d" ;;
    patch) set -- patch "$d" ;;
    paper) case "$2" in ccx_*) set -- ccx "$src" "$out/paper/$PAPER_REF" ;; *) set -- paper "$d" "$out/paper/$PAPER_REF" ;; esac ;;
  esac
  if "$ev" "$@" > "$d/eval.txt.part" 2> "$d/eval.err"; then
    mv "$d/eval.txt.part" "$d/eval.txt"; rm -f "$d/eval.err"
  else
    echo "accuracy-cost: evaluation failed for $d: $(cat "$d/eval.err")" >&2
    rm -f "$d/eval.txt.part"; status=1
  fi
}
for prob in $problems; do
  refsrc=/nonexistent
  [ "$prob" = paper ] && refsrc=$out/paper/$PAPER_REF/case.h5
  [ "$prob" = knobs ] && refsrc=$out/knobs/T4/case.h5
  if [ "$prob" = paper ] || [ "$prob" = knobs ]; then
    [ -f "$refsrc" ] || { echo "accuracy-cost: $prob: the reference run $refsrc is missing: no errors" >&2; status=1; continue; }
  fi
  grep -v '^#' "$out/sweeps/$prob.meta" | while read -r c elem meth lev h tl; do
    evaluate "$prob" "$c" "$tl"
  done
  if [ "$prob" = paper ]; then
    for d in "$out"/paper/ccx_L*; do [ -d "$d" ] && evaluate paper "$(basename "$d")" 0; done
  fi
done

# ---- 5. tables, rates, plots ----
for prob in $problems; do
  meta=$out/sweeps/$prob.meta
  if [ "$prob" = paper ]; then
    cp "$meta" "$meta.ccx"
    for d in "$out"/paper/ccx_L*; do
      [ -d "$d" ] || continue
      lev=${d##*_L}
      hb=$(echo $paper_q4 | awk -v l="$lev" '{ print $l }')
      echo "ccx_L$lev q4 ccx $lev $hb 2e-5" >> "$meta.ccx"
    done
    meta=$meta.ccx
  fi
  sh "$root/postproc/accuracy-cost/table.sh" "$meta" "$out/$prob" > "$out/$prob.txt.part" &&
    mv "$out/$prob.txt.part" "$out/$prob.txt" || status=1
done
sh "$root/postproc/accuracy-cost/rates.sh" "$out" $problems > "$out/rates.txt.part" && mv "$out/rates.txt.part" "$out/rates.txt" || status=1
if command -v gnuplot > /dev/null 2>&1; then
  for prob in $problems; do
    [ "$prob" = knobs ] && continue
    gnuplot -e "table='$out/$prob.txt'; problem='$prob'; output='$out/figures/$prob.png'" \
      "$root/postproc/accuracy-cost/error-time.gp" 2> "$out/figures/$prob.gnuplot.txt" || { status=1; cat "$out/figures/$prob.gnuplot.txt" >&2; }
  done
else
  echo "accuracy-cost: gnuplot is not installed: no plots" >&2
fi
echo "accuracy-cost: tables $out/<problem>.txt, rates $out/rates.txt, plots $out/figures/"
exit $status
