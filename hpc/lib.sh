# Shell functions shared by the hpc/ scripts (POSIX sh; sourced, not run).
# doc/hpc.md describes the sweep folder these functions work on.

# The stem of every case's deck and results: CASEDIR/case.nml -> CASEDIR/case.h5.
RACCORD_CASE_STEM=case

hpc_die() {
  echo "$hpc_prog: $*" >&2
  exit "${hpc_die_code:-1}"
}

# hpc_abspath PATH: PATH made absolute against the current directory (the
# folder must exist; the last component need not).
hpc_abspath() {
  case "$1" in
  /*) printf '%s\n' "$1" ;;
  *)
    _d=$(dirname -- "$1")
    _b=$(basename -- "$1")
    _d=$(cd -- "$_d" 2>/dev/null && pwd) || return 1
    if [ "$_b" = . ]; then printf '%s\n' "$_d"; else printf '%s\n' "$_d/$_b"; fi
    ;;
  esac
}

# hpc_find_raccord [GIVEN]: the raccord executable to use: GIVEN, else
# $RACCORD, else the program installed with these scripts (PREFIX/bin/raccord
# when they are PREFIX/share/raccord/hpc, cmake --install), else `raccord` on
# PATH, else build/raccord of this repository.
hpc_find_raccord() {
  _r=${1:-${RACCORD:-}}
  if [ -z "$_r" ]; then
    case "$hpc_dir" in
    */share/raccord/hpc) [ -x "$hpc_dir/../../../bin/raccord" ] && _r=$(cd "$hpc_dir/../../../bin" && pwd)/raccord ;;
    esac
  fi
  if [ -z "$_r" ]; then
    if command -v raccord > /dev/null 2>&1; then
      _r=$(command -v raccord)
    elif [ -x "$hpc_dir/../build/raccord" ]; then
      _r=$hpc_dir/../build/raccord
    else
      return 1
    fi
  fi
  case "$_r" in */*) _r=$(hpc_abspath "$_r") || return 1 ;; esac
  [ -x "$_r" ] || command -v "$_r" > /dev/null 2>&1 || return 1
  printf '%s\n' "$_r"
}

# hpc_case_done OUTDIR [DECK]: true when OUTDIR/<stem>.h5 exists (complete by
# the .part/.incomplete convention of doc/output-format.md) and is newer than
# DECK (default OUTDIR/case.nml; <stem> is DECK's name without extension), so
# that a deck rewritten by sweep-gen.sh after its run makes the case run again.
hpc_case_done() {
  _deck=${2:-$1/$RACCORD_CASE_STEM.nml}
  _stem=$(basename "$_deck")
  _stem=${_stem%.*}
  [ -f "$1/$_stem.h5" ] || return 1
  [ -n "$(find "$1/$_stem.h5" -newer "$_deck" -print 2>/dev/null)" ]
}

# hpc_now: seconds since the epoch.
hpc_now() {
  date +%s 2>/dev/null || awk 'BEGIN { srand(); print srand() }'
}

# hpc_slurm_seconds TIME: a Slurm time ("MM", "MM:SS", "HH:MM:SS",
# "D-HH", "D-HH:MM", "D-HH:MM:SS") in seconds; empty for UNLIMITED or junk.
hpc_slurm_seconds() {
  printf '%s\n' "$1" | awk '
    /^[0-9]+$/                          { print $1 * 60; exit }
    /^[0-9]+:[0-9]+$/                   { split($1, a, ":"); print a[1] * 60 + a[2]; exit }
    /^[0-9]+:[0-9]+:[0-9]+$/            { split($1, a, ":"); print a[1] * 3600 + a[2] * 60 + a[3]; exit }
    /^[0-9]+-[0-9]+(:[0-9]+(:[0-9]+)?)?$/ {
      split($1, d, "-"); n = split(d[2], a, ":")
      print d[1] * 86400 + a[1] * 3600 + (n > 1 ? a[2] * 60 : 0) + (n > 2 ? a[3] : 0); exit }'
}

# hpc_wallclock_seconds: the seconds raccord may run before it must stop and
# write its checkpoint, i.e. the time left to this job minus
# RACCORD_WALLCLOCK_MARGIN (default 300 s). Sources, first found wins:
# RACCORD_WALLCLOCK_SECONDS already set; SLURM_JOB_END_TIME (epoch seconds,
# set by Slurm in the job's environment); RACCORD_TIME_LIMIT (the --time
# value, counted from SLURM_JOB_START_TIME or from now); `squeue -o %L`
# (time left). Prints nothing when no limit is known.
hpc_wallclock_seconds() {
  if [ -n "${RACCORD_WALLCLOCK_SECONDS:-}" ]; then
    printf '%s\n' "$RACCORD_WALLCLOCK_SECONDS"
    return
  fi
  _margin=${RACCORD_WALLCLOCK_MARGIN:-300}
  _now=$(hpc_now)
  _left=
  if [ -n "${SLURM_JOB_END_TIME:-}" ]; then
    _left=$((SLURM_JOB_END_TIME - _now))
  elif [ -n "${RACCORD_TIME_LIMIT:-}" ]; then
    _lim=$(hpc_slurm_seconds "$RACCORD_TIME_LIMIT")
    if [ -n "$_lim" ]; then _left=$((${SLURM_JOB_START_TIME:-$_now} + _lim - _now)); fi
  elif [ -n "${SLURM_JOB_ID:-}" ] && command -v squeue > /dev/null 2>&1; then
    _left=$(hpc_slurm_seconds "$(squeue -h -j "$SLURM_JOB_ID" -o %L 2>/dev/null | head -n 1)")
  fi
  [ -n "$_left" ] || return 0
  _s=$((_left - _margin))
  [ "$_s" -ge 60 ] || _s=60
  printf '%s\n' "$_s"
}

# hpc_raccord_has_checkpoint RACCORD: true when this raccord stops at a
# wall-clock limit with a checkpoint (it lists --wall-clock in --help), or when
# RACCORD_CHECKPOINT=yes; false with RACCORD_CHECKPOINT=no.
hpc_raccord_has_checkpoint() {
  case "${RACCORD_CHECKPOINT:-auto}" in
  yes) return 0 ;;
  no) return 1 ;;
  esac
  "$1" --help 2>/dev/null | grep -q -- '--wall-clock'
}

# hpc_case_line SWEEPDIR N: line N of SWEEPDIR/cases.txt (number, name, values),
# tab-separated; empty when there is no case N.
hpc_case_line() {
  awk -F '\t' -v n="$2" '$1 == n { print; exit }' "$1/cases.txt"
}

# hpc_case_count SWEEPDIR: number of cases in SWEEPDIR/cases.txt.
hpc_case_count() {
  awk -F '\t' '$1 ~ /^[0-9]+$/ { n++ } END { print n + 0 }' "$1/cases.txt"
}

# hpc_job_case CASEDIR [DECK]: what a batch job does with one case (the Slurm
# templates call it; doc/hpc.md, "Exit codes"): run-case.sh, then by its exit
#   0   done (or already complete)                 -> 0
#   1   bad command line (a script problem)        -> 1, not requeued
#   2   deck or mesh refused                       -> 2, not requeued: fix the input
#   3   numerical failure                          -> 3, not requeued; reported with the log's last errors
#   4   file system failure                        -> run once more after
#       RACCORD_RETRY_DELAY seconds (default 60); a second 4 -> 4
#   5   wall-clock limit, checkpoint written       -> `scontrol requeue $SLURM_JOB_ID`
#       (at most RACCORD_MAX_REQUEUE times, default 20, counted by
#       SLURM_RESTART_COUNT); without Slurm, prints how to resubmit -> 5
#   >128 killed by a signal (time limit without checkpoint, scancel) -> as is
# It runs run-case.sh in the background so that this shell can pass on the
# USR1 of `#SBATCH --signal=B:USR1@...` (and TERM) while it waits.
hpc_job_case() {
  _dir=$1
  _deckopt=
  [ $# -lt 2 ] || _deckopt=$2
  _try=1
  while :; do
    if [ -n "$_deckopt" ]; then
      sh "$hpc_dir/run-case.sh" -d "$_deckopt" "$_dir" &
    else
      sh "$hpc_dir/run-case.sh" "$_dir" &
    fi
    _child=$!
    trap 'hpc_got_signal=1; kill -USR1 "$_child" 2>/dev/null' USR1
    trap 'hpc_got_signal=1; kill -TERM "$_child" 2>/dev/null' TERM
    # A trapped signal interrupts wait (status > 128) whether or not the
    # child has ended yet; waiting again returns the child's own status
    # (127 only if it was already collected: then keep what was seen).
    _code=
    while :; do
      hpc_got_signal=0
      wait "$_child"
      _rc=$?
      if [ "$_rc" -eq 127 ] && [ -n "$_code" ]; then break; fi
      _code=$_rc
      if [ "$hpc_got_signal" = 1 ] && [ "$_code" -gt 128 ]; then continue; fi
      break
    done
    trap - USR1 TERM
    if [ "$_code" -eq 4 ] && [ "$_try" -eq 1 ]; then
      echo "job: file system failure (exit 4): trying once more in ${RACCORD_RETRY_DELAY:-60} s"
      sleep "${RACCORD_RETRY_DELAY:-60}"
      _try=2
      continue
    fi
    break
  done
  case "$_code" in
  0) echo "job: case complete: $_dir" ;;
  1) echo "job: bad command line (exit 1): a problem of the job script; not requeued" ;;
  2) echo "job: the deck or mesh was refused (exit 2): fix the input and submit again; not requeued" ;;
  3)
    echo "job: numerical failure (exit 3): not requeued; files *.incomplete.* in $_dir; last errors:"
    grep -h 'ERROR\|incomplete' "$_dir"/*.log "$_dir/run.out" 2>/dev/null | tail -n 5 | sed 's/^/  /'
    ;;
  4) echo "job: file system failure (exit 4) twice: not requeued; check quota and the folder $_dir" ;;
  5)
    _n=${SLURM_RESTART_COUNT:-0}
    if [ -n "${SLURM_JOB_ID:-}" ] && command -v scontrol > /dev/null 2>&1; then
      if [ "$_n" -ge "${RACCORD_MAX_REQUEUE:-20}" ]; then
        echo "job: checkpoint written (exit 5) but requeued $_n times already (RACCORD_MAX_REQUEUE): not requeued; resubmit by hand"
      elif scontrol requeue "$SLURM_JOB_ID"; then
        echo "job: checkpoint written (exit 5): job $SLURM_JOB_ID requeued (restart $((_n + 1)))"
      else
        echo "job: checkpoint written (exit 5) but scontrol requeue $SLURM_JOB_ID failed: resubmit by hand"
      fi
    else
      echo "job: checkpoint written (exit 5): not under Slurm; run the same command again to go on"
    fi
    ;;
  *)
    if [ "$_code" -gt 128 ]; then
      echo "job: raccord was stopped by signal $((_code - 128)) (time limit without checkpoint, or scancel): not requeued; a new submission starts the case again"
    else
      echo "job: unexpected exit $_code: not requeued"
    fi
    ;;
  esac
  return "$_code"
}


# hpc_first_error FILE: raccord's first error message in FILE (the line
# "ERROR [caller] ..."; else the first line with ERROR), cut to 300 characters.
hpc_first_error() {
  awk '/^ERROR \[/ { print substr($0, 1, 300); found = 1; exit }
       /ERROR/ && first == "" { first = substr($0, 1, 300) }
       END { if (!found && first != "") print first }' "$1" 2>/dev/null
}

# raccord's error exits print only its message; a run-time error (a bug)
# would add gfortran's backtrace, kept short in the case files.
: "${GFORTRAN_ERROR_BACKTRACE:=0}"
export GFORTRAN_ERROR_BACKTRACE
