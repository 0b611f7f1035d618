# test_reproduce.sh: the report of 'make reproduce' (scripts/reproduce.sh -n, scripts/reproduce.awk)
# on a made-up run whose numbers are known: ratios, the training and validation labels, Table 17
# scored on the declared basis (against the full-plane sum of the paper's grid where it prints
# one, else the printed value; A1 and A2 at 0 m/s reported and not counted), the ordering and rise checks,
# the speeds of the grids against the paper's Table 2, the paper grids' sums
# (sessions/paper/grids/README.md), the cell-by-cell comparison at the text's tau with the
# declared score (the integral of |Delta P| over the full plane over the paper's Q; under wind
# after aligning the P-weighted along-course centroids, the unaligned figure beside), the
# detection of a value computed twice with different results; and that reproduce.sh stops with
# one line naming the file when the paper's data cannot be found. Last, a whole quick run of
# sessions/paper.ses on coarse grids: every grid at the paper's Table 2 speeds, none at tau top.
. tests/lib.sh

# the paper's data is part of the repository: its absence is a failure, not a skip
G=sessions/paper/grids
check paper_data_present cond '[ -r "$G/table04_caseA_wind0.csv" ] && [ -r sessions/paper/values.csv ] &&
  [ -r sessions/paper/README.md ] && [ "$(ls "$G"/table*.csv | wc -l)" -eq 8 ]'
R=$TMP/r
mkdir -p "$R"
printf '%s\n' 'date=2000-01-01 00:00:00 UTC' 'commit=abc1234' 'machine=test' 'nproc=2' 'load=0 0 0' \
  'sessions=made-up' "step=0.05 m (the paper's)" 'grids=17' 'wall=125' 'status=0' >"$R/run.txt"

# ours: Table 2's first row as printed; Table 17 as printed except A at 0 m/s (0.0581, the
# full-plane sum of Table 4), A2 at 0 m/s (0.050, twice the printed 0.025), B at 4 m/s (0.600: out)
# and A1 at 10 m/s (0.700 > A's 0.677: the ordering fails at 10 m/s); the sweeps at the paper's
# Table 2 (noted) but A2's, which is not noted and A2 at 10 m/s at the model's 12.488 m/s; C at
# 0 m/s a second time with another value; Table 4's grid as ours, with (0, 0) raised to P = 1
# and one cell outside the paper's table (0.9, 0) with P = 0.2; Table 8's grid as ours at tau
# rmax moved 0.25 m forward, and as it is at tau top (with its own Q, 0.6800)
PAPER='# speed and angle: the paper'"'"'s Table 2, case B'"'"'s column, at each wind (...)'
{
  printf 'case,wind,speed,angle\nB,0,7.5,90.0\n'
  echo "$PAPER"
  printf 'case,wind,face,speed,angle,q\n'
  printf '# recalled: the grids of wind 0, 4 are identical to grids computed earlier in this session and were not simulated again\n'
  printf 'C,0,0,40.600,90.00,0.849\nC,4,0,40.600,88.00,0.853\nC,10,0,40.400,84.70,0.859\n'
  echo "$PAPER"
  printf '# recalled: the grid is identical to one computed earlier in this session and was not simulated again\n'
  printf 'case,wind,face,speed,angle,q\n'
  printf 'B,0,0,7.500,90.00,0.256\nB,4,0,8.500,62.00,0.600\nB,10,0,12.500,37.00,0.858\n'
  echo "$PAPER"
  printf 'case,wind,face,speed,angle,q\n'
  printf 'A,0,0,7.500,90.00,0.0581\nA,4,0,8.500,62.00,0.216\nA,10,0,12.500,37.00,0.677\n'
  echo "$PAPER"
  printf 'case,wind,face,speed,angle,q\n'
  printf 'A1,0,0,7.500,90.00,0.026\nA1,4,0,8.500,62.00,0.086\nA1,10,0,12.500,37.00,0.700\n'
  printf 'case,wind,face,speed,angle,q\n'
  printf 'A2,0,0,7.500,90.00,0.050\nA2,4,0,8.500,62.00,0.049\nA2,10,0,12.488,36.80,0.452\n'
  echo "$PAPER"
  printf 'case,wind,speed,angle,face,step,cells,contact_cells,q,seconds\nC,0,40.600,90.00,0,0.05,1271,602,0.8500,9.5\n'
  "$UASIMPACT" -c "set format csv; grid load $G/table04_caseA_wind0.csv; grid cells" |
    sed 's/^0\.000,0\.000,\([01]\),\(.*\),[^,]*$/0.000,0.000,1,\2,1/'
  printf '0.900,0.000,1,0,0,0,0,0.2\n'
  "$UASIMPACT" -c "set format csv; grid load $G/table08_caseA_wind10.csv; grid cells" |
    awk -F, -v OFS=, '/^-?[0-9]/ { $1 = sprintf("%.3f", $1 + 0.25) } { print }'
  echo "$PAPER"
  echo '# tau top: Delta is taken when the drone centre reaches head-top level, 0.863 m further along the course than the paper'"'"'s text (R_max above the head top; '"'"'set tau rmax'"'"')'
  printf 'case,wind,speed,angle,face,step,cells,contact_cells,q,seconds\nA,10,12.500,37.00,0,0.05,1000,500,0.6800,1.5\n'
  "$UASIMPACT" -c "set format csv; grid load $G/table08_caseA_wind10.csv; grid cells" |
    sed 's/^\(# grid of case .*; status: complete\)$/\1; tau top (Delta at head-top level)/'
} >"$R/raw.csv"
check made_up_top_cells has "$R/raw.csv" '^# grid of case A, wind 10 m/s, face 0 deg (.*); status: complete; tau top'
run_report() { sh scripts/reproduce.sh -n -o "$R" >"$TMP/out" 2>"$TMP/err"; RC=$?; }
run_report
check report_status cond '[ "$RC" -eq 0 ] && [ ! -s "$TMP/err" ] && [ -s "$R/report.md" ]'
check report_run has "$R/report.md" '^| wall time of the run | 125 s (2 min 05 s) |$'
# the recalled grids are counted one by one (two of a sweep, one grid)
check report_recalled has "$R/report.md" '^3 grids were recalled: the conditions of each'
check report_commit cond 'has "$R/report.md" "^| git commit | abc1234 |$" && has "$R/report.md" "^| nproc | 2 "'

# the grids' speeds: 17 rows (15 sweep rows, two summaries), 14 noted, 16 equal to Table 2
check speeds_header has "$R/report.md" '^| impact speed and descent angle | 14 of 17 grid rows say it took the paper.s Table 2 (.*); 16 of 17 equal Table 2 as printed; not Table 2.s (case and wind): A2 at 10 m/s: 12.488 m/s, 36.80 deg |$'
check speeds_check has "$R/checks.csv" '^speed and angle from Table 2 (grid rows),all,16 of 17,$'

# every printed number beside ours, labelled: Table 2 as printed (validation), ratio 1
check values_table2 has "$R/values.csv" '^Table 2,speed,B,0,,7.5,7.5,1.000,,validation,,$'
check values_missing has "$R/values.csv" '^Table 2,speed,C,0,,,40.6,,,validation,,$'
# Table 4's caption (training), beside the full-plane sum of its printed grid
check values_caption has "$R/values.csv" '^Table 4,q,A,0,0,0.0581,0.031,1.874,no,training,0.0581,1.000$'
check values_t17_labels cond 'has "$R/values.csv" "^Table 17,q,C,0,0,0.849,0.849,1.000,yes,training,0.8469,1.002$" &&
  has "$R/values.csv" "^Table 17,q,A1,0,0,0.026,0.026,1.000,yes,validation,,$" &&
  has "$R/values.csv" "^Table 17,q,C,4,0,0.853,0.853,1.000,yes,validation,,$"'
check values_p_centre_training cond 'has "$R/values.csv" "^Table 13,p_centre,A,0,,,0.053,,,training,,$" &&
  has "$R/values.csv" "^Table 13,p_centre,A,10,,,1.00,,,validation,,$" &&
  has "$R/values.csv" "^Table 13,factor,A,0,,,4.4,,,validation,,$"'
check values_report_set has "$R/report.md" '^| q | A | 0 | training | 0.0581 | 0.031 | 1.874 | no | 0.0581 (1.000) | caption'

# Table 17, scored on the declared basis (uasimpact-model(5), CALIBRATION, Scoring): against the
# full-plane sum of the paper's grid where it prints one (A at 0 m/s: Table 4's 0.0581, B at
# 0 m/s: Table 5's 0.2861 against the printed 0.256, A1 at 10 m/s: Table 15's), else the printed
# value (4 m/s); A1 and A2 at 0 m/s under both readings and not counted; B at 4 m/s out: 12 of 13
check t17_a0 has "$R/table17.csv" '^A,0,0.0581,0.031,1.874,no,training,full-plane sum of the printed grid,0.0581,1.000,yes$'
check t17_b0 has "$R/table17.csv" '^B,0,0.256,0.256,1.000,yes,training,full-plane sum of the printed grid,0.2861,0.895,yes$'
check t17_a1 has "$R/table17.csv" '^A1,0,0.026,0.026,1.000,yes,validation,not counted (printed / twice it),0.026 / 0.052,1.000,uncounted$'
check t17_a2 has "$R/table17.csv" '^A2,0,0.050,0.025,2.000,no,validation,not counted (printed / twice it),0.025 / 0.050,2.000,uncounted$'
check t17_b4 has "$R/table17.csv" '^B,4,0.600,0.382,1.571,no,validation,printed,0.382,1.571,no$'
check t17_ratio has "$R/table17.csv" '^A1,10,0.700,0.638,1.097,yes,validation,full-plane sum of the printed grid,0.6378,1.098,yes$'
check t17_count has "$R/report.md" '^- Table 17: \*\*12 of 13 Q values within a factor 1.3\*\* of the paper (training 3 of 3, validation 9 of 10); against the full-plane sum of the paper.s grid where it prints one (A at 0 m/s 0.0581), else the printed value; A1 and A2 at 0 m/s not counted (A1 1.000 against the printed value, 0.500 against twice it; A2 2.000 against the printed value, 1.000 against twice it)'
check t17_row has "$R/report.md" '^| A2 | 0 | validation | 0.050 | 0.025 | 2.000 | not counted (printed / twice it) | 0.025 / 0.050 | 2.000 / 1.000 | not counted |$'
check t17_qtop has "$R/report.md" '^Q A 0.6800 (1.004 x tau rmax)'

# the ordering: scored at 4 and 10 m/s (fails at 10), shown at 0 (fails: A1 < A2)
check order_0 has "$R/checks.csv" '^ordering C>=B>=A>=A1>=A2,wind 0,fails,holds$'
check order_4 has "$R/checks.csv" '^ordering C>=B>=A>=A1>=A2,wind 4,holds,holds$'
check order_10 has "$R/checks.csv" '^ordering C>=B>=A>=A1>=A2,wind 10,fails,holds$'
check order_which has "$R/report.md" '^| 10 | fails: A < A1 (0.677 < 0.700) | holds |$'
check order_summary has "$R/report.md" '^- Ordering C >= B >= A >= A1 >= A2 (ours, validation): 4 m/s holds; 10 m/s fails (A < A1 (0.677 < 0.700)); 0 m/s (not scored) fails'
check rises_a has "$R/checks.csv" '^Q rises with wind (0;4;10),A,yes,yes$'
check rises_steps has "$R/checks.csv" '^Q rises with wind (0;2;4;6;8;10),A,missing,$'

# the paper's grids: full-plane (mirror rule) and half sums as in the grids' README, and the Q of
# grid load equal to the full-plane sum
for t in 04,0.0581,0.0310 05,0.2861,0.1529 06,0.8469,0.4447 08,0.6766,0.3610 09,0.8582,0.4608 \
         10,0.8588,0.4507 15,0.6378,0.3399 16,0.4515,0.2324; do
  n=${t%%,*}; full=${t#*,}; full=${full%,*}; half=${t##*,}
  check "grid_sums_table$n" awk -F, -v t="${n#0}" -v f="$full" -v h="$half" \
    '$1 == t { found = 1; if ($5 != f || $6 != f || $7 != h) bad = 1 } END { exit bad || !found }' "$R/paper-grids.csv"
done
check grid_ours_ratio has "$R/paper-grids.csv" '^4,A,0,0.031,0.0581,0.0581,0.0310,0.0581,1.874,1.000,training$'

# cell by cell: Table 4 against itself but for the two changed cells (tau rmax)
pos=$(awk -F, '!/^#/ && $1 != "along" { for (i = 2; i <= NF; i++) if ($i > 0) n++ } END { print n }' \
      "$G/table04_caseA_wind0.csv")
check footprint_counts awk -F, -v pos="$pos" \
  '$1 == 4 { found = 1; if ($4 != pos || $5 != 1 || $6 != 0 || $17 != "rmax" || $18 != "training") bad = 1 } END { exit bad || !found }' "$R/footprint.csv"
mad4=$(awk -v pos="$pos" 'BEGIN { printf "%.3f", (0.947 + 0.2) / (pos + 1) }')
check footprint_max awk -F, -v pos="$pos" \
  '$1 == 4 { f = 1; if ($12 != "0.9470" || $13 != "0.00" || $14 != "0.00") bad = 1
             if ($10 != sprintf("%.4f", (0.947 + 0.2) / (pos + 1))) bad = 1 } END { exit bad || !f }' "$R/footprint.csv"
# the declared score of Table 4: |Delta P| 0.947 at (0, 0) and 0.2 at (0.9, 0) (the Delta_perp = 0
# column, counted once), times the cell area, over the full-plane sum of the printed grid
q4=$(awk -F, '!/^#/ && $1 != "along" { for (i = 2; i <= NF; i++) s += $i / 100 * 0.0025 * (i == 2 ? 1 : 2) }
  END { printf "%.10g", s }' "$G/table04_caseA_wind0.csv")
iae4=$(awk -v q="$q4" 'BEGIN { printf "%.3f", (0.947 + 0.2) * 0.0025 / q }')
check iae_table4 awk -F, -v q="$q4" \
  '$1 == 4 { f = 1; if ($19 != sprintf("%.4f", (0.947 + 0.2) * 0.0025 / q) || $20 != "" || $21 != "") bad = 1 }
  END { exit bad || !f }' "$R/footprint.csv"
check mad_zero_wind cond 'has "$R/report.md" "^- Zero-wind grids (training), integral of |Delta P| over the full plane / the paper.s Q (goal <= 0.30 each): Table 4 (A) $iae4, Table 5 (B) -, Table 6 (C) -; mean |Delta P| over the union footprint: Table 4 (A) $mad4, Table 5 (B) -, Table 6 (C) -\.$"'
check cells_outside has "$R/cells-table04.csv" '^0.90,0.00,0.2,0,0.2,ours$'
check diffmap_row has "$R/diffmap-table04.csv" '^0.00,94.7,0.0,'
check footprint_absent has "$R/report.md" '^| 5 | B | 0 | training | - | - | no cells of ours'
# Table 8 at the text's tau: the paper's grid moved 0.25 m forward. The centroids differ by
# 0.25 m, the alignment moves it back (-0.25 m) and the aligned score is 0; the unaligned is not.
# The tau top cells of the run (an older session's) are not compared.
check footprint_shift awk -F, '$1 == 8 { f++; if ($8 > 0.6 || ($15 - $16 - 0.25)^2 > 1e-6 || $17 != "rmax" || $18 != "validation" || !($19 > 0.05) || $20 != "-0.25" || $21 != "0.0000") bad = 1 }
  END { exit bad || f != 1 }' "$R/footprint.csv"
check cells_rmax_aligned cond '[ -s "$R/cells-table08.csv" ] && grep -q ",ours$" "$R/cells-table08.csv" &&
  [ "$(lines "$R/aligned-table08.csv")" -gt 100 ] && [ ! -e "$R/cells-table08-rmax.csv" ] &&
  awk -F, "NR > 1 && (\$5 > 1e-9 || \$5 < -1e-9) { bad = 1 } END { exit bad }" "$R/aligned-table08.csv"'
check iae_table8_row has "$R/report.md" '^| 8 | A | 10 | validation | 0\.[0-9]* | 0.000 (-0.25 m) | '
check iae_10_summary has "$R/report.md" '^- 10 m/s grids (validation), integral of |Delta P| / the paper.s Q at the text.s tau, after aligning the P-weighted along-course centroids (goal <= 0.40 each; unaligned beside): Table 8 (A) 0.000 (unaligned 0\.[0-9]*, shift -0.25 m), Table 9 (B) -,'
check map_aligned has "$R/report.md" '^Table 8 (case A, 10 m/s, tau rmax, aligned by -0.25 m); columns Delta_perp = 0.00 .. [0-9.]* m; rows [0-9.-]* .. [0-9.-]* m:$'
check no_best_shift cond '! grep -qi "best.*shift" "$R/report.md"'
# the footprint overlap of the summary, as computed (Table 8 moved: partial)
check footprint_level has "$R/report.md" '^- Footprint overlap with the paper.s grids (cells with P > 0 in both / in either, as computed): Table 4 [0-9.]*, Table 8 0\.[0-9]*\.$'

# a value computed twice with different results is reported
check repeats_differ cond 'has "$R/report.md" "SOME DIFFER" && has "$R/report.md" "^- q of case C, wind 0, face 0: 0.849 then 0.8500$"'

# no run to report on: one message, non-zero
rm "$R/raw.csv"
run_report
check report_needs_run cond '[ "$RC" -ne 0 ] && has "$TMP/err" "raw.csv is missing"'

# the paper's data cannot be found: one line naming the file, status 1, nothing run or written
PAPER_GRIDS=$TMP/nogrids sh scripts/reproduce.sh -o "$TMP/r2" >"$TMP/out" 2>"$TMP/err"; RC=$?
check missing_grids cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^reproduce: the paper.s grid $TMP/nogrids/table04_caseA_wind0.csv is missing" &&
  [ ! -e "$TMP/r2" ]'
mkdir -p "$TMP/somegrids"
cp "$G"/table0*.csv "$TMP/somegrids/"
PAPER_GRIDS=$TMP/somegrids sh scripts/reproduce.sh -n -o "$R" >"$TMP/out" 2>"$TMP/err"; RC=$?
check missing_one_grid cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^reproduce: the paper.s grid $TMP/somegrids/table10_caseC_wind10.csv is missing"'
PAPER_VALUES=$TMP/none.csv sh scripts/reproduce.sh -o "$TMP/r3" >"$TMP/out" 2>"$TMP/err"; RC=$?
check missing_values cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^reproduce: the paper.s values $TMP/none.csv are missing or empty" && [ ! -e "$TMP/r3" ]'
: >"$TMP/empty.csv"
PAPER_VALUES=$TMP/empty.csv sh scripts/reproduce.sh -n -o "$R" >"$TMP/out" 2>"$TMP/err"; RC=$?
check empty_values cond '[ "$RC" -eq 1 ] && has "$TMP/err" "empty.csv are missing or empty"'

# the whole reproduction on coarse grids (not a reproduction: make reproduce STEP=0.4): every
# grid at the paper's Table 2, none at tau top (the declared basis), a report with no conflicts
sh scripts/reproduce.sh -s 0.4 -o "$TMP/quick" >"$TMP/out" 2>"$TMP/err"; RC=$?
check quick_status cond '[ "$RC" -eq 0 ] && [ -s "$TMP/quick/report.md" ]'
check quick_paper_speeds has "$TMP/quick/report.md" '^| impact speed and descent angle | every grid row ([0-9]*) says it took the paper.s Table 2 (.*); \([0-9]*\) of \1 equal Table 2 as printed; 6 of 6 compare rows'
check quick_no_tau_top cond '! grep -q "tau top" "$TMP/quick/raw.csv"'
check quick_no_conflict has "$TMP/quick/report.md" '^- Repeated computations: [0-9]* values asked for more than once, all identical'
finish
