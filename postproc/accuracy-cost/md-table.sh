#!/bin/sh
# A Markdown table of chosen columns of an accuracy-cost table
# (OUTDIR/<problem>.txt), errors in %, for doc/accuracy-cost.md:
#   sh postproc/accuracy-cost/md-table.sh TABLE COLUMN...
# A column named err_* (or ke_ie_*, change_ref) is printed as a signed
# percentage with 3 significant digits; patch errors (err_max, err_l2 below
# 1e-6) in e-notation; others as they are.
table=$1; shift
awk -v cols="$*" '
  /^#/ { for (i = 2; i <= NF; i++) c[$i] = i - 1; n = split(cols, w, " ")
         line = "|"; sep = "|"
         for (k = 1; k <= n; k++) { line = line " " w[k] " |"; sep = sep "---|" }
         print line; print sep; next }
  {
    line = "|"
    for (k = 1; k <= n; k++) {
      v = $(c[w[k]])
      if (v != "-" && (w[k] ~ /^err_/ || w[k] == "change_ref")) {
        a = (v < 0 ? -v : v)
        if (a != 0 && a < 1e-4) v = sprintf("%.1e", v); else v = sprintf("%.3g %%", 100 * v)
      } else if (v != "-" && w[k] ~ /^ke_ie/) v = sprintf("%.1e", v)
      line = line " " v " |"
    }
    print line
  }' "$table"
