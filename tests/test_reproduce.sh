# test_reproduce.sh: the report of 'make reproduce' (scripts/reproduce.sh -n, scripts/reproduce.awk)
# on a made-up run whose numbers are known: ratios, the Table 17 verdicts, the ordering and rise
# checks, the paper grids' sums (sessions/paper/grids/README.md), the cell-by-cell comparison and
# the detection of a value computed twice with different results; and that reproduce.sh stops
# with one line naming the file when the paper's data cannot be found
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
# full-plane sum of Table 4) and A1 at 10 m/s (0.700 > A's 0.677: the ordering fails at 10 m/s);
# C at 0 m/s a second time with another value; Table 4's grid as ours, with (0, 0) raised to
# P = 1 and one cell outside the paper's table (0.9, 0) with P = 0.2; Table 8's grid as ours,
# moved 0.25 m forward
{
  printf 'case,wind,speed,angle\nB,0,7.5,90.0\n'
  printf 'case,wind,face,speed,angle,q\n'
  printf '# recalled: the grids of wind 0, 4 are identical to grids computed earlier in this session and were not simulated again\n'
  printf 'C,0,0,39.7,90,0.849\nC,4,0,39.7,88,0.853\nC,10,0,39.7,84.5,0.859\n'
  printf '# recalled: the grid is identical to one computed earlier in this session and was not simulated again\n'
  printf 'B,0,0,7.5,90,0.256\nB,4,0,8.5,62,0.382\nB,10,0,12.5,37,0.858\n'
  printf 'A,0,0,7.5,90,0.0581\nA,4,0,8.5,62,0.216\nA,10,0,12.5,37,0.677\n'
  printf 'A1,0,0,7.5,90,0.026\nA1,4,0,8.5,62,0.086\nA1,10,0,12.5,37,0.700\n'
  printf 'A2,0,0,7.5,90,0.025\nA2,4,0,8.5,62,0.049\nA2,10,0,12.5,37,0.452\n'
  printf 'case,wind,speed,angle,face,step,cells,contact_cells,q,seconds\nC,0,39.7,90,0,0.05,1271,602,0.8500,9.5\n'
  "$UASRISK" -c "set format csv; grid load $G/table04_caseA_wind0.csv; grid cells" |
    sed 's/^0\.000,0\.000,\([01]\),\(.*\),[^,]*$/0.000,0.000,1,\2,1/'
  printf '0.900,0.000,1,0,0,0,0,0.2\n'
  "$UASRISK" -c "set format csv; grid load $G/table08_caseA_wind10.csv; grid cells" |
    awk -F, -v OFS=, '/^-?[0-9]/ { $1 = sprintf("%.3f", $1 + 0.25) } { print }'
} >"$R/raw.csv"
run_report() { sh scripts/reproduce.sh -n -o "$R" >"$TMP/out" 2>"$TMP/err"; RC=$?; }
run_report
check report_status cond '[ "$RC" -eq 0 ] && [ ! -s "$TMP/err" ] && [ -s "$R/report.md" ]'
check report_run has "$R/report.md" '^| wall time of the run | 125 s (2 min 05 s) |$'
# the recalled grids are counted one by one (two of a sweep, one grid)
check report_recalled has "$R/report.md" '^3 grids were recalled: the conditions of each'
check report_commit cond 'has "$R/report.md" "^| git commit | abc1234 |$" && has "$R/report.md" "^| nproc | 2 "'

# every printed number beside ours: Table 2 as printed, ratio 1
check values_table2 has "$R/values.csv" '^Table 2,speed,B,0,,7.5,7.5,1.000,$'
check values_missing has "$R/values.csv" '^Table 2,speed,C,0,,,40.6,,$'
check values_caption has "$R/values.csv" '^Table 4,q,A,0,0,0.0581,0.031,1.874,no$'

# Table 17: 14 of 15 within 1.3; the ordering fails at 10 m/s only; Q rises for A
check t17_ratio has "$R/table17.csv" '^A1,10,0.700,0.638,1.097,yes$'
check t17_count has "$R/report.md" '^- Table 17: \*\*14 of 15 Q values within a factor 1.3\*\*'
check order_0 has "$R/checks.csv" '^ordering C>=B>=A>=A1>=A2,wind 0,holds,holds$'
check order_10 has "$R/checks.csv" '^ordering C>=B>=A>=A1>=A2,wind 10,fails,holds$'
check order_which has "$R/report.md" '^| 10 | fails: A < A1 (0.677 < 0.700) | holds |$'
check rises_a has "$R/checks.csv" '^Q rises with wind (0;4;10),A,yes,yes$'
check rises_steps has "$R/checks.csv" '^Q rises with wind (0;2;4;6;8;10),A,missing,$'

# the paper's grids: full-plane (mirror rule) and half sums as in the grids' README, and the Q of
# grid load equal to the full-plane sum
for t in 04,0.0581,0.0310 05,0.2861,0.1529 06,0.8469,0.4447 08,0.6766,0.3610 09,0.8582,0.4608 \
         10,0.8588,0.4507 15,0.6378,0.3399 16,0.4515,0.2324; do
  n=${t%%,*}; full=${t#*,}; full=${full%,*}; half=${t##*,}
  check "grid_sums_table$n" awk -F, -v t="${n#0}" -v f="$full" -v h="$half" \
    '$1 == t { found = 1; if ($5 != f || $6 != f || $7 != h) exit 1 } END { exit !found }' "$R/paper-grids.csv"
done
check grid_ours_ratio has "$R/paper-grids.csv" '^4,A,0,0.031,0.0581,0.0581,0.0310,0.0581,1.874,1.000$'

# cell by cell: Table 4 against itself but for the two changed cells
pos=$(awk -F, '!/^#/ && $1 != "along" { for (i = 2; i <= NF; i++) if ($i > 0) n++ } END { print n }' \
      "$G/table04_caseA_wind0.csv")
check footprint_counts awk -F, -v pos="$pos" \
  '$1 == 4 { found = 1; if ($4 != pos || $5 != 1 || $6 != 0) exit 1 } END { exit !found }' "$R/footprint.csv"
check footprint_max awk -F, -v pos="$pos" \
  '$1 == 4 { if ($12 != "0.9470" || $13 != "0.00" || $14 != "0.00") exit 1
             if ($10 != sprintf("%.4f", (0.947 + 0.2) / (pos + 1))) exit 1 }' "$R/footprint.csv"
check cells_outside has "$R/cells-table04.csv" '^0.90,0.00,0.2,0,0.2,ours$'
check diffmap_row has "$R/diffmap-table04.csv" '^0.00,94.7,0.0,'
check footprint_absent has "$R/report.md" '^| 5 | B | 0 | no cells of ours'
check footprint_shift awk -F, '$1 == 8 { f = 1; if ($8 > 0.5 || ($15 - $16 - 0.25)^2 > 1e-6 || $17 != "-0.25" || $18 != "1.000") exit 1 }
  END { exit !f }' "$R/footprint.csv"
# the level difference of that shift: 0.25 m x tan(37 deg) (Table 8's caption angle) above tau
check footprint_level has "$R/report.md" 'Table 8 0\.[0-9]* (1\.00 with ours moved -0\.25 m along, as if Delta were taken 0\.19 m above the level of tau)'

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
finish
