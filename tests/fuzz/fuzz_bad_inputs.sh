#!/bin/sh
# Bad-input fuzz set of raccord: generate the cases (make_cases.sh) from the
# seeds, run raccord on each with a time limit, check how it fails.
#
#   sh fuzz_bad_inputs.sh RACCORD WORK_DIR [SEED_DIR]
#
# RACCORD   the raccord executable
# WORK_DIR  scratch folder, emptied first; WORK_DIR/cases/<case>/ keeps each
#           case's inputs and what the run printed (stdout.txt, stderr.txt,
#           exit.txt) for a look after a failure
# SEED_DIR  default: the seeds/ folder next to this script
#
# Environment: FUZZ_TIMEOUT (seconds per run, default 20), FUZZ_ONLY (run
# only the cases whose name contains this text), FUZZ_BACKTRACE=1 (run with
# gfortran's backtraces on, see below).
#
# raccord's own error exits print only raccord's message (no ERROR STOP,
# no backtrace). A gfortran backtrace after a run-time error costs about
# 0.35 s per run (it calls addr2line), so the runs have
# GFORTRAN_ERROR_BACKTRACE=0; crashes stay visible without it: a run-time
# check still prints "Fortran runtime error", a signal still ends the
# process with exit >= 128. Each failed case is run once more with the
# backtrace on, into stderr.backtrace.txt.
#
# Every case whose input is bad must end with:
#   - an exit code in the case's expected set (1 bad command line, 2 bad
#     scene or mesh, 3 numerical failure, 4 file system failure; see
#     make_cases.sh for which family expects which);
#   - no crash: no signal (exit >= 128, or the time limit), no "Fortran
#     runtime error", no "Program received signal", no "Segmentation
#     fault", no "Backtrace", no gfortran "ERROR STOP" line (raccord
#     leaves with its exit code after its own message, nothing else);
#   - a line "ERROR [...] <text>" on stderr naming the problem;
#   - no result file that looks complete: no <stem>.h5, .xmf, .history.txt
#     or .contact<k>.txt without ".incomplete" or ".part" in its name.
# A random mutation ("maybe") that exits 0 is a valid input: it is counted
# apart and must then be a clean, complete run (complete files, nothing
# .part / .incomplete, no ERROR line, no crash). A mutation of comments only
# ("valid") must run like that.
#
# Special runs (setup= in case.txt, see make_cases.sh and
# make_cases_hostile.sh): not_writable, disk_full and disk_full_now (a
# tmpfs, root only), locked (flock(1) holds <stem>.lock during the run),
# damage (a run stopped with --wall-clock, one of its files damaged, then
# the case's --restart; an exit 0 must reproduce an uninterrupted run, by
# cmp and h5diff; damage mode none: restarted as it is, mode deck: the deck
# replaced by the case's next.nml first, mode swap: the files of the case's
# next/ put in place first, mode gone: the deck deleted first,
# make_cases_features.sh). env= sets one environment variable for the run; args
# are split as the shell would split them ('' is an empty argument).
#
# Known failures (known_failures.txt next to this script: one case name a
# line, "#" comments naming the bug) are run and reported, but do not count
# among the failures; one that passes is reported so it can be moved back.
#
# Output: one line "FAIL <case folder>: <reason>" per failed case, a count
# per family, and the last line "fuzz: N passed, M failed". Exit 1 when M > 0.
set -u
LC_ALL=C
export LC_ALL

raccord=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
seeds=${3:-$here/seeds}
limit=${FUZZ_TIMEOUT:-20}
if [ "${FUZZ_BACKTRACE:-0}" = 1 ]; then bt=1; else bt=0; fi
only=${FUZZ_ONLY:-}
known_list=$here/known_failures.txt
min_bad=300

case $raccord in /*) ;; *) raccord=$(pwd)/$raccord ;; esac
[ -x "$raccord" ] || { echo "fuzz: $raccord is not an executable" >&2; exit 2; }
command -v timeout > /dev/null 2>&1 || { echo "fuzz: needs timeout (coreutils)" >&2; exit 2; }

# A tmpfs left mounted by a killed earlier run (CTest's timeout) would stop rm -rf.
if [ -d "$work" ] && [ -r /proc/mounts ]; then
  w=$(cd "$work" && pwd)
  awk -v w="$w/" 'index($2, w) == 1 { print $2 }' /proc/mounts | while read -r m; do umount "$m"; done
fi
rm -rf "$work"
mkdir -p "$work" || { echo "fuzz: cannot create $work" >&2; exit 2; }
work=$(cd "$work" && pwd)
cases=$work/cases
start=$(date +%s)
sh "$here/make_cases.sh" "$seeds" "$cases" || { echo "fuzz: make_cases.sh failed" >&2; exit 2; }

# Mounts made by this script, unmounted on exit whatever happens.
mounts=""
cleanup() {
  for m in $mounts; do umount "$m" 2> /dev/null; done
  # leave the scratch folder writable for the next run's rm -rf
  find "$work" -type d ! -perm -u+w -exec chmod u+w {} + 2> /dev/null
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Whether chmod stops this user from writing (it does not for root).
probe=$work/.probe
mkdir -p "$probe/ro" && chmod 555 "$probe/ro"
if (: > "$probe/ro/x") 2> /dev/null; then chmod_protects=0; else chmod_protects=1; fi
chmod 755 "$probe/ro"; rm -rf "$probe"

# case_stem ARGS: the run's name, from the deck (the last argument).
case_stem() { echo "$1" | awk '{ f = $NF; sub(/.*\//, "", f); sub(/\.[^.]*$/, "", f); print f }'; }

# damage_setup DIR: run the case's deck until a wall-clock stop (exit 5),
# then damage one of its files as damage= says. Sets damage_failed on failure.
damage_setup() {
  ddir=$1
  deck=$m_deck; dstem=${deck%.nml}
  # shellcheck disable=SC2086
  set -- $m_damage
  target=$ddir/out/$dstem$1; r=$2; mode=$3
  (cd "$ddir" && timeout -k 5 "$limit" "$raccord" -q --wall-clock 0.001 -o out "$deck" > prerun.txt 2>&1)
  pcode=$?
  if [ "$pcode" -ne 5 ] || [ ! -f "$target" ]; then
    damage_failed="setup: the run to be stopped exited $pcode (expected 5 with $target)"; return 1
  fi
  size=$(wc -c < "$target" | tr -d ' ')
  pos=$(awk -v r="$r" -v n="$size" 'BEGIN { printf "%d", r / 1e6 * n }')
  case $mode in
    flip)
      old=$(od -An -tu1 -j "$pos" -N1 "$target" | tr -d ' \n')
      new=$((old ^ (1 << (r % 8))))
      # shellcheck disable=SC2059
      printf "\\$(printf %03o "$new")" | dd of="$target" bs=1 seek="$pos" conv=notrunc 2> /dev/null ;;
    zero) dd if=/dev/zero of="$target" bs=1 count=16 seek="$pos" conv=notrunc 2> /dev/null ;;
    cut) head -c "$pos" "$target" > "$target.cut" && mv "$target.cut" "$target" ;;
    none) ;;
    deck) cp "$ddir/next.nml" "$ddir/$deck" ;;
    # the files of next/ (a mesh, say) put in place of the case's own
    swap) cp "$ddir"/next/* "$ddir/" ;;
    gone) rm -f "$ddir/$deck" ;;
  esac
  echo "damage: $mode at byte $pos of $size in $target" > "$ddir/setup.txt"
  return 0
}

# damage_same DIR STEM: the restarted results must equal those of an
# uninterrupted run of the same deck (run once per deck, kept in ref/).
damage_same() {
  sdir=$1; sstem=$2; deck=$m_deck
  ref=$work/ref/$(cat "$sdir/$deck" | cksum | tr ' ' _)
  if [ ! -d "$ref" ]; then
    mkdir -p "$ref" && cp "$sdir/$deck" "$sdir"/*.msh "$sdir"/*.inp "$ref/" 2> /dev/null
    (cd "$ref" && "$raccord" -q -o out "$deck" > /dev/null 2>&1)
  fi
  for f in history.txt contact1.txt; do
    [ -f "$ref/out/$sstem.$f" ] || continue
    cmp -s "$sdir/out/$sstem.$f" "$ref/out/$sstem.$f" || reason="$reason exit 0 after damage, but $sstem.$f differs from an uninterrupted run;"
  done
  # /scene holds the deck's path, which differs between the two folders
  if command -v h5diff > /dev/null 2>&1 && \
      ! h5diff -q --exclude-path /scene "$sdir/out/$sstem.h5" "$ref/out/$sstem.h5" > /dev/null 2>&1; then
    reason="$reason exit 0 after damage, but $sstem.h5 differs from an uninterrupted run (h5diff);"
  fi
}

# The known failures, read once: " name name ... ".
known=" "
[ -f "$known_list" ] && known=" $(awk '{ sub(/#.*/, "") } NF { printf "%s ", $1 }' "$known_list")"
is_known() { case $known in *" $1 "*) return 0 ;; *) return 1 ;; esac; }
# load_meta DIR: the fields of DIR/case.txt into m_<field>, with shell
# builtins only (a sed per field and case cost more than the runs).
load_meta() {
  m_family=; m_kind=; m_expect=; m_args=; m_setup=; m_env=; m_names=; m_deck=; m_damage=
  while IFS= read -r line; do
    case $line in
      family=*) m_family=${line#family=} ;;
      kind=*) m_kind=${line#kind=} ;;
      expect=*) m_expect=${line#expect=} ;;
      args=*) m_args=${line#args=} ;;
      setup=*) m_setup=${line#setup=} ;;
      env=*) m_env=${line#env=} ;;
      names=*) m_names=${line#names=} ;;
      deck=*) m_deck=${line#deck=} ;;
      damage=*) m_damage=${line#damage=} ;;
    esac
  done < "$1/case.txt"
}

# check_case DIR: run the case in DIR; set $reason (empty = passed) and $outcome.
check_case() {
  dir=$1
  load_meta "$dir"
  family=$m_family; kind=$m_kind; expect=$m_expect; args=$m_args; setup=$m_setup
  reason=""; outcome=bad
  case $setup in
    not_writable)
      # -o ro/out or -o ro: ro a read-only folder; as root the folder would be
      # writable anyway, so ro becomes a regular file and the output path
      # lies under it (or is it).
      if [ "$chmod_protects" = 1 ]; then mkdir "$dir/ro" && chmod 555 "$dir/ro"
      else : > "$dir/ro"; echo "setup: running as root, ro is a regular file" > "$dir/setup.txt"; fi
      ;;
    disk_full|disk_full_now)
      mkdir -p "$dir/out"
      if [ "$(id -u)" -ne 0 ] || ! mount -t tmpfs -o size=64k tmpfs "$dir/out" 2> /dev/null; then
        outcome=skipped; echo "setup: cannot mount a tmpfs (not root?): skipped" > "$dir/setup.txt"
        return
      fi
      mounts="$mounts $dir/out"
      # full before the run starts
      [ "$setup" = disk_full_now ] && head -c 70000 /dev/zero > "$dir/out/filler" 2> /dev/null
      ;;
    locked)
      # another process holds the stem's lock (flock(1), the same flock(2)
      # raccord takes) for the whole run
      if ! command -v flock > /dev/null 2>&1; then
        outcome=skipped; echo "setup: no flock(1): skipped" > "$dir/setup.txt"; return
      fi
      mkdir -p "$dir/out"
      lockfile=$dir/out/$(case_stem "$args").lock
      flock -o "$lockfile" sleep 30 > /dev/null 2>&1 &
      holder=$!
      n=0
      while flock -n "$lockfile" true 2> /dev/null && [ "$n" -lt 100 ]; do sleep 0.02; n=$((n + 1)); done
      ;;
    damage)
      damage_setup "$dir" || { reason=$damage_failed; return; }
      ;;
  esac
  envv=$m_env
  [ -n "$envv" ] || envv=FUZZ_NO_ENV=1
  eval "set -- $args"
  (cd "$dir" && GFORTRAN_ERROR_BACKTRACE=$bt exec env "$envv" timeout -k 5 "$limit" "$raccord" "$@" > stdout.txt 2> stderr.txt)
  code=$?
  echo "$code" > "$dir/exit.txt"
  if [ "$setup" = locked ]; then kill "$holder" 2> /dev/null; wait "$holder" 2> /dev/null; fi
  if [ "$setup" = disk_full ] || [ "$setup" = disk_full_now ]; then
    ls -la "$dir/out" > "$dir/out.listing.txt" 2>&1
    df -k "$dir/out" >> "$dir/out.listing.txt" 2>&1
    # keep what the run left (for the checks below and a look later), then unmount
    mkdir -p "$dir/out.kept" && cp -p "$dir/out"/* "$dir/out.kept/" 2> /dev/null
    umount "$dir/out" && rmdir "$dir/out" && mv "$dir/out.kept" "$dir/out"
  fi

  err=$dir/stderr.txt
  # Crashes, whatever the exit code.
  if [ "$code" -eq 124 ] || [ "$code" -eq 137 ]; then
    reason="no answer within ${limit} s (killed by timeout, exit $code)"
  elif [ "$code" -ge 128 ]; then
    reason="killed by a signal (exit $code)"
  fi
  crash=$(grep -a -m1 -E 'Fortran runtime error|Program received signal|Segmentation fault|Aborted|Floating point exception|malloc\(\)|double free|HDF5-DIAG|HDF5: infinite loop|libgomp: (Out of memory|Thread creation)' "$err")
  [ -z "$reason" ] && [ -n "$crash" ] && reason="crash on stderr: $crash"
  # raccord leaves with its exit code and nothing after its own message: a
  # backtrace or gfortran's ERROR STOP text is a stop raccord did not make.
  if [ -z "$reason" ] && grep -aq -E 'Backtrace|^ERROR STOP' "$err"; then
    reason="runtime stop text on stderr: $(grep -a -m1 -E 'Backtrace|^ERROR STOP' "$err")"
  fi
  # Complete-looking result files anywhere in the case folder.
  # (a checkpoint, <stem>.checkpoint.h5, is no result)
  complete=$(cd "$dir" && find . -type f \( -name '*.h5' -o -name '*.xmf' -o -name '*.history.txt' -o -name '*.contact*.txt' \) \
    ! -name '*.incomplete*' ! -name '*.part*' ! -name '*.checkpoint.h5' -print | sort | tr '\n' ' ')

  if [ "$code" -eq 0 ] && [ -z "$reason" ]; then
    case $kind in
      bad) reason="exit 0: the bad input was accepted${complete:+ (wrote $complete)}" ;;
      maybe|valid)
        outcome=valid
        stem=$(echo "$args" | awk '{ f = $NF; sub(/.*\//, "", f); sub(/\.[^.]*$/, "", f); print f }')
        odir=$(echo "$args" | awk '{ for (i = 1; i < NF; i++) if ($i == "-o" || $i == "--output") print $(i + 1) }')
        if [ "$setup" = damage ]; then stem=${m_deck%.nml}; odir=out; fi
        for ext in h5 xmf history.txt; do
          [ -s "$dir/$odir/$stem.$ext" ] || reason="$reason exit 0 but $odir/$stem.$ext missing;"
        done
        left=$(cd "$dir" && find . -name '*.part*' -o -name '*.incomplete*' | tr '\n' ' ')
        [ -n "$left" ] && reason="$reason exit 0 but left $left;"
        grep -aq '^ERROR' "$err" && reason="$reason exit 0 with an ERROR line: $(grep -a -m1 '^ERROR' "$err");"
        # a restart from damaged files may only succeed with the results
        # of an uninterrupted run
        [ "$setup" = damage ] && [ -z "$reason" ] && damage_same "$dir" "$stem"
        ;;
    esac
    return
  fi
  [ -n "$reason" ] && return
  if [ "$kind" = valid ]; then
    reason="only a comment changed, yet exit $code: $(grep -a -m1 '^ERROR \[' "$err")"
    return
  fi
  case " $expect " in
    *" $code "*) ;;
    *) reason="exit $code, expected one of: $expect" ;;
  esac
  if ! grep -aq '^ERROR \[[^]]*\] *[^ ]' "$err"; then
    reason="${reason:+$reason; }no 'ERROR [...] message' line on stderr"
  else
    names=$m_names
    # the case folder's own path taken out first: its name (the case's)
    # would otherwise match the names of any message that prints a path
    if [ -n "$names" ] && ! grep -a '^ERROR \[' "$err" | \
        awk -v d="$dir" '{ while ((i = index($0, d)) > 0) $0 = substr($0, 1, i - 1) "<case>" substr($0, i + length(d)); print }' | \
        grep -qiF -- "$names"; then
      reason="${reason:+$reason; }the ERROR line does not name '$names': $(grep -a -m1 '^ERROR \[' "$err")"
    fi
  fi
  if [ -n "$complete" ]; then
    reason="${reason:+$reason; }complete-looking result files after exit $code: $complete"
  fi
}

passed=0; failed=0; nbad=0; nvalid=0; nskip=0; nknown=0; nknown_fixed=0
: > "$work/families.txt"
for dir in "$cases"/*/; do
  dir=${dir%/}
  name=$(basename "$dir")
  if [ -n "$only" ]; then case $name in *"$only"*) ;; *) continue ;; esac; fi
  check_case "$dir"
  echo "$m_family $outcome ${reason:+fail}" >> "$work/families.txt"
  if [ "$outcome" = skipped ]; then
    nskip=$((nskip + 1)); echo "skip $name: $(cat "$dir/setup.txt")"; continue
  fi
  if is_known "$name"; then
    if [ -n "$reason" ]; then nknown=$((nknown + 1)); echo "KNOWN FAILURE $dir: $reason"
    else nknown_fixed=$((nknown_fixed + 1)); echo "KNOWN FAILURE NOW PASSES $dir: move it out of known_failures.txt"; fi
    continue
  fi
  if [ -n "$reason" ] && [ "$bt" = 0 ] && [ "$m_setup" = "" ]; then
    eval "set -- $m_args"
    (cd "$dir" && GFORTRAN_ERROR_BACKTRACE=1 timeout -k 5 "$limit" "$raccord" "$@" > /dev/null 2> stderr.backtrace.txt)
  fi
  if [ -n "$reason" ]; then
    failed=$((failed + 1)); echo "FAIL $dir: $reason"
  else
    passed=$((passed + 1))
    if [ "$outcome" = valid ]; then nvalid=$((nvalid + 1)); else nbad=$((nbad + 1)); fi
  fi
done

awk '{ n[$1]++; if ($2 == "valid") v[$1]++; if ($2 == "skipped") s[$1]++; if ($3 == "fail") f[$1]++ }
  END { for (k in n) printf "  %-9s %4d cases, %3d valid mutants, %2d failed (known failures included), %d skipped\n", k, n[k], v[k], f[k], s[k] }' \
  "$work/families.txt" | sort
elapsed=$(($(date +%s) - start))
echo "fuzz: $nbad bad inputs refused as expected, $nvalid mutants were valid inputs (ran through cleanly), $nskip skipped, $nknown known failures (known_failures.txt), $nknown_fixed known failures now passing; ${elapsed} s"
if [ -z "$only" ] && [ $((nbad + nknown)) -lt "$min_bad" ]; then
  echo "FAIL $cases: only $((nbad + nknown)) genuinely bad cases were checked, fewer than $min_bad"
  failed=$((failed + 1))
fi
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
