#!/bin/sh
# The figures of Baillet & Sassi (2003), section 4, reproduced by raccord.
#
#   sh tools/paper-figures.sh [OUTDIR] [FIGURE ...]
#
# OUTDIR (default results/paper; relative to the current directory) gets
#   OUTDIR/runs/<deck>/      the runs of input/paper/<deck>.nml (and of the
#                            slow copies, OUTDIR/decks/slow_*.nml: T doubled)
#   OUTDIR/figures/          <figure>.png and <figure>.pdf (gnuplot pngcairo / pdfcairo)
#   OUTDIR/numbers.txt       the numbers of doc/reproduction.md (postproc/paper/numbers.sh)
#   OUTDIR/calculix/         the CalculiX run of Fig. 1(b) (tools/calculix/fig1b-ccx.sh),
#                            when ccx is installed
#   OUTDIR/calculix-finite/  the CalculiX run with NLGEOM and neo-Hooke bodies
#                            (tools/calculix/finite-ccx.sh), figure 'finite' only
#   OUTDIR/finite-numbers.txt  the numbers of the finite-strain section of
#                            doc/reproduction.md (postproc/paper/finite-numbers.sh)
#   OUTDIR/calculix-plastic/ the CalculiX run with a *PLASTIC block, loaded and
#                            unloaded (tools/calculix/plastic-ccx.sh), figure
#                            'plastic' only
# FIGURE is any of fig1b fig2a fig2b fig3 fig4a fig4b cycle numbers (default:
# all of them), or finite: the paper's test with finite strain (neo-Hooke
# bodies) beside small strain, not drawn by default (its four runs take
# about 10 times the CPU of the small-strain ones), or plastic: the paper's
# test with a J2 layer, loaded and unloaded, against CalculiX *PLASTIC, not
# drawn by default either (two runs of 5-9 min, and CalculiX about
# 40 min on the fine mesh). Builds raccord (Release, in $RACCORD_BUILD, default build/)
# when needed, runs only the decks whose results are missing or older than
# their deck, two at a time, then draws. Rerunning does only what is missing;
# delete OUTDIR/runs/<deck> to force a run. Exit 0 when every figure was
# drawn, 1 when a run or a plot failed, 2 on a bad argument.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-results/paper}
[ "$#" -gt 0 ] && shift
figs=${*:-fig1b fig2a fig2b fig3 fig4a fig4b cycle numbers}
build=${RACCORD_BUILD:-$root/build}
case "$build" in /*) ;; *) build=$root/$build ;; esac
case "$out" in *\'*) echo "paper-figures: a folder with a quote (') is not supported" >&2; exit 2 ;; esac

# Decks each figure needs (slow_* are made here from the deck after 'slow_').
decks=""
for f in $figs; do
  case "$f" in
    fig1b) d="fig1b_nts_slave_block fig1b_nts_slave_disc" ;;
    fig2a) d="fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc" ;;
    fig2b) d="fig2a_mortar_p1_slave_block fig2b_mortar_p0_slave_block fig2a_mortar_p1_slave_disc fig2b_mortar_p0_slave_disc" ;;
    fig3) d="fig3_mortar_p0_mu010 fig3_mortar_p1_mu010 fig3_mortar_p0_mu020 fig3_mortar_p1_mu020 fig3_mortar_p0_mu050 fig3_mortar_p1_mu050" ;;
    fig4a) d="fig4a_q4_mortar_p1 fig4a_q8_mortar_p1" ;;
    fig4b) d="fig4b_q8_mortar_p0_mu020 fig4b_q8_mortar_p1_mu020" ;;
    cycle) d="fig1b_nts_slave_block fig1b_nts_slave_disc fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc fig2b_mortar_p0_slave_block cycle_mortar_p1_mu020" ;;
    numbers) d="fig1b_nts_slave_block fig1b_nts_slave_disc fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc
      fig2b_mortar_p0_slave_block fig2b_mortar_p0_slave_disc fig3_mortar_p0_mu010 fig3_mortar_p1_mu010
      fig3_mortar_p0_mu020 fig3_mortar_p1_mu020 fig3_mortar_p0_mu050 fig3_mortar_p1_mu050
      fig4a_q4_mortar_p1 fig4a_q8_mortar_p1 fig4b_q8_mortar_p0_mu020 fig4b_q8_mortar_p1_mu020
      slow_fig2a_mortar_p1_slave_block slow_fig3_mortar_p1_mu020" ;;
    finite) d="fig1b_nts_slave_block fig1b_nts_slave_disc fig2a_mortar_p1_slave_block fig2a_mortar_p1_slave_disc
      finite_nts_slave_block finite_nts_slave_disc finite_mortar_p1_slave_block finite_mortar_p1_slave_disc" ;;
    plastic) d="fig2a_mortar_p1_slave_block plastic_mortar_p1_slave_block plastic_nts_slave_block" ;;
    *) echo "paper-figures: unknown figure '$f' (fig1b fig2a fig2b fig3 fig4a fig4b cycle numbers finite plastic)" >&2; exit 2 ;;
  esac
  decks="$decks $d"
done
decks=$(printf '%s\n' $decks | awk '!seen[$0]++')

command -v gnuplot > /dev/null 2>&1 || { echo "paper-figures: gnuplot is not installed (sh tools/install-packages.sh)" >&2; exit 1; }
mkdir -p "$out/runs" "$out/figures" "$out/decks"
out=$(cd "$out" && pwd)

# 1. Build (Release) when the executable is missing or a source is newer.
exe=$build/raccord
if [ ! -x "$exe" ] || [ -n "$(find "$root/src" "$root/CMakeLists.txt" -newer "$exe" -print 2>/dev/null | head -n 1)" ]; then
  echo "paper-figures: building raccord (Release) in $build"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$build" --target raccord -j "$(nproc 2>/dev/null || echo 2)" > /dev/null
fi

# 2. Runs: a deck is done when its history and contact profile have their
#    final names (raccord renames them only when the run completes) and are
#    newer than the deck.
todo=""
for name in $decks; do
  case "$name" in
    slow_*) deck=$out/decks/$name.nml
            sh "$root/postproc/paper/slow-deck.sh" "$root/input/paper/${name#slow_}.nml" "$deck.new"
            if cmp -s "$deck.new" "$deck"; then rm -f "$deck.new"; else mv "$deck.new" "$deck"; fi ;;
    *) deck=$root/input/paper/$name.nml ;;
  esac
  r=$out/runs/$name/$name
  if [ -f "$r.history.txt" ] && [ -f "$r.contact1.txt" ] && [ ! "$deck" -nt "$r.history.txt" ]; then
    continue
  fi
  todo="$todo $deck"
done
status=0
if [ -n "$todo" ]; then
  echo "paper-figures: $(echo $todo | wc -w) run(s) to do, two at a time (about 15 s each on the fine mesh, 30 s the slow ones)"
  printf '%s\n' $todo | xargs -P 2 -n 1 sh "$root/postproc/paper/run-deck.sh" "$exe" "$out/runs" || status=1
else
  echo "paper-figures: every run needed is already complete in $out/runs"
fi

# 3. CalculiX for Fig. 1(b), when ccx is installed (skips with a message otherwise).
case " $figs " in
  *" fig1b "*)
    if [ ! -f "$out/calculix/ccx_pressure.txt" ] || [ "$root/tools/calculix/fig1b-ccx.sh" -nt "$out/calculix/ccx_pressure.txt" ]; then
      sh "$root/tools/calculix/fig1b-ccx.sh" "$out/calculix" || echo "paper-figures: the CalculiX comparison failed; Fig. 1(b) is drawn without it" >&2
    fi ;;
esac
# ... and with NLGEOM for the finite-strain figure, beside the small-strain one.
case " $figs " in
  *" finite "*)
    if [ ! -f "$out/calculix/ccx_pressure.txt" ] || [ "$root/tools/calculix/fig1b-ccx.sh" -nt "$out/calculix/ccx_pressure.txt" ]; then
      sh "$root/tools/calculix/fig1b-ccx.sh" "$out/calculix" || echo "paper-figures: the small-strain CalculiX run failed; the finite figure is drawn without it" >&2
    fi
    if [ ! -f "$out/calculix-finite/ccx_pressure.txt" ] || [ "$root/tools/calculix/finite-ccx.sh" -nt "$out/calculix-finite/ccx_pressure.txt" ]; then
      sh "$root/tools/calculix/finite-ccx.sh" "$out/calculix-finite" || echo "paper-figures: the finite-strain CalculiX run failed; the finite figure is drawn without it" >&2
    fi ;;
esac

# ... and with a *PLASTIC block, loaded and unloaded, for the plastic figure.
case " $figs " in
  *" plastic "*)
    if [ ! -f "$out/calculix-plastic/ccx_residual.txt" ] || [ "$root/tools/calculix/plastic-ccx.sh" -nt "$out/calculix-plastic/ccx_residual.txt" ]; then
      sh "$root/tools/calculix/plastic-ccx.sh" "$out/calculix-plastic" || echo "paper-figures: the plastic CalculiX run failed; the plastic figure is drawn without it" >&2
    fi ;;
esac

# 4. Figures, each in PNG and PDF.
for f in $figs; do
  [ "$f" = numbers ] && continue
  for fmt in png pdf; do
    if ! gnuplot -e "res='$out/runs'; figdir='$out/figures'; ccx='$out/calculix/ccx_pressure.txt'; ccxf='$out/calculix-finite/ccx_pressure.txt'; ccxpl='$out/calculix-plastic'; format='$fmt'" \
        -e "cd '$root/postproc/paper'" "$root/postproc/paper/$f.gp"; then
      echo "paper-figures: $f.$fmt failed" >&2
      status=1
    fi
  done
  [ -f "$out/figures/$f.png" ] && echo "paper-figures: wrote $out/figures/$f.png and .pdf"
done

# 5. The numbers behind doc/reproduction.md.
case " $figs " in
  *" numbers "*)
    if sh "$root/postproc/paper/numbers.sh" "$out/runs" "$out/calculix/ccx_pressure.txt" > "$out/numbers.txt.tmp"; then
      mv "$out/numbers.txt.tmp" "$out/numbers.txt"
      echo "paper-figures: wrote $out/numbers.txt"
    else
      echo "paper-figures: numbers.sh failed" >&2
      status=1
    fi ;;
esac
case " $figs " in
  *" finite "*)
    if sh "$root/postproc/paper/finite-numbers.sh" "$out/runs" "$out/calculix-finite/ccx_pressure.txt" \
        "$out/calculix/ccx_pressure.txt" > "$out/finite-numbers.txt.tmp"; then
      mv "$out/finite-numbers.txt.tmp" "$out/finite-numbers.txt"
      echo "paper-figures: wrote $out/finite-numbers.txt"
    else
      echo "paper-figures: finite-numbers.sh failed" >&2
      status=1
    fi ;;
esac
exit $status
