# reproduce.awk: the report of 'make reproduce' (run by scripts/reproduce.sh).
#   awk -f scripts/table17.awk -f scripts/reproduce.awk -v out=DIR -v values=sessions/paper/values.csv \
#       -v run=DIR/run.txt -v loads=DIR/paper-load.txt DIR/raw.csv
# Input: raw.csv, the CSV tables uasimpact printed for sessions/paper.ses (descent, parametric, grid
# summary rows, sweeps, compare, grid cells, with their '#' notes: the paper's Table 2 as the
# source of speed and angle, tau top in older runs); run.txt, the conditions of the run (key=value);
# values.csv, the paper's printed numbers; paper-load.txt, "FILE Q" per paper grid CSV with the Q
# that 'grid load' computes. Output in DIR: report.md and the CSV files listed in it.
# Our values are taken as uasimpact printed them; a value computed twice must be printed the same
# (the report lists any that differ). Ratios are ours / paper. Every comparison is labelled
# training (the zero-wind grids of A, B and C: their cells, P{F|Delta=(0,0)} among them, and
# their sums) or validation (everything else), the project's calibration rule
# (sessions/paper/README.md). The labels, the ratios and the scoring of Table 17 are
# scripts/table17.awk's (shared with 'make sensitivity'): load it first,
#   awk -f scripts/table17.awk -f scripts/reproduce.awk ...

BEGIN {
  FS = ","
  NCASE = split("C B A A1 A2", CASES, " ")
  NWIND = split("0 2 4 6 8 10", WINDS, " ")
  NFACE = split("0 45 90 135 180", FACES, " ")
  read_run(run)
  read_values(values)
}

# ---- raw.csv: remember every value under quantity|case|wind|face ----

/^# grid of case / {
  # "# grid of case A, wind 0 m/s, face 0 deg (computed); status: complete[; tau top ...]":
  # cells follow
  s = $0
  sub(/^# grid of case /, "", s)
  split(s, w, " ")
  sub(/,$/, "", w[1])
  cellkey = w[1] "|" (w[3] + 0) "|" (w[6] + 0) "|" ($0 ~ /; tau top/ ? "top" : "rmax")
  next
}
# the notes of the next table: speed and angle from the paper's Table 2; Delta at tau top
/^# speed and angle: the paper's Table 2/ { NOTEPAPER = 1; next }
/^# tau top: / { NOTETOP = 1; next }
/^#/ { next }
/^(case|dpar|x|t),/ { hdr = $0; TPAPER = NOTEPAPER; TTOP = NOTETOP; NOTEPAPER = NOTETOP = 0; next }
hdr == "case,wind,speed,angle" { put("speed", $1, $2, "", $3); put("angle", $1, $2, "", $4); next }
hdr ~ /^case,wind,speed,angle,planform,/ {
  put("planform", $1, $2, "", $5); put("mtow", $1, $2, "", $6); put("gliding", $1, $2, "", $7)
  put("pof_rcc", $1, $2, "", $8); put("pof_bc", $1, $2, "", $9); put("pof_awke", $1, $2, "", $10)
  next
}
hdr ~ /,q,seconds(,complete)?$/ {
  # case,wind,speed,angle,face,step,cells,contact_cells,q,seconds
  put(TTOP ? "qtop" : "q", $1, $2, $5, $9)
  speedrow($1, $2, $3, $4, TPAPER)
  gridstep = $6
  if (!(($1 " at " $2 " m/s" (TTOP ? " (tau top)" : "")) in SEC)) {
    SEC[$1 " at " $2 " m/s" (TTOP ? " (tau top)" : "")] = 1
    TIMES = TIMES (TIMES == "" ? "" : ", ") $1 " at " $2 " m/s" (TTOP ? " (tau top)" : "") " " $10 " s"
  }
  next
}
hdr == "case,wind,face,speed,angle,q" {
  put(TTOP ? "qtop" : "q", $1, $2, $3, $6)
  speedrow($1, $2, $4, $5, TPAPER)
  next
}
hdr ~ /^case,wind,p_centre,/ {
  # case,wind,p_centre,gliding,q_parametric,q,factor (compare prints no face); its gliding area is
  # at the grid's angle (Table 2's with 'set descent paper'), parametric's at the descent model's
  put("p_centre", $1, $2, "", $3); put("gliding_compare", $1, $2, "", $4)
  put("q_parametric", $1, $2, "", $5); put("q", $1, $2, "", $6); put("factor", $1, $2, "", $7)
  NCMP++
  if (TPAPER) NCMPP++
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
  read_grids()
  SPEEDS = speeds_text()
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

# the speed and angle of one grid (summary row or sweep row) against the paper's Table 2 (case C's
# column for C, case B's for the others); noted: the table said they came from Table 2
function speedrow(c, w, sp, an, noted,    col, ps, pa) {
  NSR++
  if (noted) NSRN++
  col = c == "C" ? "C" : "B"
  ps = paper("Table 2", "speed", col, w)
  pa = paper("Table 2", "angle", col, w)
  if (ps != "" && sp + 0 == ps + 0 && an + 0 == pa + 0) NSRM++
  else if (!((c "|" w) in SPMISS)) {
    SPMISS[c "|" w] = 1
    if (++NSPM <= 4) SPM = SPM (SPM == "" ? "" : ", ") c " at " w " m/s: " sp " m/s, " an " deg"
  }
}

# where the grids' speeds and angles came from, in one line
function speeds_text(    s) {
  if (NSR + 0 == 0) return "no grid rows in the run"
  s = (NSRN + 0 == NSR + 0 ? "every grid row (" NSR + 0 ") says" : NSRN + 0 " of " NSR + 0 " grid rows say") \
      " it took the paper's Table 2 (`set descent paper`: case B's column for A, A1, A2, B," \
      " case C's for C); " NSRM + 0 " of " NSR + 0 " equal Table 2 as printed"
  if (NCMP + 0 > 0) s = s "; " NCMPP + 0 " of " NCMP + 0 " compare rows (Tables 11-13) say so too"
  if (SPM != "") s = s "; not Table 2's (case and wind): " SPM (NSPM > 4 ? " and " NSPM - 4 " more" : "")
  return s
}

# a lattice offset as a key: two decimals, no negative zero
function lat(x,    s) {
  s = sprintf("%.2f", x + 0)
  return s == "-0.00" ? "0.00" : s
}

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
  m("| impact speed and descent angle | " SPEEDS " |")
  m("| moment tau of Delta | Q, the zero-wind grids and the sweeps: rmax, the paper's text (the drone centre R_max above the head top; at zero wind the same grid as top); every grid compared cell by cell at rmax too, the 10 m/s ones after aligning the P-weighted along-course centroids (uasimpact-model(5), CALIBRATION, Scoring) |")
  m("| single grids' own timings | " (TIMES == "" ? "-" : TIMES) " (sweeps and compare print no times) |")
  m("| wall time of the run | " sprintf("%d s (%d min %02d s)", wall, int(wall / 60), wall % 60) " |")
  m("| status | " RUN["status"] " |")
  m("")
  m("*Ours* is this run; *paper* is the number the paper prints (sessions/paper/values.csv, each")
  m("value with its table; the grids in sessions/paper/grids); *ratio* = ours / paper. The target")
  m("is every Q within a factor " TOL " of the paper (ratio in [" sprintf("%.3f", 1 / TOL) ", " TOL "]).")
  m("")
  m("*Set* labels every comparison by the project's calibration rule: **training** is the three")
  m("zero-wind grids, Tables 4, 5 and 6 (cases A, B, C at 0 m/s, every cell over the full plane,")
  m("so also P{F|Delta=(0,0)} at 0 m/s of Tables 11-13 and the grids' sums Q): the only data of")
  m("the paper that `make calibrate` fitted the built-in models' unknowns to (the person: public")
  m("test corridors; uasimpact-model(5), CALIBRATION). **Validation** is everything else: Table 17")
  m("at 4 and 10 m/s, every A1 and A2 value, the 10 m/s grids (Tables 8-10, 15, 16), the faces of")
  m("Fig. 11, the rest of Tables")
  m("11-13, and the numbers of Tables 2 and 3. Validation results are reported as they are: nothing")
  m("was tuned to them.")
  m("")
}

# the verdicts of the sections, first
function summary(    i) {
  m("## Summary")
  m("")
  m("- Table 17: **" T17IN " of " T17N " Q values within a factor " TOL "** of the paper (training " T17TIN " of 3, validation " T17VIN " of " T17N - 3 "); " T17HOW "; ratios (ours / reference) " T17R ".")
  m("- Ordering C >= B >= A >= A1 >= A2 (ours, validation): " ORDS ".")
  m("- Zero-wind grids (training), integral of |Delta P| over the full plane / the paper's Q (goal <= 0.30 each): " IAE0 "; mean |Delta P| over the union footprint: " MAD0 ".")
  m("- 10 m/s grids (validation), integral of |Delta P| / the paper's Q at the text's tau, after aligning the P-weighted along-course centroids (goal <= 0.40 each; unaligned beside): " IAE10 "; mean |Delta P| over the union footprint, unaligned: " MAD10 ".")
  m("- Impact speed and descent angle: " SPEEDS ".")
  m("- Q rises with wind 0 -> 4 -> 10 m/s (ours, validation): " RISE3 "; over every 2 m/s step: " RISE6 ".")
  m("- Every printed Q of the paper (all tables, repeats included, against the printed value): " QIN " of " QN " within a factor " TOL " (training " QTIN " of " QTN ", validation " QVIN " of " QVN ").")
  m("- The paper's grids: captions against the full-plane sums of the printed cells: " MISMATCH ".")
  m("- Footprint overlap with the paper's grids (cells with P > 0 in both / in either, as computed): " FOOT ".")
  m("- Repeated computations: " REPEATS ".")
  m("")
}

# every printed number of the paper beside ours, grouped by table
function values_section(    i, o, r, f, last, s, note, st, fq, rf) {
  f = out "/values.csv"
  csvline(f, "source,quantity,case,wind,face,ours,paper,ratio,within_" TOL ",set,full_plane_sum,ratio_full_plane_sum")
  p("## Every printed number of the paper")
  p("")
  p("All numbers also in `values.csv`. Q in m^2, speed in m/s, angle in degrees, probabilities as")
  p("fractions. Tables 11-13 rows come from `compare` (P{F|Delta=(0,0)} x gliding area against Q).")
  p("Where the paper prints the grid of a Q, the full-plane sum of its printed cells is given")
  p("beside the printed value (they differ for Tables 4 and 5, see below). The Table 2 and Table 3")
  p("rows are uasimpact's descent and parametric models; the grids' own speeds and angles (and so the")
  p("gliding areas of Tables 11-13, from `compare`) are in the header (*impact speed and descent")
  p("angle*).")
  last = ""
  for (i = 1; i <= NV; i++) {
    o = ours(VQ[i] == "gliding" && VS[i] ~ /^Table 1[123]$/ ? "gliding_compare" : VQ[i], VC[i], VW[i], VF[i])
    r = ratio(o, VV[i])
    s = VQ[i] == "q" ? within(r) : ""
    st = setof(VQ[i], VC[i], VW[i])
    fq = VQ[i] == "q" ? fullq(VC[i], VW[i]) : ""
    rf = ratio(o, fq)
    if (VQ[i] == "q" && o != "") {
      nq++; if (s == "yes") nin++
      if (st == "training") { nqt++; if (s == "yes") nint++ }
      else { nqv++; if (s == "yes") ninv++ }
    }
    csvline(f, VS[i] "," VQ[i] "," VC[i] "," VW[i] "," VF[i] "," o "," VV[i] "," r "," s "," st "," fq "," rf)
    if (VS[i] != last) {
      p("")
      p("### " VS[i])
      p("")
      p("| quantity | case | wind | set | ours | paper | ratio | Q within x" TOL " | full-plane sum of the printed grid (ratio) | where |")
      p("|---|---|---:|---|---:|---:|---:|---|---|---|")
      last = VS[i]
    }
    note = VN[i]
    gsub(/\|/, "\\|", note)
    p("| " VQ[i] " | " VC[i] " | " VW[i] " | " st " | " blank(o) " | " VV[i] " | " blank(r) " | " s " | " \
      (fq != "" ? fq " (" blank(rf) ")" : "") " | " note " |")
  }
  close(f)
  p("")
  QIN = nin + 0; QN = nq + 0; QTIN = nint + 0; QTN = nqt + 0; QVIN = ninv + 0; QVN = nqv + 0
  p("**Q values within a factor " TOL " of the printed value: " nin + 0 " of " nq + 0 "** (every Q row")
  p("above, repeats included; training " nint + 0 " of " nqt + 0 ", validation " ninv + 0 " of " nqv + 0 ").")
  p("")
}

# the full-plane sum of the paper's printed grid of a case and wind (4 decimals), or ""
function fullq(c, w) {
  return ((c "|" (w + 0)) in FULLQ) ? sprintf("%.4f", FULLQ[c "|" (w + 0)]) : ""
}

# Table 17, the ordering C >= B >= A >= A1 >= A2 and the rise with wind
function table17_section(    f, c, w, i, j, o, pv, r, n, nin, ck, sw, rc, st, ref, refv, rin, r1, rr, a, b, pa, pb, ok, pok, ord, po, miss, qt) {
  f = out "/table17.csv"
  ck = out "/checks.csv"
  csvline(f, "case,wind,ours,paper,ratio,within_" TOL ",set,reference,reference_value,ratio_reference,within_reference")
  csvline(ck, "check,subject,ours,paper")
  p("## Table 17: Q (m^2) for cases C, B, A, A1, A2 at 0, 4 and 10 m/s wind")
  p("")
  p("Each value is scored against a *reference*, as uasimpact-model(5) declares (CALIBRATION,")
  p("Scoring): where the paper prints a grid of that case and wind (Tables 4-6, 8-10, 15, 16), the")
  p("full-plane sum of that grid, computed here from sessions/paper/grids/ (Table 17's 0.031 for A")
  p("at 0 m/s is Table 4's half-plane sum); else the value Table 17 prints (4 m/s). A1 and A2 at")
  p("0 m/s have no grid and their plane basis cannot be known: the ratio is given against the")
  p("printed value and against twice it, and they are not counted (k of 13).")
  p("")
  p("| case | wind | set | ours | paper (Table 17) | ratio to it | reference | reference value | ratio to the reference | within x" TOL " |")
  p("|---|---:|---|---:|---:|---:|---|---:|---:|---|")
  split("0 4 10", sw, " ")
  T17R = ""
  for (i = 1; i <= NCASE; i++) {
    c = CASES[i]
    for (j = 1; j <= 3; j++) {
      w = sw[j]
      o = ours("q", c, w, 0)
      pv = paper("Table 17", "q", c, w)
      st = setof("q", c, w)
      r = ratio(o, pv)
      # the declared scoring (scripts/table17.awk): against the full-plane sum of the printed
      # grid where there is one, else the printed value; A1 and A2 at 0 m/s not counted
      rin = score17(c, w, o, pv, ((c "|" (w + 0)) in FULLQ) ? FULLQ[c "|" (w + 0)] : "")
      ref = S17REF; refv = S17REFV; r1 = S17RATIO; rr = S17RR
      if (rin != "uncounted") n++
      if (rin == "yes") { nin++; if (st == "training") T17TIN++; else T17VIN++ }
      csvline(f, c "," w "," o "," pv "," r "," within(r) "," st "," ref "," refv "," r1 "," rin)
      p("| " c " | " w " | " st " | " blank(o) " | " pv " | " blank(r) " | " ref " | " refv " | " blank(rr) " | " \
        (rin == "yes" ? "yes" : rin == "no" ? "**no**" : rin == "uncounted" ? "not counted" : "-") " |")
      T17R = T17R (T17R == "" ? "" : ", ") c "@" w " " blank(r1)
    }
  }
  close(f)
  p("")
  T17IN = nin + 0; T17N = n + 0; T17TIN += 0; T17VIN += 0
  T17HOW = "against the full-plane sum of the paper's grid where it prints one (A at 0 m/s " blank(fullq("A", 0)) "), else the printed value; A1 and A2 at 0 m/s not counted (" a1a2() ")"
  p("**Within a factor " TOL ": " nin + 0 " of " n " counted values** (training " T17TIN " of 3, validation " T17VIN " of " n - 3 "). In `table17.csv`.")
  p("")
  qt = ""
  for (i = 1; i <= NCASE; i++) {
    o = ours("qtop", CASES[i], 10, 0)
    if (o != "") qt = qt (qt == "" ? "" : ", ") CASES[i] " " o " (" blank(ratio(o, ours("q", CASES[i], 10, 0))) " x tau rmax)"
  }
  if (qt != "") {
    p("The run also has 10 m/s grids with tau top (Delta at head-top level; not the declared basis):")
    p("Q " qt ". The two definitions label the same paths differently, so Q differs only by where")
    p("the lattice samples the paths.")
    p("")
  }

  # ordering at each wind of the table
  p("### Ordering C >= B >= A >= A1 >= A2 (validation)")
  p("")
  p("Scored at 4 and 10 m/s. At 0 m/s the paper's printed values mix sums (A's is a half-plane sum),")
  p("so its row is shown for information only.")
  p("")
  p("| wind | ours | paper |")
  p("|---:|---|---|")
  ORDS = ""
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
    if (w != 0) ORDS = ORDS (ORDS == "" ? "" : "; ") w " m/s " ok (ord != "" ? " (" ord ")" : "")
    p("| " w (w == 0 ? " (not scored)" : "") " | " ok (ord != "" ? ": " ord : "") (miss != "" ? " (no value for" miss ")" : "") " | " pok (po != "" ? ": " po : "") " |")
    csvline(ck, "ordering C>=B>=A>=A1>=A2,wind " w "," ok "," pok)
  }
  if (ours("q", "A", 0, 0) != "") {
    ORDS = ORDS "; 0 m/s (not scored) " (index(ORDL0(), "<") ? "fails (" ORDL0() ")" : "holds")
  }
  p("")

  # the rise with wind: at the table's winds, and over the 2 m/s steps of Figs. 10 and 13
  p("### Does Q rise with wind? (A, A1, A2, B; C for reference; validation)")
  p("")
  p("| case | 0 -> 4 -> 10 m/s (Table 17) ours | paper | every 2 m/s step 0..10 (Figs. 10, 13) ours |")
  p("|---|---|---|---|")
  split("A A1 A2 B C", rc, " ")
  RISE3 = ""; RISE6 = ""
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
  p("")
  p("The paper prints only 0, 4 and 10 m/s; its Figs. 10 and 13 show rising curves for A, A1, A2")
  p("and B. Checks also in `checks.csv`.")
  p("")
  # the speeds: every grid at the paper's Table 2
  csvline(ck, "speed and angle from Table 2 (grid rows),all," NSRM + 0 " of " NSR + 0 ",")
  close(ck)
}

# the pairs out of order at 0 m/s (ours), or ""
function ORDL0(    i, a, b, s) {
  s = ""
  for (i = 1; i < NCASE; i++) {
    a = ours("q", CASES[i], 0, 0); b = ours("q", CASES[i + 1], 0, 0)
    if (a != "" && b != "" && a + 0 < b + 0) s = s (s == "" ? "" : ", ") CASES[i] " < " CASES[i + 1] " (" a " < " b ")"
  }
  return s
}

# A1 and A2 at 0 m/s under both readings (not counted)
function a1a2(    i, c, o, pv, s, rin) {
  s = ""
  for (i = 1; i <= 2; i++) {
    c = i == 1 ? "A1" : "A2"
    o = ours("q", c, 0, 0); pv = paper("Table 17", "q", c, 0)
    if (o == "" || pv == "") { s = s (s == "" ? "" : "; ") c " -"; continue }
    rin = score17(c, 0, o, pv, "")
    s = s (s == "" ? "" : "; ") c " " blank(ratio(o, pv)) " against the printed value, " \
        blank(S17R2) " against twice it"
  }
  return s
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
  csvline(f, "figure,case,wind,face,ours,paper,paper_source,set")
  p("## Figures 10, 11 and 13: Q (m^2) against wind (validation)")
  p("")
  p("The paper draws these curves without printing their values; where a table prints the same")
  p("point, it is given in brackets (paper value, ratio to it). The zero-wind points of A, B and C")
  p("are the training grids' sums; every other point is validation. All points in `curves.csv`.")
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
      csvline(f, "Fig. 11,B," w "," FACES[i] "," o "," pv "," (pv != "" ? PQSRC : "") "," \
              (FACES[i] == 0 ? setof("q", "B", w) : "validation"))
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
      csvline(out "/curves.csv", fig "," cs[i] "," w ",0," o "," pv "," (pv != "" ? PQSRC : "") "," setof("q", cs[i], w))
    }
    p(line)
  }
  p("")
}

# ---- the paper's printed grids: their sums, and cell by cell against ours ----

# the Q that uasimpact's 'grid load' computes for each file, and the files themselves
function read_grids(    l, a, i) {
  while ((getline l < loads) > 0) {
    split(l, a, " ")
    NG++
    GFILE[NG] = a[1]
    GLOAD[NG] = a[2]
  }
  close(loads)
  for (i = 1; i <= NG; i++) {
    read_paper_grid(i)
    FULLQ[GC[i] "|" (GW[i] + 0)] = GFULL[i]
  }
}

function grids_section(    f, fp, t, c, w, i, cap, o, full, half, k, tau, line) {
  p("## The paper's printed P{F|Delta} grids")
  p("")
  p("The paper prints each grid for Delta_perp >= 0 only (results are mirror-symmetric for face 0).")
  p("Full-plane sum = 0.0025 m^2 x [sum(column Delta_perp = 0) + 2 x sum(columns Delta_perp > 0)] /")
  p("100, the mirror rule of sessions/paper/grids/README.md; half sum = 0.0025 m^2 x sum(printed")
  p("cells) / 100. `grid load` builds the same full plane (column 0 once, the others mirrored) and")
  p("its Q = sum P x 0.05 m x 0.05 m is given beside it. Our Q is always the full plane (tau rmax).")
  p("")
  p("| table | case | wind | set | caption Q | full-plane sum | grid load Q | half sum | ours | ours / caption | ours / full-plane sum |")
  p("|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|")
  f = out "/paper-grids.csv"
  csvline(f, "table,case,wind,caption_q,full_sum,load_q,half_sum,ours_q,ratio_caption,ratio_full,set")
  for (i = 1; i <= NG; i++) {
    t = GT[i]; c = GC[i]; w = GW[i]
    cap = paper("Table " t, "q", c, w)
    o = ours("q", c, w, 0)
    full = sprintf("%.4f", GFULL[i]); half = sprintf("%.4f", GHALF[i])
    p("| " t " | " c " | " w " | " setof("q", c, w) " | " cap " | " full " | " GLOAD[i] " | " half " | " blank(o) " | " \
      blank(ratio(o, cap)) " | " blank(ratio(o, full)) " |")
    csvline(f, t "," c "," w "," cap "," full "," GLOAD[i] "," half "," o "," ratio(o, cap) "," ratio(o, full) "," setof("q", c, w))
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
  MAD0 = "not compared"
  MAD10 = "not compared"
  IAE0 = "not compared"
  IAE10 = "not compared"
  if (gridstep != "" && gridstep + 0 != 0.05) {
    p("Skipped: this run used a " gridstep " m pitch, the paper's grids a 0.05 m pitch.")
    p("")
    return
  }
  p("Compared on the paper's half plane (Delta_perp >= 0) over every lattice point that either grid")
  p("covers (a point outside a grid counts as no contact, P = 0). The paper's text gives P{F|Delta}")
  p("in percent to one decimal and not its contact boundary (a red line in the PDF), so the")
  p("*footprint* is P > 0 at that precision: paper P > 0, ours P >= 0.05 %. *Touch* counts our cells")
  p("where the drone touches the person at all. *Mean |Delta P|* (MAD), bias (ours - paper) and max")
  p("|diff| are in P (0..1) over the *union footprint*, the cells where ours or the paper's P > 0.")
  p("")
  p("*tau* is the moment our Delta is taken (uasimpact(1), `set tau`): every grid here is at **rmax**,")
  p("the paper's text (the drone centre R_max above the head top). The score is the one declared in")
  p("uasimpact-model(5), CALIBRATION, Scoring: *int |Delta P|* is the integral of |P_ours - P_paper| over")
  p("the full plane (the Delta_perp = 0 column once, the others twice: both grids are mirror-symmetric),")
  p("divided by the paper's Q (the full-plane sum of its printed grid). Under wind the paper's printed")
  p("grids sit downstream of the text's tau (by about R_max/tan(psi)): a 10 m/s grid is scored after")
  p("moving ours along the course so that the P-weighted along-course centroids of the two grids")
  p("coincide (*shift*, m, + = forward; P between our rows interpolated linearly), with the unaligned")
  p("figure beside it. No shift is searched for. Goals (issue 33): at most 0.30 for each zero-wind grid")
  p("(training), at most 0.40 for each 10 m/s grid aligned (validation).")
  p("")
  p("Also per grid, on the paper's half plane: the footprint (cells with P > 0 in both, only ours, only")
  p("the paper's, neither), the mean |Delta P| (MAD), bias and max |diff| over the union footprint, and")
  p("the P-weighted along-course centroids (m).")
  p("")
  p("| table | case | wind | set | int abs Delta P / Q_paper | aligned (shift) | both | only ours | only paper | neither | footprint overlap (both / union) | ours touch | mean abs Delta P | bias | max abs diff (at dpar, dperp) | centroid dpar, ours / paper |")
  p("|---|---|---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|")
  fp = out "/footprint.csv"
  csvline(fp, "table,case,wind,both,only_ours,only_paper,neither,overlap,ours_touch,mad,bias,max_abs_diff,max_at_dpar,max_at_dperp,centroid_ours,centroid_paper,tau,set,iae,shift,iae_aligned")
  FOOT = ""; MAD0 = ""; MAD10 = ""; IAE0 = ""; IAE10 = ""
  for (i = 1; i <= NG; i++) {
    compare_grid(i, fp, "rmax")
    if (GW[i] + 0 == 0) {
      MAD0 = MAD0 (MAD0 == "" ? "" : ", ") "Table " GT[i] " (" GC[i] ") " MADS
      IAE0 = IAE0 (IAE0 == "" ? "" : ", ") "Table " GT[i] " (" GC[i] ") " IAES
    } else {
      MAD10 = MAD10 (MAD10 == "" ? "" : ", ") "Table " GT[i] " (" GC[i] ") " MADS
      IAE10 = IAE10 (IAE10 == "" ? "" : ", ") "Table " GT[i] " (" GC[i] ") " IAEA \
              (IAEA == "-" ? "" : " (unaligned " IAES ", shift " SHIFTS " m)")
    }
  }
  close(fp)
  p("")
  p("Under wind the drone descends at psi < 90 deg, so the along offset of one path depends on the")
  p("height at which it is taken: a footprint moved by s along the course is the footprint of")
  p("offsets taken s tan(psi) lower. With the text's tau our 10 m/s footprints lie upstream of the")
  p("paper's by about R_max/tan(psi); the centroid alignment removes that rigid shift, which moves no")
  p("Q. The aligned cells are in `aligned-tableNN.csv` (columns dpar,dperp,ours_p,paper_p,diff).")
  p("")
  p("Maps (paper layout: rows Delta_par from front to back, columns Delta_perp from 0 outwards;")
  p("as computed at 0 m/s, aligned at 10 m/s): `=` both have P > 0 within 10 points of each other, `+` /")
  p("`-` both, ours more than 10 points higher / lower, `o` only ours, `p` only the paper, `.` neither.")
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

# the full-plane weight of a half-plane column: Delta_perp = 0 once, the others twice (mirror)
function wperp(perp) { return perp + 0 == 0 ? 1 : 2 }

# our P at (par, perp) of grid key, 0 outside it
function pours(key, par, perp,    k) {
  k = key SUBSEP lat(par) SUBSEP perp
  return (k in OP) ? OP[k] : 0
}

# our P moved sft forward along the course, at (x, perp): linear between our rows (pitch h)
function pshift(key, x, perp, sft, h,    y, j, u) {
  y = (x - sft) / h
  j = int(y)
  if (j > y) j--  # floor: int() truncates toward zero
  u = y - j
  if (u < 1e-9) return pours(key, j * h, perp)
  if (u > 1 - 1e-9) return pours(key, (j + 1) * h, perp)
  return (1 - u) * pours(key, j * h, perp) + u * pours(key, (j + 1) * h, perp)
}

# one comparison of paper grid i with our grid at tau: the declared score (the integral of |Delta
# P| over the full plane over the paper's Q; under wind also after aligning the P-weighted
# along-course centroids), the footprint, MAD, bias and max |diff|, the cells and difference map,
# and (under wind) the aligned cells; MADS, IAES, IAEA and SHIFTS hold the figures for the summary
function compare_grid(i, fp, tau,    key, t, c, w, cf, dm, af, r, s, par, perp, po, pa, fo, fa, d, both, oo, op, nn, un, mad, bias, mx, touch, line, mpar, mperp, co, ca, so, sa, st, dstep, iae, iaea, sft, lo, hi, xa, wt, q) {
  t = GT[i]; c = GC[i]; w = GW[i]
  st = setof("q", c, w)
  key = c "|" w "|0|" tau
  MADS = "-"; IAES = "-"; IAEA = "-"; SHIFTS = "-"
  if (!(key in HAVE)) {
    p("| " t " | " c " | " w " | " st " | - | - | no cells of ours for this case, wind and tau in the run ||||||||||")
    return
  }
  lattice(i, key)
  cf = out "/cells-" GNAME[i] ".csv"
  dm = out "/diffmap-" GNAME[i] ".csv"
  csvline(cf, "dpar,dperp,ours_p,paper_p,diff,footprint")
  line = "along"
  for (s = 1; s <= NPERP; s++) line = line "," LPERP[s]
  csvline(dm, line)
  both = oo = op = nn = 0; mad = bias = mx = 0; touch = 0; co = ca = so = sa = 0; iae = 0
  dstep = 0.05  # the paper's pitch: grids_section compares no other
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
      wt = wperp(perp)
      iae += (d < 0 ? -d : d) * wt
      co += po * par * wt; so += po * wt
      ca += pa * par * wt; sa += pa * wt
      if (w + 0 == 0) CH[i, r, s] = fo && fa ? (d > 0.1 ? "+" : d < -0.1 ? "-" : "=") : fo ? "o" : fa ? "p" : "."
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
  q = GFULL[i]
  iae = iae * dstep * dstep
  IAES = q > 0 ? sprintf("%.3f", iae / q) : "-"
  un = both + oo + op
  MADS = un ? sprintf("%.3f", mad / un) : "-"

  # under wind: ours moved so that the P-weighted along-course centroids coincide
  if (w + 0 != 0 && so > 0 && sa > 0) {
    sft = ca / sa - co / so
    SHIFTS = sprintf("%+.2f", sft)
    lo = LPAR[NPAR] + (sft < 0 ? sft : 0) - dstep
    hi = LPAR[1] + (sft > 0 ? sft : 0) + dstep
    af = out "/aligned-" GNAME[i] ".csv"
    csvline(af, "dpar,dperp,ours_p,paper_p,diff")
    iaea = 0
    GR[i] = 0
    for (r = int(hi / dstep + 1); r * dstep >= lo - 1e-9; r--) {
      par = lat(r * dstep)
      GR[i]++
      MPAR[i, GR[i]] = par
      for (s = 1; s <= NPERP; s++) {
        perp = LPERP[s]
        xa = pshift(key, par, perp, sft, dstep)
        pa = ((i, par, perp) in PP) ? PP[i, par, perp] : 0
        d = xa - pa
        iaea += (d < 0 ? -d : d) * wperp(perp)
        fo = xa >= 0.0005
        fa = pa > 0
        CH[i, GR[i], s] = fo && fa ? (d > 0.1 ? "+" : d < -0.1 ? "-" : "=") : fo ? "o" : fa ? "p" : "."
        if (xa > 0 || pa > 0) csvline(af, par "," perp "," sprintf("%.6g", xa) "," sprintf("%.4g", pa) "," sprintf("%.6g", d))
      }
    }
    close(af)
    IAEA = q > 0 ? sprintf("%.3f", iaea * dstep * dstep / q) : "-"
  } else {
    GR[i] = NPAR
    for (r = 1; r <= NPAR; r++) MPAR[i, r] = LPAR[r]
  }
  GS[i] = NPERP
  for (s = 1; s <= NPERP; s++) MPERP[i, s] = LPERP[s]
  MTAU[i] = tau (w + 0 != 0 ? ", aligned by " SHIFTS " m" : "")

  FOOT = FOOT (FOOT == "" ? "" : ", ") "Table " t " " (un ? sprintf("%.2f", both / un) : "-")
  p("| " t " | " c " | " w " | " st " | " IAES " | " (w + 0 != 0 ? IAEA " (" SHIFTS " m)" : "-") " | " \
    both " | " oo " | " op " | " nn " | " \
    (un ? sprintf("%.2f", both / un) : "-") " | " touch " | " MADS " | " \
    (un ? sprintf("%+.3f", bias / un) : "-") " | " sprintf("%.3f", mx) (mx > 0 ? " (" mpar ", " mperp ")" : "") " | " \
    centre(co, so) " / " centre(ca, sa) " |")
  csvline(fp, t "," c "," w "," both "," oo "," op "," nn "," (un ? sprintf("%.3f", both / un) : "") "," touch "," \
          (un ? sprintf("%.4f", mad / un) : "") "," (un ? sprintf("%.4f", bias / un) : "") "," sprintf("%.4f", mx) "," mpar "," mperp "," \
          centre(co, so) "," centre(ca, sa) "," tau "," st "," (IAES == "-" ? "" : sprintf("%.4f", iae / q)) "," \
          (SHIFTS == "-" ? "" : SHIFTS) "," (IAEA == "-" ? "" : sprintf("%.4f", iaea * dstep * dstep / q)))
}

function centre(sum, n) { return n ? sprintf("%+.2f", sum / n) : "-" }

function map_grid(i,    r, s, line, r0, r1, dots) {
  if (!(i in GR)) return
  # rows where neither grid has P > 0 are left out at both ends
  dots = ""
  for (s = 1; s <= GS[i]; s++) dots = dots "."
  r0 = 1; r1 = GR[i]
  while (r0 < r1 && maprow(i, r0) == dots) r0++
  while (r1 > r0 && maprow(i, r1) == dots) r1--
  p("Table " GT[i] " (case " GC[i] ", " GW[i] " m/s, tau " MTAU[i] "); columns Delta_perp = " MPERP[i, 1] " .. " MPERP[i, GS[i]] " m; rows " MPAR[i, r0] " .. " MPAR[i, r1] " m:")
  p("")
  p("```")
  for (r = r0; r <= r1; r++) p(sprintf("%6s ", MPAR[i, r]) maprow(i, r))
  p("```")
  p("")
}

function maprow(i, r,    s, line) {
  line = ""
  for (s = 1; s <= GS[i]; s++) line = line CH[i, r, s]
  return line
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
