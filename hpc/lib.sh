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
# $RACCORD, else `raccord` on PATH, else build/raccord of this repository.
hpc_find_raccord() {
  _r=${1:-${RACCORD:-}}
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

# hpc_case_done CASEDIR: true when CASEDIR/case.h5 exists (complete by the
# .part/.incomplete convention of doc/output-format.md) and is newer than
# CASEDIR/case.nml (a deck rewritten by sweep-gen.sh after the run is run again).
hpc_case_done() {
  [ -f "$1/$RACCORD_CASE_STEM.h5" ] || return 1
  [ -n "$(find "$1/$RACCORD_CASE_STEM.h5" -newer "$1/$RACCORD_CASE_STEM.nml" -print 2>/dev/null)" ]
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
