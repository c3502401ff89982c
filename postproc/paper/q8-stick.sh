#!/bin/sh
# Diagnostic of the Q8 stick-traction zigzag of Fig. 4(b) (issue #16 item 3;
# doc/reproduction.md "Fig. 4(b)", doc/theory-contact.md section 6). From
# the shipped deck input/paper/fig4b_q8_mortar_p1_mu020.nml it writes four
# variants, runs them and prints the figures the doc quotes:
#   q8        mu = 0.5 (the whole zone sticks at t = T), disc damped as in
#             the Fig. 3 decks (alpha = 1e7 1/s), so no ringing is frozen in
#   q4        the same on paper_q4.msh: Q4 with the same node spacing on
#             the block top (0.02 mm) and the same disc arc spacing
#   q8_dense  q8 stopped at T with 400 frames (one every 5e-8 s)
#   q8_p0     q8 with P0 multipliers
# Measures at t = T over the stick core (pressure >= 0.6 of its peak,
# |shear| <= 0.95 mu pressure; windows of five nodes):
#   zigzag   max |fourth difference of lam_t| / 16 over max |lam_t| (as
#            tests/contact/test_paper_stick.f90); also for the nodal-force
#            traction `shear` (column 6) over max |lam_t|
#   ux_alt   max |fourth difference of u_x| / 16 of the slave nodes, mm
#            (u_x = deformed x - x of frame 0): the alternation in the
#            bodies' state, not in the conversion of forces to tractions
#   incr     for the dense run: the zigzag of lam_t(T) - lam_t(t_k) over
#            the nodes at least three node spacings (0.06 mm) inside the
#            stick front of t_k, over max |lam_t(T)|: what the stick zone
#            adds after the front has passed, against lam_t(t_k) itself.
#
#   sh postproc/paper/q8-stick.sh EXE [WORKDIR] [--check]
#
# The shipped deck has edge_multipliers = 'tangential_corners' (the
# tangential multipliers at the corners of the Q8 edges), so the variants
# have it too; with a multiplier on every trace node (the key removed) the
# Q8 P1 zigzag is 0.211 (doc/reproduction.md, "The Q8 stick zigzag").
# EXE is a (Release) raccord; about 1-2 minutes on one core. With --check
# (CTest `paper_stick_q8`, slow) it exits 1 unless the Q4 twin, what the Q8
# stick zone adds after the front has passed, and the Q8 P1 and P0 stick
# tractions themselves are smooth (zigzag < 0.02 of the peak, the 2 %
# target of issue #16 item 3).
# POSIX sh + awk.
set -eu
exe=$1
work=${2:-${TMPDIR:-/tmp}/raccord-q8-stick}
check=${3:-}
src=$(cd "$(dirname "$0")/../../input/paper" && pwd)
mkdir -p "$work"

# variant NAME MESH MULTIPLIER TEND FRAMES
variant() {
  sed -e "s|file = 'paper_q8.msh'|file = '$src/$2'|" \
      -e "s/multiplier = 'P1', friction = 0.2/multiplier = '$3', friction = 0.5/" \
      -e "s/density = 2.7e-9\$/density = 2.7e-9, damping = 1.0e7/" \
      -e "s/t_end = 4.0e-05/t_end = $4/" -e "s/frames = 40/frames = $5/" \
      "$src/fig4b_q8_mortar_p1_mu020.nml" > "$work/$1.nml"
  grep -q "damping = 1.0e7" "$work/$1.nml" && grep -q "friction = 0.5" "$work/$1.nml" \
    || { echo "q8-stick: could not write the $1 variant (deck changed?)" >&2; exit 1; }
  "$exe" --quiet --output "$work/$1" "$work/$1.nml" > "$work/$1.out" 2>&1 \
    || { echo "q8-stick: $1 failed, see $work/$1.out" >&2; exit 1; }
}
variant q8 paper_q8.msh P1 4.0e-05 40
variant q4 paper_q4.msh P1 4.0e-05 40
variant q8_p0 paper_q8.msh P0 4.0e-05 40
variant q8_dense paper_q8.msh P1 2.0e-05 400

# measures FILE FRAME: zigzag, shear zigzag and ux_alt at frame FRAME
measures() {
  awk -v fr="$2" -v name="$3" '
    /^# frame/ { f = $3; i = 0; next } /^#/ || NF < 10 { next }
    f == 0 { i++; x0[i] = $2; next }
    f == fr { i++; n = i; x[i] = $2; p[i] = $5; sh[i] = $6; lt[i] = $10 }
    function d4(v, i) { return (v[i-2] - 4*v[i-1] + 6*v[i] - 4*v[i+1] + v[i+2]) / 16 }
    function ab(a) { return a < 0 ? -a : a }
    END {
      pm = 0; tm = 0
      for (i = 1; i <= n; i++) { if (p[i] > pm) pm = p[i]; if (ab(lt[i]) > tm) tm = ab(lt[i]); u[i] = x[i] - x0[i] }
      for (i = 1; i <= n; i++) core[i] = (p[i] >= 0.6 * pm && ab(sh[i]) <= 0.95 * 0.5 * p[i])
      z = 0; zs = 0; za = 0
      for (i = 3; i <= n - 2; i++) {
        if (!(core[i-2] && core[i-1] && core[i] && core[i+1] && core[i+2])) continue
        if (ab(d4(lt, i)) > z) { z = ab(d4(lt, i)); xz = x[i] }
        if (ab(d4(sh, i)) > zs) zs = ab(d4(sh, i))
        if (ab(d4(u, i)) > za) za = ab(d4(u, i))
      }
      printf "%-9s max |lam_t| %6.1f MPa  zigzag %.4f (x = %+.3f)  shear zigzag %.4f  ux_alt %.2e mm\n", \
        name, tm, z / tm, xz, zs / tm, za
    }' "$1"
}
sum=$work/summary.txt
{
echo "# Q8 stick traction at t = T, mu = 0.5, disc damped (postproc/paper/q8-stick.sh)"
measures "$work/q8/q8.contact1.txt" 20 q8
measures "$work/q8_p0/q8_p0.contact1.txt" 20 q8_p0
measures "$work/q4/q4.contact1.txt" 20 q4

echo "# what the stick zone adds after the front has passed (dense run, T = frame 400)"
for k in 200 240 280 320; do
  awk -v fk="$k" '
    /^# frame/ { f = $3; i = 0; if (f == fk) tk = $5; next } /^#/ || NF < 10 { next }
    f == 0 { i++; x0[i] = $2; next }
    f == fk { i++; a[i] = $10; s[i] = $7; next }
    f == 400 { i++; n = i; b[i] = $10 }
    function ab(v) { return v < 0 ? -v : v }
    function d4(v, i) { return (v[i-2] - 4*v[i-1] + 6*v[i] - 4*v[i+1] + v[i+2]) / 16 }
    END {
      front = 0; tm = 0
      for (i = 1; i <= n; i++) { if (s[i] > 0 && ab(x0[i]) > front) front = ab(x0[i]); if (ab(b[i]) > tm) tm = ab(b[i]); d[i] = b[i] - a[i] }
      zi = 0; za = 0
      for (i = 3; i <= n - 2; i++) {
        ok = 1
        for (j = i - 2; j <= i + 2; j++) if (ab(x0[j]) > front - 0.06) ok = 0
        if (!ok) continue
        if (ab(d4(d, i)) > zi) zi = ab(d4(d, i))
        if (ab(d4(a, i)) > za) za = ab(d4(a, i))
      }
      printf "t_k = %.2e  front |x| = %.3f  incr zigzag %.4f   lam_t(t_k) zigzag %.4f (of max |lam_t(T)|)\n", tk, front, zi / tm, za / tm
    }' "$work/q8_dense/q8_dense.contact1.txt"
done
} > "$sum"
cat "$sum"
[ "$check" = "--check" ] || exit 0
grep -q "edge_multipliers = 'tangential_corners'" "$work/q8.nml" \
  || { echo "FAIL  the Q8 variant lacks edge_multipliers = 'tangential_corners' (deck changed?)"; exit 1; }
awk '
  $1 == "q8" { q8 = $7 } $1 == "q8_p0" { q8p0 = $7 } $1 == "q4" { q4 = $7 }
  $1 == "t_k" { n++; if ($10 + 0 > inc) inc = $10 + 0 }
  END {
    bad = 0
    if (q4 == "" || q4 + 0 >= 0.02) { print "FAIL  Q4 twin zigzag " q4 " (expected < 0.02)"; bad = 1 }
    if (n != 4 || inc >= 0.02) { print "FAIL  increments after the front " inc " (expected < 0.02 at 4 times)"; bad = 1 }
    if (q8 == "" || q8 + 0 >= 0.02) { print "FAIL  Q8 P1 zigzag " q8 " (expected < 0.02)"; bad = 1 }
    if (q8p0 == "" || q8p0 + 0 >= 0.02) { print "FAIL  Q8 P0 zigzag " q8p0 " (expected < 0.02)"; bad = 1 }
    if (!bad) print "pass  Q4 twin " q4 ", increments after the front " inc ", Q8 P1 " q8 ", Q8 P0 " q8p0 ": all < 0.02"
    exit bad
  }' "$sum"
