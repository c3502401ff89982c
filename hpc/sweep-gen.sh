#!/bin/sh
# Writes the sweep folder of a sweep file: one folder per case holding its deck
# case.nml (the template with every @NAME@ replaced), and checks every deck
# with `raccord --check`. Format and layout: doc/hpc.md.
#
#   sh hpc/sweep-gen.sh [-o OUTDIR] [-r RACCORD] [--no-check] SWEEPFILE
#
# -o OUTDIR    the sweep folder (default results/<sweep file name without extension>)
# -r RACCORD   the raccord executable (default $RACCORD, the installed raccord, raccord on PATH, build/raccord)
# --no-check   write the decks without checking them (no raccord needed)
#
# A deck whose text did not change keeps its file (and its time stamp), so a
# complete case stays complete; a changed deck makes its case run again.
# Writes OUTDIR/cases.txt (number, name, parameters; the Slurm array index is
# the number) and OUTDIR/<case>/check.txt (the output of raccord --check).
# Exit: 0 every deck written and accepted, 1 bad command line, 2 bad sweep file
# or template (nothing written), 10 decks written but some refused by --check.
set -u
hpc_prog=sweep-gen.sh
hpc_dir=$(cd "$(dirname "$0")" && pwd)
. "$hpc_dir/lib.sh"

usage() {
  sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 1
}

outdir=
raccord=
check=1
while [ $# -gt 0 ]; do
  case "$1" in
  -o | --output) [ $# -ge 2 ] || usage; outdir=$2; shift 2 ;;
  -r | --raccord) [ $# -ge 2 ] || usage; raccord=$2; shift 2 ;;
  --no-check) check=0; shift ;;
  -h | --help) usage ;;
  -*) echo "$hpc_prog: unknown option '$1'" >&2; usage ;;
  *) break ;;
  esac
done
[ $# -eq 1 ] || usage
sweep=$1
[ -f "$sweep" ] || { echo "$hpc_prog: no sweep file '$sweep'" >&2; exit 1; }

stem=$(basename "$sweep")
stem=${stem%.*}
[ -n "$outdir" ] || outdir=results/$stem
case "$outdir$sweep" in *"'"* | *"
"*) echo "$hpc_prog: quotes and newlines are not allowed in folder names" >&2; exit 1 ;; esac
if [ "$check" = 1 ]; then
  raccord=$(hpc_find_raccord "$raccord") ||
    { echo "$hpc_prog: no raccord executable (give -r, set RACCORD, or use --no-check)" >&2; exit 1; }
fi

mkdir -p "$outdir" || { echo "$hpc_prog: cannot create $outdir" >&2; exit 1; }
outdir=$(hpc_abspath "$outdir")
sweepdir=$(cd "$(dirname "$sweep")" && pwd)

awk -f "$hpc_dir/sweep.awk" -v sweep="$sweep" -v sweepdir="$sweepdir" -v outdir="$outdir" < /dev/null || {
  code=$?
  # a failed generation leaves no half-written deck behind
  find "$outdir" -name case.nml.new -exec rm -f {} + 2>/dev/null
  exit "$code"
}
cp "$sweep" "$outdir/sweep.txt" 2>/dev/null || true

n=$(hpc_case_count "$outdir")
written=0
same=0
bad=0
i=1
while [ "$i" -le "$n" ]; do
  name=$(hpc_case_line "$outdir" "$i" | cut -f 2)
  dir=$outdir/$name
  if [ -f "$dir/case.nml" ] && cmp -s "$dir/case.nml.new" "$dir/case.nml"; then
    rm -f "$dir/case.nml.new"
    same=$((same + 1))
    what=unchanged
  else
    mv -f "$dir/case.nml.new" "$dir/case.nml" || exit 4
    written=$((written + 1))
    what=written
  fi
  if [ "$check" = 1 ]; then
    "$raccord" --check "$dir/case.nml" > "$dir/check.txt" 2>&1
    code=$?
    if [ "$code" -eq 0 ]; then
      echo "ok    $i $name ($what)"
    else
      bad=$((bad + 1))
      why=$(hpc_first_error "$dir/check.txt")
      echo "BAD   $i $name ($what): raccord --check exit $code: $why"
    fi
  else
    echo "ok    $i $name ($what, not checked)"
  fi
  i=$((i + 1))
done

# Folders of cases no longer in the sweep file are left alone, and named.
for d in "$outdir"/*/; do
  [ -f "$d/case.nml" ] || continue
  name=$(basename "$d")
  awk -F '\t' -v n="$name" '$2 == n { f = 1 } END { exit !f }' "$outdir/cases.txt" ||
    echo "note: $outdir/$name is not a case of this sweep file (left alone)"
done

echo "sweep $outdir: $n cases ($written decks written, $same unchanged)$([ "$check" = 1 ] && echo ", $bad refused by raccord --check")"
[ "$bad" -eq 0 ] || exit 10
exit 0
