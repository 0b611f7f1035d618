# reproduce.awk: the report of 'make reproduce' (run by scripts/reproduce.sh).
#   awk -f scripts/reproduce.awk -v out=DIR -v values=sessions/paper/values.csv \
#       -v run=DIR/run.txt -v loads=DIR/paper-load.txt DIR/raw.csv
# Input: raw.csv, the CSV tables uasrisk printed for sessions/paper.ses (descent, parametric, grid
# summary rows, sweeps, compare, grid cells); run.txt, the conditions of the run (key=value);
# values.csv, the paper's printed numbers; paper-load.txt, "FILE Q" per paper grid CSV with
# the Q that 'grid load' computes. Output in DIR: report.md and the CSV files listed in it.
# Our values are taken as uasrisk printed them; a value computed twice must be printed the same
# (the report lists any that differ). Ratios are ours / paper.

BEGIN {
  FS = ","
  TOL = 1.3                         # the issue's target: every Q within a factor 1.3
  NCASE = split("C B A A1 A2", CASES, " ")
  NWIND = split("0 2 4 6 8 10", WINDS, " ")
  NFACE = split("0 45 90 135 180", FACES, " ")
  read_run(run)
  read_values(values)
}

# ---- raw.csv: remember every value under quantity|case|wind|face ----

/^# grid of case / {
  # "# grid of case A, wind 0 m/s, face 0 deg (computed); status: complete": cells follow
  s = $0
  sub(/^# grid of case /, "", s)
  split(s, w, " ")
  sub(/,$/, "", w[1])
  cellkey = w[1] "|" (w[3] + 0) "|" (w[6] + 0)
  next
}
/^#/ { next }
/^(case|dpar|x|t),/ { hdr = $0; next }
hdr == "case,wind,speed,angle" { put("speed", $1, $2, "", $3); put("angle", $1, $2, "", $4); next }
hdr ~ /^case,wind,speed,angle,planform,/ {
  put("planform", $1, $2, "", $5); put("mtow", $1, $2, "", $6); put("gliding", $1, $2, "", $7)
  put("pof_rcc", $1, $2, "", $8); put("pof_bc", $1, $2, "", $9); put("pof_awke", $1, $2, "", $10)
  next
}
hdr ~ /,q,seconds$/ {
  # case,wind,speed,angle,face,step,cells,contact_cells,q,seconds
  put("q", $1, $2, $5, $9)
  gridstep = $6
  if (!(($1 " at " $2 " m/s") in SEC)) {
    SEC[$1 " at " $2 " m/s"] = 1
    TIMES = TIMES (TIMES == "" ? "" : ", ") $1 " at " $2 " m/s " $10 " s"
  }
  next
}
hdr == "case,wind,face,speed,angle,q" { put("q", $1, $2, $3, $6); next }
hdr ~ /^case,wind,p_centre,/ {
  # case,wind,p_centre,gliding,q_parametric,q,factor (compare prints no face)
  put("p_centre", $1, $2, "", $3); put("gliding", $1, $2, "", $4)
  put("q_parametric", $1, $2, "", $5); put("q", $1, $2, "", $6); put("factor", $1, $2, "", $7)
  next
}
hdr ~ /^dpar,dperp,contact,/ && cellkey != "" {
  k = cellkey SUBSEP lat($1) SUBSEP lat($2)
  OP[k] = $8 + 0
  OC[k] = $3 + 0
  HAVE[cellkey] = 1
  next
}

# the sections go to a body file; the report is the header, the summary of their verdicts, the body
END {
  md = out "/report.md"
  body = out "/report.body"
  values_section()
  table17_section()
  figures_section()
  grids_section()
  consistency_section()
  close(body)
  header()
  summary()
  while ((getline l < body) > 0) print l > md
  close(body)
  close(md)
  system("rm -f '" body "'")
}

# ---- helpers ----

function read_run(f,    l, i) {
  while ((getline l < f) > 0) {
    i = index(l, "=")
    if (i) RUN[substr(l, 1, i - 1)] = substr(l, i + 1)
  }
  close(f)
}

function read_values(f,    l, a) {
  NV = 0
  while ((getline l < f) > 0) {
    if (l ~ /^#/ || l ~ /^source,/ || l == "") continue
    split(l, a, ",")
    NV++
    VS[NV] = a[1]; VQ[NV] = a[2]; VC[NV] = a[3]; VW[NV] = a[4]; VF[NV] = a[5]; VV[NV] = a[6]
    VN[NV] = a[7]
  }
  close(f)
}

# a value of ours; a second, different value for the same key is a conflict
function put(q, c, w, f, v,    k) {
  k = q "|" c "|" (w + 0) "|" f
  if (k in OURS) {
    if (OURS[k] != v) CONFLICT[k] = CONFLICT[k] " " v
    NREP[k]++
  } else {
    OURS[k] = v
  }
}

function ours(q, c, w, f,    k) {
  k = q "|" c "|" (w + 0) "|" f
  return (k in OURS) ? OURS[k] : ""
}

# a lattice offset as a key: two decimals, no negative zero
function lat(x,    s) {
  s = sprintf("%.2f", x + 0)
  return s == "-0.00" ? "0.00" : s
}

function ratio(a, b) {
  if (a == "" || b == "" || b + 0 == 0) return ""
  return sprintf("%.3f", a / b)
}

function within(r) {
  if (r == "") return ""
  return (r + 0 >= 1 / TOL && r + 0 <= TOL) ? "yes" : "no"
}

function blank(s) { return s == "" ? "-" : s }

function p(s) { print s > body }

function m(s) { print s > md }

function csvline(f, s) { print s > f }

# ---- report ----

function header(    wall) {
  wall = RUN["wall"] + 0
  m("# Reproduction of Jiang, Blom & Rattanagraikanakorn (2025)")
  m("")
  m("Written by `make reproduce` (scripts/reproduce.sh, scripts/reproduce.awk) from one run of")
  m("`" RUN["sessions"] "` with CSV output (`" out "/raw.csv`).")
  m("")
  if (RUN["step"] ~ /quick/) {
    m("**Grid pitch " RUN["step"] ": not a reproduction.**")
    m("")
  }
  m("| run | |")
  m("|---|---|")
  if ("started" in RUN) m("| started | " RUN["started"] " |")
  m("| finished | " RUN["date"] " |")
  m("| git commit | " RUN["commit"] " |")
  m("| machine | " RUN["machine"] " |")
  m("| nproc | " RUN["nproc"] " (load average at the start: " RUN["load"] "; the machine is shared, so times are noisy) |")
  m("| grid pitch | " RUN["step"] " |")
  m("| grids run | " RUN["grids"] " (each session stands alone, so some grids are run more than once) |")
  m("| single grids' own timings | " (TIMES == "" ? "-" : TIMES) " (sweeps and compare print no times) |")
  m("| wall time of the run | " sprintf("%d s (%d min %02d s)", wall, int(wall / 60), wall % 60) " |")
  m("| status | " RUN["status"] " |")
  m("")
  m("*Ours* is this run; *paper* is the number the paper prints (sessions/paper/values.csv, each")
  m("value with its table); *ratio* = ours / paper. These are validation results, reported as they")
  m("are: the models are not tuned to the paper's Q values. The target is every Q within a factor")
  m(TOL " of the paper (ratio in [" sprintf("%.3f", 1 / TOL) ", " TOL "]).")
  m("")
}

# the verdicts of the sections, first
function summary(    i) {
  m("## Summary")
  m("")
  m("- Table 17: **" T17IN " of 15 Q values within a factor " TOL "** of the paper; ratios (ours / paper) " T17R ".")
  m("- Ordering C >= B >= A >= A1 >= A2 (ours): " ORDS ".")
  m("- Q rises with wind 0 -> 4 -> 10 m/s (ours): " RISE3 "; over every 2 m/s step: " RISE6 ".")
  m("- Every printed Q of the paper (all tables, repeats included): " QIN " of " QN " within a factor " TOL ".")
  m("- The paper's grids: captions against the full-plane sums of the printed cells: " MISMATCH ".")
  m("- Footprint overlap with the paper's grids (cells with P > 0 in both / in either; a shift is a")
  m("  diagnostic, not applied): " FOOT ".")
  m("- Repeated computations: " REPEATS ".")
  m("")
}

# every printed number of the paper beside ours, grouped by table
function values_section(    i, o, r, f, last, nq, nin, s, note) {
  f = out "/values.csv"
  csvline(f, "source,quantity,case,wind,face,ours,paper,ratio,within_" TOL)
  p("## Every printed number of the paper")
  p("")
  p("All numbers also in `values.csv`. Q in m^2, speed in m/s, angle in degrees, probabilities as")
  p("fractions. Tables 11-13 rows come from `compare` (P{F|Delta=(0,0)} x gliding area against Q).")
  last = ""
  for (i = 1; i <= NV; i++) {
    o = ours(VQ[i], VC[i], VW[i], VF[i])
    r = ratio(o, VV[i])
    s = VQ[i] == "q" ? within(r) : ""
    if (VQ[i] == "q" && o != "") { nq++; if (s == "yes") nin++ }
    csvline(f, VS[i] "," VQ[i] "," VC[i] "," VW[i] "," VF[i] "," o "," VV[i] "," r "," s)
    if (VS[i] != last) {
      p("")
      p("### " VS[i])
      p("")
      p("| quantity | case | wind | ours | paper | ratio | Q within x" TOL " | where |")
      p("|---|---|---:|---:|---:|---:|---|---|")
      last = VS[i]
    }
    note = VN[i]
    gsub(/\|/, "\\|", note)
    p("| " VQ[i] " | " VC[i] " | " VW[i] " | " blank(o) " | " VV[i] " | " blank(r) " | " s " | " note " |")
  }
  close(f)
  p("")
  QIN = nin + 0; QN = nq + 0
  p("**Q values within a factor " TOL " of the paper: " nin + 0 " of " nq + 0 "** (every Q row above,")
  p("repeats included).")
  p("")
}

# Table 17, the ordering C >= B >= A >= A1 >= A2 and the rise with wind
function table17_section(    f, c, w, i, j, o, pv, r, n, nin, line, ord, po, miss, a, b, pa, pb, ok, pok, ck, sw, rc) {
  f = out "/table17.csv"
  ck = out "/checks.csv"
  csvline(f, "case,wind,ours,paper,ratio,within_" TOL)
  csvline(ck, "check,subject,ours,paper")
  p("## Table 17: Q (m^2) for cases C, B, A, A1, A2 at 0, 4 and 10 m/s wind")
  p("")
  p("| case | 0 m/s ours | paper | ratio | 4 m/s ours | paper | ratio | 10 m/s ours | paper | ratio |")
  p("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
  split("0 4 10", sw, " ")
  for (i = 1; i <= NCASE; i++) {
    c = CASES[i]
    line = "| " c
    for (j = 1; j <= 3; j++) {
      w = sw[j]
      o = ours("q", c, w, 0)
      pv = paper("Table 17", "q", c, w)
      r = ratio(o, pv)
      n++
      if (within(r) == "yes") nin++
      csvline(f, c "," w "," o "," pv "," r "," within(r))
      line = line " | " blank(o) " | " pv " | " blank(r) (within(r) == "no" ? " (out)" : "")
      T17R = T17R (T17R == "" ? "" : ", ") c "@" w " " blank(r)
    }
    p(line " |")
  }
  close(f)
  p("")
  T17IN = nin + 0
  p("**Within a factor " TOL ": " nin + 0 " of " n " values** (\"out\" marks the others). In `table17.csv`.")
  p("")

  # ordering at each wind of the table
  p("### Ordering C >= B >= A >= A1 >= A2")
  p("")
  p("| wind | ours | paper |")
  p("|---:|---|---|")
  for (j = 1; j <= 3; j++) {
    w = sw[j]
    ord = ""; po = ""; miss = ""
    for (i = 1; i < NCASE; i++) {
      a = ours("q", CASES[i], w, 0); b = ours("q", CASES[i + 1], w, 0)
      pa = paper("Table 17", "q", CASES[i], w); pb = paper("Table 17", "q", CASES[i + 1], w)
      if (a == "" || b == "") miss = miss " " CASES[i] "/" CASES[i + 1]
      else if (a + 0 < b + 0) ord = ord (ord == "" ? "" : ", ") CASES[i] " < " CASES[i + 1] " (" a " < " b ")"
      if (pa + 0 < pb + 0) po = po (po == "" ? "" : ", ") CASES[i] " < " CASES[i + 1]
    }
    ok = miss != "" ? "missing" : ord == "" ? "holds" : "fails"
    pok = po == "" ? "holds" : "fails"
    ORDS = ORDS (ORDS == "" ? "" : "; ") w " m/s " ok (ord != "" ? " (" ord ")" : "")
    p("| " w " | " ok (ord != "" ? ": " ord : "") (miss != "" ? " (no value for" miss ")" : "") " | " pok (po != "" ? ": " po : "") " |")
    csvline(ck, "ordering C>=B>=A>=A1>=A2,wind " w "," ok "," pok)
  }
  p("")

  # the rise with wind: at the table's winds, and over the 2 m/s steps of Figs. 10 and 13
  p("### Does Q rise with wind? (A, A1, A2, B; C for reference)")
  p("")
  p("| case | 0 -> 4 -> 10 m/s (Table 17) ours | paper | every 2 m/s step 0..10 (Figs. 10, 13) ours |")
  p("|---|---|---|---|")
  split("A A1 A2 B C", rc, " ")
  for (i = 1; i <= 5; i++) {
    c = rc[i]
    ok = rises(c, "0 4 10", "ours")
    pok = rises(c, "0 4 10", "paper")
    r = rises(c, "0 2 4 6 8 10", "ours")
    p("| " c " | " ok " | " pok " | " r " |")
    csvline(ck, "Q rises with wind (0;4;10)," c "," word(ok) "," word(pok))
    if (c != "C") {
      RISE3 = RISE3 (RISE3 == "" ? "" : ", ") c " " word(ok)
      RISE6 = RISE6 (RISE6 == "" ? "" : ", ") c " " word(r)
    }
    csvline(ck, "Q rises with wind (0;2;4;6;8;10)," c "," word(r) ",")
  }
  close(ck)
  p("")
  p("The paper prints only 0, 4 and 10 m/s; its Figs. 10 and 13 show rising curves for A, A1, A2")
  p("and B. Checks also in `checks.csv`.")
  p("")
}

function word(s) { return s ~ /^yes/ ? "yes" : s ~ /^no/ ? "no" : "missing" }

# "yes" if Q strictly rises over the winds, else "no: w1->w2 a->b; ..."
function rises(c, list, who,    n, w, i, a, b, bad) {
  n = split(list, w, " ")
  bad = ""
  for (i = 1; i < n; i++) {
    a = who == "ours" ? ours("q", c, w[i], 0) : paper("Table 17", "q", c, w[i])
    b = who == "ours" ? ours("q", c, w[i + 1], 0) : paper("Table 17", "q", c, w[i + 1])
    if (a == "" || b == "") return "missing"
    if (!(b + 0 > a + 0)) bad = bad (bad == "" ? "" : ", ") w[i] "->" w[i + 1] " m/s: " a " -> " b
  }
  return bad == "" ? "yes" : "no: " bad
}

# the paper's value of a quantity in a table, or ""
function paper(src, q, c, w,    i) {
  for (i = 1; i <= NV; i++) {
    if (VS[i] == src && VQ[i] == q && VC[i] == c && VW[i] + 0 == w + 0) return VV[i]
  }
  return ""
}

# the paper's value of a zero-face Q at a wind in any table, and where it is printed
function paper_q(c, w,    i) {
  PQSRC = ""
  for (i = 1; i <= NV; i++) {
    if (VQ[i] == "q" && VC[i] == c && VW[i] + 0 == w + 0 && VF[i] != "") {
      PQSRC = VS[i]
      return VV[i]
    }
  }
  return ""
}

# Figs. 10, 11, 13: our curves, with the paper's printed values where there are any
function figures_section(    f, i, j, c, w, o, pv, line, lo, hi, fc, v) {
  f = out "/curves.csv"
  csvline(f, "figure,case,wind,face,ours,paper,paper_source")
  p("## Figures 10, 11 and 13: Q (m^2) against wind")
  p("")
  p("The paper draws these curves without printing their values; where a table prints the same")
  p("point, it is given in brackets (paper value, ratio). All points in `curves.csv`.")
  p("")
  p("### Fig. 10: cases A, B, C, face 0")
  p("")
  fig_table("Fig. 10", "A B C")
  lo = ""; hi = ""
  for (j = 1; j <= NWIND; j++) {
    o = ours("q", "C", WINDS[j], 0)
    if (o == "") continue
    if (lo == "" || o + 0 < lo + 0) lo = o
    if (hi == "" || o + 0 > hi + 0) hi = o
  }
  p("The paper: \"for case C, horizontal wind has no effect on Q\" (0.849 at 0 m/s, 0.853 at 4, 0.859")
  p("at 10, a spread of 1.2 %). Ours for C over 0..10 m/s: " blank(lo) " to " blank(hi) \
    (lo != "" && lo + 0 > 0 ? sprintf(" (a spread of %.1f %%).", 100 * (hi / lo - 1)) : "."))
  p("")
  p("### Fig. 11: case B, face directions 0, 45, 90, 135, 180 deg")
  p("")
  line = "| wind |"
  for (i = 1; i <= NFACE; i++) line = line " face " FACES[i] " |"
  p(line " max/min |")
  line = "|---:|"
  for (i = 1; i <= NFACE + 1; i++) line = line "---:|"
  p(line)
  for (j = 1; j <= NWIND; j++) {
    w = WINDS[j]
    line = "| " w " |"
    lo = ""; hi = ""
    for (i = 1; i <= NFACE; i++) {
      o = ours("q", "B", w, FACES[i])
      line = line " " blank(o) " |"
      pv = FACES[i] == 0 ? paper_q("B", w) : ""
      csvline(f, "Fig. 11,B," w "," FACES[i] "," o "," pv "," (pv != "" ? PQSRC : ""))
      if (o == "") continue
      if (lo == "" || o + 0 < lo + 0) lo = o
      if (hi == "" || o + 0 > hi + 0) hi = o
    }
    p(line " " (lo != "" && lo + 0 > 0 ? sprintf("%.2f", hi / lo) : "-") " |")
  }
  p("")
  p("The paper: \"the effect of human face direction phi is quite limited\" (no values printed). The")
  p("last column is the largest Q over the smallest across the five faces at that wind.")
  p("")
  p("### Fig. 13: cases B, A, A1, A2, face 0")
  p("")
  fig_table("Fig. 13", "B A A1 A2")
  close(f)
}

# one row per wind, one column per case; the paper's value in brackets where printed
function fig_table(fig, list,    n, cs, i, j, w, o, pv, line) {
  n = split(list, cs, " ")
  line = "| wind |"
  for (i = 1; i <= n; i++) line = line " " cs[i] " |"
  p(line)
  line = "|---:|"
  for (i = 1; i <= n; i++) line = line "---:|"
  p(line)
  for (j = 1; j <= NWIND; j++) {
    w = WINDS[j]
    line = "| " w " |"
    for (i = 1; i <= n; i++) {
      o = ours("q", cs[i], w, 0)
      pv = paper_q(cs[i], w)
      line = line " " blank(o) (pv != "" ? " (" pv ", " blank(ratio(o, pv)) ")" : "") " |"
      csvline(out "/curves.csv", fig "," cs[i] "," w ",0," o "," pv "," (pv != "" ? PQSRC : ""))
    }
    p(line)
  }
  p("")
}

# ---- the paper's printed grids: their sums, and cell by cell against ours ----

function grids_section(    f, fp, l, a, t, c, w, i, cap, o, full, half) {
  # the Q that uasrisk's 'grid load' computes for each file
  while ((getline l < loads) > 0) {
    split(l, a, " ")
    NG++
    GFILE[NG] = a[1]
    GLOAD[NG] = a[2]
  }
  close(loads)

  p("## The paper's printed P{F|Delta} grids")
  p("")
  p("The paper prints each grid for Delta_perp >= 0 only (results are mirror-symmetric for face 0).")
  p("Full-plane sum = 0.0025 m^2 x [sum(column Delta_perp = 0) + 2 x sum(columns Delta_perp > 0)] /")
  p("100, the mirror rule of sessions/paper/grids/README.md; half sum = 0.0025 m^2 x sum(printed")
  p("cells) / 100. `grid load` builds the same full plane (column 0 once, the others mirrored) and")
  p("its Q = sum P x 0.05 m x 0.05 m is given beside it. Our Q is always the full plane.")
  p("")
  p("| table | case | wind | caption Q | full-plane sum | grid load Q | half sum | ours | ours / caption | ours / full-plane sum |")
  p("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
  f = out "/paper-grids.csv"
  csvline(f, "table,case,wind,caption_q,full_sum,load_q,half_sum,ours_q,ratio_caption,ratio_full")
  for (i = 1; i <= NG; i++) {
    read_paper_grid(i)
    t = GT[i]; c = GC[i]; w = GW[i]
    cap = paper("Table " t, "q", c, w)
    o = ours("q", c, w, 0)
    full = sprintf("%.4f", GFULL[i]); half = sprintf("%.4f", GHALF[i])
    p("| " t " | " c " | " w " | " cap " | " full " | " GLOAD[i] " | " half " | " blank(o) " | " \
      blank(ratio(o, cap)) " | " blank(ratio(o, full)) " |")
    csvline(f, t "," c "," w "," cap "," full "," GLOAD[i] "," half "," o "," ratio(o, cap) "," ratio(o, full))
  }
  close(f)
  p("")
  MISMATCH = caption_mismatch()
  p("Captions that differ from the full-plane sum by more than 0.005 m^2: " MISMATCH ".")
  p("")

  # cell by cell
  p("## Cell by cell: our grids against the paper's")
  p("")
  FOOT = "not compared"
  if (gridstep != "" && gridstep + 0 != 0.05) {
    p("Skipped: this run used a " gridstep " m pitch, the paper's grids a 0.05 m pitch.")
    p("")
    return
  }
  p("Compared on the paper's half plane (Delta_perp >= 0) over every lattice point that either grid")
  p("covers (a point outside a grid counts as no contact, P = 0). The paper's text gives P{F|Delta}")
  p("in percent to one decimal and not its contact boundary (a red line in the PDF), so the")
  p("*footprint* is P > 0 at that precision: paper P > 0, ours P >= 0.05 %. *Touch* counts our cells")
  p("where the drone touches the person at all. MAD, bias (ours - paper) and max |diff| are in P")
  p("(0..1) over the union of the two footprints. Per-cell values in `cells-tableNN.csv`, the")
  p("difference map (ours - paper, percent, the paper's layout) in `diffmap-tableNN.csv`. The last")
  p("two columns are diagnostics only (nothing is shifted in the comparison): the mean Delta_par of")
  p("each footprint, and the whole-row shift of our footprint along the course (m, + = forward)")
  p("that would overlap the paper's best.")
  p("")
  p("| table | case | wind | both | only ours | only paper | neither | footprint overlap (both / union) | ours touch | MAD | bias | max abs diff (at dpar, dperp) | footprint centre dpar, ours / paper | along shift of ours for the best overlap (overlap) |")
  p("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---|")
  fp = out "/footprint.csv"
  csvline(fp, "table,case,wind,both,only_ours,only_paper,neither,overlap,ours_touch,mad,bias,max_abs_diff,max_at_dpar,max_at_dperp,centre_ours,centre_paper,best_shift,best_overlap")
  FOOT = ""
  for (i = 1; i <= NG; i++) compare_grid(i, fp)
  close(fp)
  p("")
  p("Under wind the drone descends at psi < 90 deg, so the along offset of one path depends on the")
  p("height at which it is taken: a footprint moved by s along the course is the footprint of")
  p("offsets taken s tan(psi) lower. Ours are taken at tau, the drone centre R_max above the head")
  p("top (paper 4.2, Fig. 7). Where a best shift is found under wind, the summary gives that")
  p("level difference: it says at which height the paper's printed grids appear to measure Delta.")
  p("Q does not depend on it (a shift moves cells, it does not change them).")
  p("")
  p("Maps (paper layout: rows Delta_par from front to back, columns Delta_perp from 0 outwards):")
  p("`=` both have P > 0 within 10 points of each other, `+` / `-` both, ours more than 10 points")
  p("higher / lower, `o` only ours, `p` only the paper, `.` neither.")
  p("")
  for (i = 1; i <= NG; i++) map_grid(i)
}

# the table number, case and wind from the file name, and the grid itself
function read_paper_grid(i,    file, name, a, l, f, n, r, k, v) {
  file = GFILE[i]
  name = file
  sub(/.*\//, "", name)
  sub(/\.csv$/, "", name)
  split(name, a, "_")
  GNAME[i] = a[1]
  GT[i] = a[1]; sub(/^table0*/, "", GT[i])
  GC[i] = a[2]; sub(/^case/, "", GC[i])
  GW[i] = a[3]; sub(/^wind/, "", GW[i])
  GFULL[i] = 0; GHALF[i] = 0
  r = 0
  while ((getline l < file) > 0) {
    if (l ~ /descent angle psi = [0-9.]+ deg/) {
      GPSI[i] = l
      sub(/.*descent angle psi = /, "", GPSI[i])
      sub(/ deg.*/, "", GPSI[i])
    }
    if (l ~ /^#/ || l ~ /^[ \t]*$/) continue
    n = split(l, f, ",")
    if (f[1] == "along") {
      GNCOL[i] = n - 1
      for (k = 2; k <= n; k++) GPERP[i, k - 1] = lat(f[k])
      continue
    }
    r++
    GPAR[i, r] = lat(f[1])
    for (k = 2; k <= n; k++) {
      v = f[k] / 100
      PP[i, GPAR[i, r], GPERP[i, k - 1]] = v
      GHALF[i] += v * 0.0025
      GFULL[i] += v * 0.0025 * (k == 2 ? 1 : 2)
    }
  }
  GNROW[i] = r
  close(file)
}

function caption_mismatch(    i, s, cap) {
  s = ""
  for (i = 1; i <= NG; i++) {
    cap = paper("Table " GT[i], "q", GC[i], GW[i])
    if (cap != "" && (cap - GFULL[i] > 0.005 || GFULL[i] - cap > 0.005)) {
      s = s (s == "" ? "" : "; ") "Table " GT[i] " (case " GC[i] ", " GW[i] " m/s): caption " cap \
          ", full-plane sum " sprintf("%.4f", GFULL[i]) ", half sum " sprintf("%.4f", GHALF[i])
    }
  }
  return s == "" ? "none" : s
}

# the union of the two lattices (half plane) as sorted lists of offsets
function lattice(i, key,    k, a, par, perp) {
  delete UPAR
  delete UPERP
  for (k = 1; k <= GNROW[i]; k++) UPAR[GPAR[i, k]] = 1
  for (k = 1; k <= GNCOL[i]; k++) UPERP[GPERP[i, k]] = 1
  for (k in OP) {
    split(k, a, SUBSEP)
    if (a[1] != key || a[3] + 0 < 0) continue
    UPAR[a[2]] = 1
    UPERP[a[3]] = 1
  }
  NPAR = 0
  for (par in UPAR) LPAR[++NPAR] = par
  NPERP = 0
  for (perp in UPERP) LPERP[++NPERP] = perp
  sortnum(LPAR, NPAR, -1)
  sortnum(LPERP, NPERP, 1)
}

# insertion sort of numbers kept as strings; dir 1 ascending, -1 descending
function sortnum(v, n, dir,    i, j, x) {
  for (i = 2; i <= n; i++) {
    x = v[i]
    for (j = i - 1; j >= 1 && dir * (v[j] - x) > 0; j--) v[j + 1] = v[j]
    v[j + 1] = x
  }
}

function compare_grid(i, fp,    a, key, t, c, w, cf, dm, r, s, par, perp, po, pa, fo, fa, d, both, oo, op, nn, un, mad, bias, mx, touch, line, mpar, mperp, co, ca, k, kb, nb, ob, sh) {
  t = GT[i]; c = GC[i]; w = GW[i]
  key = c "|" w "|0"
  if (!(key in HAVE)) {
    p("| " t " | " c " | " w " | no cells of ours for this case and wind in the run |||||||||||")
    return
  }
  lattice(i, key)
  cf = out "/cells-" GNAME[i] ".csv"
  dm = out "/diffmap-" GNAME[i] ".csv"
  csvline(cf, "dpar,dperp,ours_p,paper_p,diff,footprint")
  line = "along"
  for (s = 1; s <= NPERP; s++) line = line "," LPERP[s]
  csvline(dm, line)
  both = oo = op = nn = 0; mad = bias = mx = 0; touch = 0; co = ca = 0
  delete FO
  delete FA
  for (r = 1; r <= NPAR; r++) {
    par = LPAR[r]
    line = par
    for (s = 1; s <= NPERP; s++) {
      perp = LPERP[s]
      po = ((key, par, perp) in OP) ? OP[key, par, perp] : 0
      pa = ((i, par, perp) in PP) ? PP[i, par, perp] : 0
      if (((key, par, perp) in OC) && OC[key, par, perp]) touch++
      fo = po >= 0.0005
      fa = pa > 0
      d = po - pa
      CH[i, r, s] = fo && fa ? (d > 0.1 ? "+" : d < -0.1 ? "-" : "=") : fo ? "o" : fa ? "p" : "."
      if (fo) { FO[r, s] = 1; co += par }
      if (fa) { FA[r, s] = 1; ca += par }
      if (fo && fa) both++
      else if (fo) oo++
      else if (fa) op++
      else nn++
      if (fo || fa) {
        mad += d < 0 ? -d : d
        bias += d
        if ((d < 0 ? -d : d) > mx) { mx = d < 0 ? -d : d; mpar = par; mperp = perp }
      }
      csvline(cf, par "," perp "," sprintf("%.6g", po) "," sprintf("%.4g", pa) "," sprintf("%.6g", d) "," \
              (fo && fa ? "both" : fo ? "ours" : fa ? "paper" : "neither"))
      line = line "," sprintf("%.1f", 100 * d)
    }
    csvline(dm, line)
  }
  close(cf)
  close(dm)
  GR[i] = NPAR
  GS[i] = NPERP
  for (r = 1; r <= NPAR; r++) MPAR[i, r] = LPAR[r]
  for (s = 1; s <= NPERP; s++) MPERP[i, s] = LPERP[s]
  un = both + oo + op

  # diagnostic: the along shift of our footprint (whole rows) that overlaps the paper's best
  kb = 0; ob = un ? both / un : 0
  for (k = -60; k <= 60; k++) {
    nb = 0
    for (sh in FO) {
      split(sh, a, SUBSEP)
      if (((a[1] - k, a[2]) in FA)) nb++
    }
    if (un && nb / (oo + op + 2 * both - nb) > ob + 1e-12) { ob = nb / (oo + op + 2 * both - nb); kb = k }
  }
  sh = sprintf("%+.2f", kb * (LPAR[1] - LPAR[2]))
  FOOT = FOOT (FOOT == "" ? "" : ", ") "Table " t " " (un ? sprintf("%.2f", both / un) : "-") \
         (kb ? " (" sprintf("%.2f", ob) " with ours moved " sh " m along" \
               lower(kb * (LPAR[1] - LPAR[2]), GPSI[i]) ")" : "")
  p("| " t " | " c " | " w " | " both " | " oo " | " op " | " nn " | " \
    (un ? sprintf("%.2f", both / un) : "-") " | " touch " | " (un ? sprintf("%.3f", mad / un) : "-") " | " \
    (un ? sprintf("%+.3f", bias / un) : "-") " | " sprintf("%.3f", mx) (mx > 0 ? " (" mpar ", " mperp ")" : "") " | " \
    centre(co, both + oo) " / " centre(ca, both + op) " | " sh " (" sprintf("%.2f", ob) ") |")
  csvline(fp, t "," c "," w "," both "," oo "," op "," nn "," (un ? sprintf("%.3f", both / un) : "") "," touch "," \
          (un ? sprintf("%.4f", mad / un) : "") "," (un ? sprintf("%.4f", bias / un) : "") "," sprintf("%.4f", mx) "," mpar "," mperp "," \
          centre(co, both + oo) "," centre(ca, both + op) "," sh "," sprintf("%.3f", ob))
}

# the level difference a whole-footprint shift along the course amounts to: a drone descending
# at psi reaches the same point of the person from dh = shift x tan(psi) lower, so a shift means
# that the offsets are taken when the drone centre is dh below the level of tau
function lower(shift, psi,    dh) {
  if (psi == "" || psi + 0 >= 89.99 || shift == 0) return ""
  dh = shift * sin(psi * 3.14159265358979 / 180) / cos(psi * 3.14159265358979 / 180)
  return sprintf(", as if Delta were taken %.2f m %s the level of tau", dh < 0 ? -dh : dh,
                 dh < 0 ? "above" : "below")
}

function centre(sum, n) { return n ? sprintf("%+.2f", sum / n) : "-" }

function map_grid(i,    r, s, line) {
  if (!(i in GR)) return
  p("Table " GT[i] " (case " GC[i] ", " GW[i] " m/s); columns Delta_perp = " MPERP[i, 1] " .. " MPERP[i, GS[i]] " m:")
  p("")
  p("```")
  for (r = 1; r <= GR[i]; r++) {
    line = sprintf("%6s ", MPAR[i, r])
    for (s = 1; s <= GS[i]; s++) line = line CH[i, r, s]
    p(line)
  }
  p("```")
  p("")
}

# ---- values computed more than once ----

function consistency_section(    k, n, a, s) {
  p("## Repeated computations")
  p("")
  n = 0
  for (k in NREP) n++
  s = ""
  for (k in CONFLICT) {
    split(k, a, "|")
    s = s "\n- " a[1] " of case " a[2] ", wind " a[3] (a[4] != "" ? ", face " a[4] : "") ": " OURS[k] " then" CONFLICT[k]
  }
  p("The sessions overlap: " n " values were asked for more than once (the same grid in several")
  p("sessions; compare's Q is keyed without a face). " (s == "" ? "Every repeat printed the same value." : "These differ:" s))
  if (recalled + 0 > 0) {
    p("")
    p(recalled " grids were recalled: the conditions of each were identical to those of a grid")
    p("computed earlier in the run, so its cells were reused, not simulated again (`set recall")
    p("off` recomputes every grid; that recomputation gives identical cells, as test_recall.sh checks).")
  }
  REPEATS = n " values asked for more than once, " (s == "" ? "all identical" : "SOME DIFFER (see the end)") \
            (recalled + 0 > 0 ? "; " recalled " grid requests recalled, not simulated again" : "")
  for (k in OURS) {
    split(k, a, "|")
    if (a[1] == "q" && a[4] == "" && (("q|" a[2] "|" a[3] "|0") in OURS) && OURS["q|" a[2] "|" a[3] "|0"] != OURS[k]) {
      p("")
      p("compare's Q of case " a[2] " at " a[3] " m/s (" OURS[k] ") differs from the face-0 grid's (" OURS["q|" a[2] "|" a[3] "|0"] ").")
    }
  }
  p("")
}
