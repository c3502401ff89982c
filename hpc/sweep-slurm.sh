#!/bin/sh
# Submits a sweep folder (written by sweep-gen.sh) to Slurm as one job array,
# hpc/slurm/raccord-array.sbatch, over the cases not yet complete (doc/hpc.md).
#
#   sh hpc/sweep-slurm.sh [-n] [-m MAX] [-r RACCORD] SWEEPDIR [SBATCH OPTION...]
#
# -n          print the sbatch command instead of running it
# -m MAX      at most MAX tasks at once (--array=...%MAX)
# -r RACCORD  the raccord executable the jobs run (exported as RACCORD)
# SBATCH OPTION...  passed to sbatch before the script, e.g. --time=12:00:00
#                   --mem=8G --partition=long (they override the #SBATCH lines)
#
# The tasks' Slurm output goes to SWEEPDIR/slurm-<job>_<task>.out.
# Exit: 0 submitted (or nothing left to run), 1 bad command line, else sbatch's code.
set -u
hpc_prog=sweep-slurm.sh
hpc_dir=$(cd "$(dirname "$0")" && pwd)
. "$hpc_dir/lib.sh"

usage() {
  sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 1
}

dry=0
max=
raccord=
while [ $# -gt 0 ]; do
  case "$1" in
  -n) dry=1; shift ;;
  -m) [ $# -ge 2 ] || usage; max=$2; shift 2 ;;
  -r) [ $# -ge 2 ] || usage; raccord=$2; shift 2 ;;
  -h | --help) usage ;;
  -*) echo "$hpc_prog: unknown option '$1'" >&2; usage ;;
  *) break ;;
  esac
done
[ $# -ge 1 ] || usage
sweep=$1
shift
[ -f "$sweep/cases.txt" ] || { echo "$hpc_prog: $sweep/cases.txt missing (write it with sweep-gen.sh)" >&2; exit 1; }
sweep=$(hpc_abspath "$sweep")
case "$max" in '' | *[!0-9]*) [ -z "$max" ] || { echo "$hpc_prog: -m wants a number" >&2; exit 1; } ;; esac

# The numbers of the cases not complete, as an --array list: 1-3,5,8-9.
n=$(hpc_case_count "$sweep")
todo=
i=1
while [ "$i" -le "$n" ]; do
  name=$(hpc_case_line "$sweep" "$i" | cut -f 2)
  hpc_case_done "$sweep/$name" || todo="$todo $i"
  i=$((i + 1))
done
if [ -z "$todo" ]; then
  echo "$hpc_prog: all $n cases of $sweep are complete: nothing to submit"
  exit 0
fi
spec=$(echo $todo | awk '{
  s = ""; a = $1; b = $1
  for (i = 2; i <= NF + 1; i++) {
    if (i <= NF && $i == b + 1) { b = $i; continue }
    s = s (s == "" ? "" : ",") (a == b ? a : a "-" b)
    if (i <= NF) { a = $i; b = $i }
  }
  print s }')
[ -z "$max" ] || spec="$spec%$max"
export_list=ALL,RACCORD_HPC=$hpc_dir
if [ -n "$raccord" ]; then export_list=$export_list,RACCORD=$(hpc_abspath "$raccord"); fi

set -- sbatch "--array=$spec" "--job-name=raccord-$(basename "$sweep")" \
  "--output=$sweep/slurm-%A_%a.out" "--export=$export_list" "$@" \
  "$hpc_dir/slurm/raccord-array.sbatch" "$sweep"
echo "$hpc_prog: $(echo $todo | wc -w) of $n cases to run"
if [ "$dry" = 1 ]; then
  echo "$*"
  exit 0
fi
command -v sbatch > /dev/null 2>&1 || { echo "$hpc_prog: no sbatch here (use -n to see the command)" >&2; exit 1; }
"$@"
