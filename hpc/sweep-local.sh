#!/bin/sh
# Runs every case of a sweep on this machine, N cases at a time, each its own
# raccord process writing into its own case folder (doc/hpc.md).
#
#   sh hpc/sweep-local.sh [-j N] [-o OUTDIR] [-r RACCORD] SWEEPFILE
#   sh hpc/sweep-local.sh [-j N] [-r RACCORD] SWEEPDIR
#
# SWEEPFILE    a sweep file: sweep-gen.sh writes (or updates) its sweep folder
#              first, OUTDIR (default results/<sweep file name without extension>)
# SWEEPDIR     a sweep folder written by sweep-gen.sh (it holds cases.txt)
# -j N         cases run at once (default: the number of processors)
# -r RACCORD   the raccord executable (default $RACCORD, the installed raccord, raccord on PATH, build/raccord)
#
# A case is done when CASEDIR/case.h5 exists (complete: never .part or
# .incomplete) and is newer than its deck; done cases are skipped, failed and
# incomplete ones run again. Interrupting the sweep (Ctrl-C, TERM) stops the
# running cases; what was complete stays complete. OMP_NUM_THREADS is 1 for
# each case unless you set it.
# The summary (also in SWEEPDIR/summary.txt) lists done, skipped and failed
# cases with exit code and folder.
# Exit: 0 every case done or skipped, 1 bad command line, 2 bad sweep file or
# template, 10 some cases failed, 130/143 interrupted.
set -u
hpc_prog=sweep-local.sh
hpc_dir=$(cd "$(dirname "$0")" && pwd)
. "$hpc_dir/lib.sh"

usage() {
  sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 1
}

jobs=
outdir=
raccord=
while [ $# -gt 0 ]; do
  case "$1" in
  -j) [ $# -ge 2 ] || usage; jobs=$2; shift 2 ;;
  -j[0-9]*) jobs=${1#-j}; shift ;;
  -o | --output) [ $# -ge 2 ] || usage; outdir=$2; shift 2 ;;
  -r | --raccord) [ $# -ge 2 ] || usage; raccord=$2; shift 2 ;;
  -h | --help) usage ;;
  -*) echo "$hpc_prog: unknown option '$1'" >&2; usage ;;
  *) break ;;
  esac
done
[ $# -eq 1 ] || usage
case "$jobs" in
'') jobs=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2) ;;
*[!0-9]* | 0) echo "$hpc_prog: -j wants a positive number, not '$jobs'" >&2; exit 1 ;;
esac
raccord=$(hpc_find_raccord "$raccord") || { echo "$hpc_prog: no raccord executable (give -r or set RACCORD)" >&2; exit 1; }

if [ -f "$1" ]; then
  if [ -n "$outdir" ]; then set -- -o "$outdir" "$1"; else set -- "$1"; fi
  sh "$hpc_dir/sweep-gen.sh" -r "$raccord" "$@"
  code=$?
  case "$code" in 0 | 10) ;; *) exit "$code" ;; esac
  [ -n "$outdir" ] || { outdir=$(basename "$1"); outdir=results/${outdir%.*}; }
elif [ -d "$1" ]; then
  [ -z "$outdir" ] || { echo "$hpc_prog: -o goes with a sweep file, not with a sweep folder" >&2; exit 1; }
  outdir=$1
else
  echo "$hpc_prog: '$1' is neither a sweep file nor a sweep folder" >&2
  exit 1
fi
[ -f "$outdir/cases.txt" ] || { echo "$hpc_prog: $outdir has no cases.txt (write it with sweep-gen.sh)" >&2; exit 1; }
outdir=$(hpc_abspath "$outdir")
n=$(hpc_case_count "$outdir")
[ "$jobs" -le "$n" ] || jobs=$n
: "${OMP_NUM_THREADS:=1}"
export OMP_NUM_THREADS

# Workers take the next unclaimed case (mkdir is atomic) until none is left.
claims=$outdir/.sweep-local.$$
mkdir "$claims" || exit 4

worker() {
  child=
  trap 'trap "" TERM; [ -z "$child" ] || { kill -TERM "$child" 2>/dev/null; wait "$child"; }; exit 143' TERM
  i=1
  while [ "$i" -le "$n" ]; do
    if mkdir "$claims/$i" 2>/dev/null; then
      name=$(hpc_case_line "$outdir" "$i" | cut -f 2)
      dir=$outdir/$name
      if hpc_case_done "$dir"; then
        echo "skipped 0 $name" > "$claims/$i/outcome"
        echo "[$i/$n] case $name: skipped (complete)"
      else
        sh "$hpc_dir/run-case.sh" -r "$raccord" "$dir" > "$claims/$i/line" 2>&1 &
        child=$!
        wait "$child"
        code=$?
        child=
        if [ "$code" -eq 0 ]; then echo "done 0 $name" > "$claims/$i/outcome"
        else echo "failed $code $name" > "$claims/$i/outcome"; fi
        echo "[$i/$n] $(cat "$claims/$i/line")"
      fi
    fi
    i=$((i + 1))
  done
}

summary() { # interrupted?
  ndone=0 nskip=0 nfail=0 nstop=0 nnot=0
  {
    i=1
    while [ "$i" -le "$n" ]; do
      name=$(hpc_case_line "$outdir" "$i" | cut -f 2)
      if [ -f "$claims/$i/outcome" ]; then
        read -r what code rest < "$claims/$i/outcome"
      elif [ -d "$claims/$i" ]; then
        what=stopped code=-
      else
        what=not-run code=-
      fi
      case "$what" in
      done) ndone=$((ndone + 1)); printf '  %-8s %3d  %-28s %s\n' done "$i" "$name" "$outdir/$name" ;;
      skipped) nskip=$((nskip + 1)); printf '  %-8s %3d  %-28s %s\n' skipped "$i" "$name" "$outdir/$name" ;;
      failed)
        nfail=$((nfail + 1))
        stage=run
        grep -q 'failed at check' "$claims/$i/line" 2>/dev/null && stage=check
        printf '  %-8s %3d  %-28s %s  exit %s (%s)\n' failed "$i" "$name" "$outdir/$name" "$code" "$stage" ;;
      stopped) nstop=$((nstop + 1)); printf '  %-8s %3d  %-28s %s\n' stopped "$i" "$name" "$outdir/$name" ;;
      *) nnot=$((nnot + 1)); printf '  %-8s %3d  %-28s %s\n' not-run "$i" "$name" "$outdir/$name" ;;
      esac
      i=$((i + 1))
    done
    echo "sweep $outdir: $n cases: $ndone done, $nskip skipped, $nfail failed$([ "$nstop" -eq 0 ] || echo ", $nstop stopped")$([ "$nnot" -eq 0 ] || echo ", $nnot not run")$1"
  } > "$claims/summary"
  cp "$claims/summary" "$outdir/summary.txt"
  echo "summary:"
  cat "$claims/summary"
}

pids=
interrupt() { # exit code
  trap '' INT TERM HUP
  echo "$hpc_prog: interrupted: stopping the running cases" >&2
  for p in $pids; do kill -TERM "$p" 2>/dev/null; done
  for p in $pids; do wait "$p" 2>/dev/null; done
  summary " (interrupted)"
  rm -rf "$claims"
  exit "$1"
}
trap 'interrupt 130' INT
trap 'interrupt 143' TERM
trap 'interrupt 129' HUP

echo "sweep $outdir: $n cases, $jobs at a time, raccord $raccord"
k=1
while [ "$k" -le "$jobs" ]; do
  worker &
  pids="$pids $!"
  k=$((k + 1))
done
for p in $pids; do wait "$p"; done
summary ""
rm -rf "$claims"
[ "$nfail" -eq 0 ] || exit 10
exit 0
