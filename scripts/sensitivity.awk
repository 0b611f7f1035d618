# sensitivity.awk: the tables of 'make sensitivity' (run by scripts/sensitivity.sh).
#   awk -f scripts/table17.awk -f scripts/sensitivity.awk -v out=DIR -v values=VALUES.csv \
#       -v grid4=TABLE4.csv -v variants=DIR/variants.txt -v step=STEP -v wall=SECONDS \
#       -v commit=REV -v date=DATE -v shipped=TEXT DIR/raw.csv
# Input: raw.csv, uasimpact's CSV output for each variant after a '#variant NAME' line (the grid
# summary rows case,wind,speed,angle,face,step,cells,contact_cells,q,seconds); variants.txt,
# name|settings|source a line; values.csv, the paper's printed numbers (Table 17's Q); the paper's
# Table 4 grid (its full-plane sum is A's reference at 0 m/s). Output in DIR: sensitivity.csv and
# sensitivity.md. Scoring and labels: scripts/table17.awk, as 'make reproduce' scores.

BEGIN {
  FS = ","
  NCASE = split("C B A A1 A2", CASES, " ")
  NWIND = split("0 4 10", WINDS, " ")
  NKEY = split("C@0 B@0 A@0 B@10 A@10 A1@10 A2@10", KEYS, " ")
  FULLA = paper_fullsum(grid4)
  gdir = grid4; sub(/\/[^\/]*$/, "", gdir)
  paper_fullsums(gdir)
  while ((getline l < variants) > 0) {
    split(l, f, "|")
    NV++
    NAME[NV] = f[1]; SETS[NV] = f[2]; SRC[NV] = f[3]
  }
  close(variants)
  while ((getline l < values) > 0) {
    split(l, f, ",")
    if (f[1] == "Table 17" && f[2] == "q") PAPER[f[3] "@" (f[4] + 0)] = f[6]
  }
  close(values)
}

/^#variant / { v = substr($0, 10); RAN[v] = 1; next }
/^#/ { next }
/^case,/ { hdr = $0; next }
hdr ~ /,q,seconds(,complete)?$/ && v != "" { Q[v, $1 "@" ($2 + 0)] = $9; SEC[v] += $10; next }

END {
  csv = out "/sensitivity.csv"
  print "variant,case,wind,q,paper_q,ratio,label,ratio_twice,reference,scored_ratio,within_" TOL > csv
  for (i = 1; i <= NV; i++) {
    v = NAME[i]
    if (!(v in RAN)) continue
    for (j = 1; j <= NCASE; j++) for (k = 1; k <= NWIND; k++) row(v, CASES[j], WINDS[k], csv)
  }
  close(csv)
  summary(out "/sensitivity.md")
}

# one value of Table 17 for variant v: its CSV row, and what the summary needs
function row(v, c, w, csv,    key, o, pv, in17) {
  key = c "@" w
  o = ((v, key) in Q) ? Q[v, key] : ""
  pv = PAPER[key]
  in17 = score17(c, w, o, pv, full17(c, w))
  R[v, key] = ratio(o, pv)
  SR[v, key] = S17RATIO
  print v "," c "," w "," o "," pv "," R[v, key] "," setof("q", c, w) "," S17R2 "," S17REF "," S17RATIO "," \
        in17 > csv
  if (in17 != "uncounted") N[v]++
  if (in17 == "yes") { IN[v]++; if (setof("q", c, w) == "training") INT[v]++; else INV[v]++ }
  if (S17RATIO != "") {
    if (!((v) in LO) || S17RATIO + 0 < LO[v] + 0) LO[v] = S17RATIO
    if (!((v) in HI) || S17RATIO + 0 > HI[v] + 0) HI[v] = S17RATIO
  }
}

# the largest move of any ratio (q / paper_q) of variant v against the shipped models
function move(v,    j, k, key, d, best, at) {
  best = ""
  for (j = 1; j <= NCASE; j++) for (k = 1; k <= NWIND; k++) {
    key = CASES[j] "@" WINDS[k]
    if (R[v, key] == "" || R["shipped", key] == "") continue
    d = R[v, key] - R["shipped", key]
    if (best == "" || (d < 0 ? -d : d) > (best < 0 ? -best : best)) { best = d; at = key }
  }
  return best == "" ? "-" : sprintf("%+.3f (%s)", best, at)
}

function summary(md,    i, v, j, line, s) {
  print "# Sensitivity of Table 17 to the public ranges (make sensitivity)" > md
  print "" > md
  print "Run " date ", commit " commit ", grid pitch " step " m, " wall " s (" int(wall / 60) " min " \
        sprintf("%02d", wall % 60) " s) for the variants below." > md
  print "" > md
  print "Each variant moves ONE unknown that the calibration does not set (or changes one decision of" > md
  print "the injury curves) to an end of the range its reference sheet gives; everything else is the" > md
  print "shipped, calibrated model (" shipped ")." > md
  print "Nothing is calibrated again: the fitted parameters stay as `make calibrate` left them (fitting" > md
  print "them again for each variant would take about half an hour each). Every grid at the paper's" > md
  print "impact speeds (`set descent paper`), face 0." > md
  print "" > md
  print "*Within x" TOL "*: the 13 counted values of Table 17 scored as `make reproduce` scores them" > md
  print "(training: the 0 m/s values of C, B, A; validation: the other 10): against the full-plane sum of" > md
  print "the paper's grid where it prints one (A at 0 m/s " sprintf("%.4f", FULLA) "), else the printed value;" > md
  print "A1 and A2 at 0 m/s not counted (their plane basis cannot be known)." > md
  print "*Ratios min-max* and the key ratios are the scored ratios (ours / that reference). *Largest move*:" > md
  print "the largest change of any ratio q / paper_q against the shipped models, and where. Every value in" > md
  print "sensitivity.csv; *s*: the grids' own seconds." > md
  print "" > md
  line = "| variant | within x" TOL " (training, validation) | ratios min-max | largest move |"
  for (j = 1; j <= NKEY; j++) line = line " " KEYS[j] " |"
  print line " s |" > md
  line = "|---|---|---|---|"
  for (j = 1; j <= NKEY; j++) line = line "---:|"
  print line "---:|" > md
  for (i = 1; i <= NV; i++) {
    v = NAME[i]
    if (!(v in RAN)) continue
    line = "| " v " | " IN[v] + 0 " of " N[v] " (" INT[v] + 0 ", " INV[v] + 0 ") | " \
           blank(LO[v]) "-" blank(HI[v]) " | " (v == "shipped" ? "-" : move(v)) " |"
    for (j = 1; j <= NKEY; j++) line = line " " blank(SR[v, KEYS[j]]) " |"
    print line " " sprintf("%.0f", SEC[v]) " |" > md
  }
  print "" > md
  print "| variant | settings (after each `case`) | source |" > md
  print "|---|---|---|" > md
  for (i = 1; i <= NV; i++) {
    v = NAME[i]
    if (!(v in RAN)) continue
    s = SETS[i]
    print "| " v " | " (s == "" ? "-" : "`" s "`") " | " SRC[i] " |" > md
  }
  print "" > md
  print "Not run, for want of a model parameter (`uasimpact -c 'model params'`): damping of the Hertz head" > md
  print "contacts, and Jackson-Green elastic-plastic Hertz for them (the laws' damping= and plastic= keys" > md
  print "are fixed in ra3.urm)." > md
  close(md)
}
