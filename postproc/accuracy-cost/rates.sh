#!/bin/sh
# Observed convergence rates of the accuracy-cost study: for each problem,
# element and method, the least-squares slope of log|error| against log h
# over the levels that have a result (the reference run of the paper's scene,
# whose error is zero by definition, is left out). Reads OUTDIR/<problem>.txt.
#
#   sh postproc/accuracy-cost/rates.sh OUTDIR PROBLEM... > rates.txt
#
# Lines: problem elem method error levels rate first_error last_error.
set -eu
out=$1; shift
echo "# problem elem method error levels rate first_error last_error"
for prob in "$@"; do
  [ "$prob" = knobs ] && continue
  awk -v prob="$prob" '
    /^#/ { for (i = 2; i <= NF; i++) col[$i] = i - 1; next }
    {
      key = $2 " " $3
      if (!(key in seen)) { seen[key] = 1; order[++nkey] = key }
      for (name in col) {
        if (name !~ /^err_/) continue
        v = $(col[name]); if (v == "-" || v + 0 == 0) continue
        n = ++cnt[key, name]
        x[key, name, n] = log($(col["h"])); y[key, name, n] = log(v < 0 ? -v : v)
        if (n == 1) first[key, name] = v
        last[key, name] = v
      }
    }
    END {
      for (q = 1; q <= nkey; q++) for (name in col) {
        if (name !~ /^err_/) continue
        key = order[q]; n = cnt[key, name]
        if (n < 2) continue
        sx = sy = sxx = sxy = 0
        for (i = 1; i <= n; i++) { sx += x[key, name, i]; sy += y[key, name, i]; sxx += x[key, name, i]^2; sxy += x[key, name, i] * y[key, name, i] }
        rate = (n * sxy - sx * sy) / (n * sxx - sx * sx)
        printf "%s %s %s %d %.3f %s %s\n", prob, key, name, n, rate, first[key, name], last[key, name]
      }
    }' "$out/$prob.txt" | sort -k2,2 -k3,3 -k4,4
done
