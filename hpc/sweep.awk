# Reads a sweep file and its template deck, writes one deck per case.
# Called by sweep-gen.sh (POSIX awk; no gawk extensions):
#
#   awk -f sweep.awk -v sweep=FILE -v sweepdir=DIR -v outdir=DIR
#
# sweep     the sweep file (format: doc/hpc.md, section "The sweep file")
# sweepdir  its folder, absolute: relative template and path values start there
# outdir    the sweep folder, absolute: OUTDIR/<case>/case.nml.new per case
#           and OUTDIR/cases.txt (the index) are written
#
# Errors name the file and line and exit 2; nothing is written then.

function fail(msg) {
  print "sweep-gen: " msg > "/dev/stderr"
  failed = 1
  exit 2
}

function warn(msg) { print "sweep-gen: warning: " msg > "/dev/stderr" }

function shq(s) { gsub(/'/, "'\\''", s); return "'" s "'" }

# Split line s into tok[1..ntok] (blanks separate; '...' or "..." group, a
# quote doubled inside stands for itself; # outside quotes ends the line).
# quoted[i] = 1 when token i was written in quotes.
function tokenize(s, where,    i, c, q, t, intok) {
  ntok = 0; t = ""; intok = 0; q = ""
  for (i = 1; i <= length(s); i++) {
    c = substr(s, i, 1)
    if (q != "") {
      if (c == q) {
        if (substr(s, i + 1, 1) == q) { t = t c; i++ } else q = ""
      } else t = t c
      continue
    }
    if (c == "'" || c == "\"") {
      if (!intok) { intok = 1; quoted[ntok + 1] = 0 }
      q = c; quoted[ntok + 1] = 1
      continue
    }
    if (c == "#") break
    if (c == " " || c == "\t" || c == "\r") {
      if (intok) { tok[++ntok] = t; t = ""; intok = 0 }
      continue
    }
    if (!intok) { intok = 1; quoted[ntok + 1] = 0 }
    t = t c
  }
  if (q != "") fail(where ": unterminated quote")
  if (intok) tok[++ntok] = t
}

# Parse NAME[:TYPE] into pname, ptype.
function namespec(s, where,    k) {
  k = index(s, ":")
  if (k) { pname = substr(s, 1, k - 1); ptype = substr(s, k + 1) }
  else { pname = s; ptype = "auto" }
  if (pname !~ /^[A-Z][A-Z0-9_]*$/)
    fail(where ": parameter name '" pname "' must be upper case letters, digits and _ (starting with a letter), used as @" pname "@ in the template")
  if (ptype !~ /^(auto|text|number|path|raw)$/)
    fail(where ": parameter " pname ": unknown type '" ptype "' (auto, text, number, path or raw)")
  if (pname in builtin)
    fail(where ": @" pname "@ is set by sweep-gen.sh for every case (" builtin_list "); choose another name")
  if (pname in ptypeof)
    fail(where ": parameter " pname " is defined twice (first on line " pline[pname] ")")
  ptypeof[pname] = ptype; pline[pname] = where
  pnames = pnames (pnames == "" ? "" : ", ") pname
}

function is_number(v) { return v ~ /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eEdD][+-]?[0-9]+)?$/ }
function is_logical(v,    l) { l = tolower(v); return l ~ /^\.(true|false|t|f)\.$/ }

# The text a value stands for in the deck.
function format_value(name, v, q, where,    t) {
  t = ptypeof[name]
  if (t == "raw") return v
  if (t == "path") {
    if (v == "") fail(where ": " name ": empty path")
    if (v !~ /^\//) v = sweepdir "/" v
    t = "text"
  }
  if (t == "number") {
    if (q || !is_number(v)) fail(where ": " name " = " v ": not a number (the parameter's type is number)")
    return v
  }
  if (t == "auto" && !q && (is_number(v) || is_logical(v))) return v
  gsub(/'/, "''", v)
  return "'" v "'"
}

function sanitize(v) { gsub(/[^A-Za-z0-9.+-]/, "_", v); return v }

BEGIN {
  builtin["CASE"] = 1; builtin["INDEX"] = 1; builtin["SWEEP_DIR"] = 1; builtin["TEMPLATE_DIR"] = 1
  builtin_list = "CASE, INDEX, SWEEP_DIR, TEMPLATE_DIR"
  if (sweep == "" || sweepdir == "" || outdir == "") fail("sweep.awk needs -v sweep=, sweepdir= and outdir=")
  nrow = 0; ncol = 0; nvary = 0; nset = 0; template = ""; pnames = ""
  ln = 0
  while ((rc = getline line < sweep) > 0) {
    ln++
    where = sweep ":" ln
    tokenize(line, where)
    if (ntok == 0) continue
    kw = tok[1]
    if (kw == "template") {
      if (ntok != 2) fail(where ": template takes one path")
      if (template != "") fail(where ": a second template (one per sweep file)")
      template = tok[2]
    } else if (kw == "set") {
      if (ntok != 3) fail(where ": set NAME[:TYPE] VALUE (quote a value with blanks)")
      namespec(tok[2], where)
      nset++; setname[nset] = pname; setval[nset] = format_value(pname, tok[3], quoted[3], where)
      setraw[nset] = tok[3]
    } else if (kw == "columns") {
      if (ncol) fail(where ": a second columns line")
      if (nrow) fail(where ": columns must come before the case lines")
      if (ntok < 2) fail(where ": columns NAME[:TYPE] ...")
      for (i = 2; i <= ntok; i++) { namespec(tok[i], where); col[++ncol] = pname }
    } else if (kw == "case") {
      if (ntok < 2) fail(where ": case NAME VALUE ...")
      if (ntok - 2 != ncol)
        fail(where ": case " tok[2] " has " ntok - 2 " values for " ncol " columns" (ncol ? " (" colnames() ")" : " (no columns line)"))
      if (tok[2] !~ /^[A-Za-z0-9][A-Za-z0-9._+=-]*$/)
        fail(where ": case name '" tok[2] "': letters, digits and . _ + = - only, starting with a letter or digit (it names the case folder)")
      if (tok[2] in rowat) fail(where ": a second case " tok[2] " (the first is on line " rowat[tok[2]] ")")
      rowat[tok[2]] = ln
      nrow++; rowname[nrow] = tok[2]
      for (i = 1; i <= ncol; i++) rowval[nrow, i] = format_value(col[i], tok[i + 2], quoted[i + 2], where)
    } else if (kw == "vary") {
      if (ntok < 3) fail(where ": vary NAME[:TYPE] VALUE VALUE ...")
      namespec(tok[2], where)
      nvary++; vname[nvary] = pname; vn[nvary] = ntok - 2
      for (i = 3; i <= ntok; i++) {
        vval[nvary, i - 2] = format_value(pname, tok[i], quoted[i], where)
        vtag[nvary, i - 2] = tolower(pname) "-" sanitize(tok[i])
      }
    } else fail(where ": unknown line '" kw "' (template, set, columns, case, vary; # starts a comment)")
  }
  if (rc < 0) fail(sweep ": cannot read")
  close(sweep)
  if (template == "") fail(sweep ": no template line")
  if (ncol && !nrow) fail(sweep ": a columns line but no case lines")
  if (!nrow && !nvary) fail(sweep ": no case (give case lines, vary lines, or both)")

  tpath = template
  if (tpath !~ /^\//) tpath = sweepdir "/" tpath
  tdir = tpath; sub(/\/[^\/]*$/, "", tdir); if (tdir == "") tdir = "/"
  nt = 0
  while ((rc = getline line < tpath) > 0) tl[++nt] = line
  if (rc < 0) fail(sweep ": template " template ": cannot read " tpath)
  close(tpath)

  # Every placeholder of the template must have a value.
  bad = ""
  for (i = 1; i <= nt; i++) {
    s = tl[i]
    while (match(s, /@[A-Z][A-Z0-9_]*@/)) {
      key = substr(s, RSTART + 1, RLENGTH - 2)
      used[key] = 1
      if (!(key in ptypeof) && !(key in builtin))
        bad = bad "\n  " tpath ":" i ": @" key "@"
      s = substr(s, RSTART + RLENGTH)
    }
  }
  for (k in ptypeof) if (!(k in used)) warn(pline[k] ": parameter " k " is not used in the template " template)
  if (bad != "")
    fail("placeholders without a value in the sweep file " sweep ":" bad "\n(parameters defined: " (pnames == "" ? "none" : pnames) "; set by sweep-gen.sh: " builtin_list ")")

  # Cases: every case line (or one unnamed row) times every combination of vary values.
  if (!nrow) { nrow = 1; rowname[1] = ""; norow = 1 }
  ncase = 0
  for (r = 1; r <= nrow; r++) {
    for (v = 1; v <= nvary; v++) pick[v] = 1
    while (1) {
      name = rowname[r]
      for (v = 1; v <= nvary; v++) name = name (name == "" ? "" : "_") vtag[v, pick[v]]
      if (name in casenum) fail(sweep ": two cases are named " name " (cases " casenum[name] " and " ncase + 1 ")")
      ncase++; casenum[name] = ncase; cname[ncase] = name
      nv = 0
      for (i = 1; i <= nset; i++) { nv++; cn[ncase, nv] = setname[i]; cv[ncase, nv] = setval[i] }
      if (!norow) for (i = 1; i <= ncol; i++) { nv++; cn[ncase, nv] = col[i]; cv[ncase, nv] = rowval[r, i] }
      for (v = 1; v <= nvary; v++) { nv++; cn[ncase, nv] = vname[v]; cv[ncase, nv] = vval[v, pick[v]] }
      cnv[ncase] = nv
      # next combination (the last vary line turns fastest)
      v = nvary
      while (v >= 1) { if (pick[v] < vn[v]) { pick[v]++; break }; pick[v] = 1; v-- }
      if (v < 1) break
    }
  }

  index_file = outdir "/cases.txt"
  print "# case\tname\tparameters (as written in the deck); sweep " sweep ", template " template > index_file
  for (c = 1; c <= ncase; c++) {
    split("", val)
    val["CASE"] = cname[c]; val["INDEX"] = c; val["SWEEP_DIR"] = sweepdir; val["TEMPLATE_DIR"] = tdir
    plist = ""
    for (i = 1; i <= cnv[c]; i++) {
      val[cn[c, i]] = cv[c, i]
      plist = plist (i > 1 ? "  " : "") cn[c, i] " = " cv[c, i]
    }
    dir = outdir "/" cname[c]
    if (system("mkdir -p " shq(dir)) != 0) fail("cannot create " dir)
    deck = dir "/case.nml.new"
    # (no sweep file name, case count or date here: a deck changes only with its values)
    print "! Sweep case " cname[c] ", template " template ": " plist > deck
    print "! Written by hpc/sweep-gen.sh; edit the sweep file or the template, not this deck." > deck
    for (i = 1; i <= nt; i++) {
      s = tl[i]; out = ""
      while (match(s, /@[A-Z][A-Z0-9_]*@/)) {
        out = out substr(s, 1, RSTART - 1) val[substr(s, RSTART + 1, RLENGTH - 2)]
        s = substr(s, RSTART + RLENGTH)
      }
      print out s > deck
    }
    close(deck)
    print c "\t" cname[c] "\t" plist > index_file
  }
  close(index_file)
  exit 0
}

function colnames(    i, s) { s = ""; for (i = 1; i <= ncol; i++) s = s (i > 1 ? " " : "") col[i]; return s }
