# Functions shared by postproc/paper/numbers.sh and finite-numbers.sh, sourced
# by them (not run alone). The caller sets runs (the run folder) and frame.
# Differences between two profiles on different nodes: the second is
# interpolated linearly in the deformed x at the nodes of the first, both
# ways, and the largest |difference| is divided by the larger peak. 'inner'
# restricts the nodes to |x| < 0.8 of the contact half-width (away from the
# contact edges, where one node spacing of edge position is a difference of
# order the peak by itself). POSIX sh + awk + sort only.

prof() { echo "$runs/$1/$1.contact1.txt"; }
hist() { echo "$runs/$1/$1.history.txt"; }

# block NAME: the lines of frame $frame, sorted by deformed x
block() {
  f=$(prof "$1")
  [ -f "$f" ] || { echo "numbers: missing $f" >&2; exit 1; }
  awk -v fr="$frame" '/^# frame/ { f = $3; next } /^#/ { next } f == fr && NF >= 10' "$f" | sort -g -k2,2
}
# time of frame $frame
frame_time() { awk -v fr="$frame" '/^# frame/ && $3 == fr { print $5; exit }' "$(prof "$1")"; }

# stats NAME COL [MU]: peak, contact width and force of column COL; Coulomb with MU > 0
stats() {
  block "$1" | awk -v c="$2" -v mu="${3:-0}" -v name="$1" '
    { n++; x[n] = $2; v[n] = $c; st[n] = $7; tn[n] = $9; tt[n] = $10; ps[n] = $5; sh[n] = $6 }
    END {
      pk = 0; xl = 1e30; xr = -1e30; na = 0; F = 0
      for (i = 1; i <= n; i++) {
        if (v[i] > pk) { pk = v[i]; xp = x[i] }
        if (st[i] > 0) { na++; if (x[i] < xl) xl = x[i]; if (x[i] > xr) xr = x[i] }
        if (i > 1) F += 0.5 * (v[i] + v[i-1]) * (x[i] - x[i-1])
      }
      printf "%-34s peak %8.1f MPa at x = %+.4f  active %3d nodes, x in [%+.4f, %+.4f], width %.4f mm  integral %7.1f N/mm\n", \
        name, pk, xp, na, xl, xr, xr - xl, F
      if (mu > 0) {
        # Coulomb, as the solver imposes it: on the nodal forces (shear and
        # pressure are both nodal force / tributary length), and on the
        # multipliers themselves where lambda_n > 5 % of its peak.
        r1 = 0; r2 = 0; pkn = 0
        for (i = 1; i <= n; i++) if (tn[i] > pkn) pkn = tn[i]
        for (i = 1; i <= n; i++) {
          if (st[i] == 0) continue
          if (ps[i] > 0) { q = (sh[i] < 0 ? -sh[i] : sh[i]) / (mu * ps[i]); if (q > r2) r2 = q }
          if (tn[i] > 0.05 * pkn) { q = (tt[i] < 0 ? -tt[i] : tt[i]) / (mu * tn[i]); if (q > r1) { r1 = q; x1 = x[i] } }
        }
        # on the cone (|shear| >= 0.99 mu pressure) = slipping or about to;
        # inside = sticking. Zones by |x|.
        aon = 1e30; non = 0; aonmax = 0
        for (i = 1; i <= n; i++) {
          if (st[i] == 0 || ps[i] <= 0) continue
          a = (x[i] < 0 ? -x[i] : x[i]); q = (sh[i] < 0 ? -sh[i] : sh[i]) / (mu * ps[i])
          if (q >= 0.99) { non++; if (a < aon) aon = a; if (a > aonmax) aonmax = a }
        }
        ncore = 0; nedge = 0; nmid = 0
        for (i = 1; i <= n; i++) {
          if (st[i] == 0 || ps[i] <= 0) continue
          a = (x[i] < 0 ? -x[i] : x[i]); q = (sh[i] < 0 ? -sh[i] : sh[i]) / (mu * ps[i])
          if (q < 0.99) { if (a < aon) ncore++; else if (a > aonmax) nedge++; else nmid++ }
        }
        if (non) printf "%-34s   on the cone (|shear| >= 0.99 mu p, slip) %d nodes, %.4f <= |x| <= %.4f; inside it (stick): %d nodes in the centre |x| < %.4f, %d between, %d at the contact edges\n", "", non, aon, aonmax, ncore, aon, nmid, nedge
        else printf "%-34s   no node on the cone: the whole contact sticks\n", ""
      }
    }'
}

# status_at NAME FRAME: stick and slip nodes (status column) at a frame
status_at() {
  awk -v fr="$2" -v name="$1" '/^# frame/ { f = $3; next } /^#/ { next }
    f == fr && NF >= 10 { a = ($2 < 0 ? -$2 : $2)
      if ($7 == 1) { ns++; if (a > as) as = a }
      if ($7 == 2) { nl++; if (!ml || a < al) { al = a; ml = 1 } if (a > alx) alx = a } }
    END { printf "%-34s frame %2d: stick %3d nodes (|x| <= %.4f), slip %3d nodes (%.4f <= |x| <= %.4f)\n", name, fr, ns, as, nl, al, alx }' "$(prof "$1")"
}

# diff NAME1 COL1 NAME2 COL2 LABEL: max |v1 - v2| / max peak, all nodes and inner nodes
diff2() {
  { block "$1" | awk -v c="$2" '{ print "A", $2, $c, $7 }'; block "$3" | awk -v c="$4" '{ print "B", $2, $c, $7 }'; } |
  awk -v label="$5" '
    $1 == "A" { na++; xa[na] = $2; va[na] = $3; if (($3 < 0 ? -$3 : $3) > pa) pa = ($3 < 0 ? -$3 : $3); if ($4 > 0) { if ($2 < l) l = $2; if ($2 > r) r = $2 } }
    $1 == "B" { nb++; xb[nb] = $2; vb[nb] = $3; if (($3 < 0 ? -$3 : $3) > pb) pb = ($3 < 0 ? -$3 : $3) }
    BEGIN { l = 1e30; r = -1e30 }
    function interp(xx, n, xs, vs,   k) {
      if (xx < xs[1] || xx > xs[n]) return "none"
      for (k = 1; k < n; k++) if (xx <= xs[k+1]) break
      if (xs[k+1] == xs[k]) return vs[k]
      return vs[k] + (vs[k+1] - vs[k]) * (xx - xs[k]) / (xs[k+1] - xs[k])
    }
    END {
      p = (pa > pb ? pa : pb); half = (r - l) / 2; c = (r + l) / 2
      m = 0; mi = 0; s = 0; ns = 0
      for (i = 1; i <= na; i++) { w = interp(xa[i], nb, xb, vb); if (w == "none") continue
        d = va[i] - w; if (d < 0) d = -d; if (d > m) { m = d; xm = xa[i] }
        if ((xa[i] - c < 0 ? c - xa[i] : xa[i] - c) < 0.8 * half) { if (d > mi) mi = d; s += d * d; ns++ } }
      for (i = 1; i <= nb; i++) { w = interp(xb[i], na, xa, va); if (w == "none") continue
        d = vb[i] - w; if (d < 0) d = -d; if (d > m) { m = d; xm = xb[i] }
        if ((xb[i] - c < 0 ? c - xb[i] : xb[i] - c) < 0.8 * half) { if (d > mi) mi = d; s += d * d; ns++ } }
      printf "%-52s peaks |max| %7.1f / %7.1f MPa (%+.2f %%)  max|d|/p_max %.4f (at x = %+.3f)  inner: max %.4f, rms %.4f\n", \
        label, pa, pb, (pa ? 100 * (pb - pa) / pa : 0), m / p, xm, mi / p, (ns ? sqrt(s / ns) / p : 0)
    }'
}

# hist_at NAME: energies and forces at the history row nearest to t = T
hist_at() {
  T=$(frame_time "$1")
  awk -v T="$T" -v name="$1" '
    $1 == "#" && $2 ~ /^[0-9]+$/ { c[$3] = $2; next }
    /^#/ { next }
    { d = $1 - T; if (d < 0) d = -d; if (!seen || d < best) { best = d; seen = 1; for (k = 1; k <= NF; k++) row[k] = $k } }
    END {
      printf "%-34s t = %.4e: KE/IE = %.2e  |contact1_Fy| = %7.1f  contact1_N = %7.1f  -disc_top_Ry = %7.1f  block_bottom_Ry = %7.1f N/mm  (uy = %.5f)\n", \
        name, row[c["time"]], row[c["kinetic"]] / row[c["internal"]], (row[c["contact1_Fy"]] < 0 ? -row[c["contact1_Fy"]] : row[c["contact1_Fy"]]), row[c["contact1_N"]], -row[c["disc_top_Ry"]], \
        row[c["block_bottom_Ry"]], row[c["disc_top_uy"]]
    }' "$(hist "$1")"
}

# max_ke_ie NAME: largest KE/IE over the loading half with IE above 1 % of its peak
ke_ie_max() {
  T=$(frame_time "$1")
  awk -v T="$T" -v name="$1" '
    $1 == "#" && $2 ~ /^[0-9]+$/ { c[$3] = $2; next } /^#/ { next }
    { n++; t[n] = $c["time"]; ke[n] = $c["kinetic"]; ie[n] = $c["internal"]; if (ie[n] > iem) iem = ie[n] }
    END { for (i = 1; i <= n; i++) if (t[i] <= T && ie[i] > 0.01 * iem) { q = ke[i] / ie[i]; if (q > m) { m = q; tm = t[i] } }
          printf "%-34s max KE/IE over t <= T where IE > 1 %% of its peak: %.2e at t = %.3e\n", name, m, tm }' "$(hist "$1")"
}

# force_diff NAME1 NAME2: -disc_top_Ry of the two at their frame-20 rows
force_diff() {
  a=$(hist_at "$1" | sed 's/.*-disc_top_Ry = *\([-0-9.]*\).*/\1/')
  b=$(hist_at "$2" | sed 's/.*-disc_top_Ry = *\([-0-9.]*\).*/\1/')
  awk -v a="$a" -v b="$b" -v l="$1 / $2" 'BEGIN { printf "%-52s -disc_top_Ry at t = T: %.1f / %.1f N/mm (%+.2f %%)\n", l, a, b, 100 * (b - a) / a }'
}
