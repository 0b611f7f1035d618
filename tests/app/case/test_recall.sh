# test_recall.sh: grid recall (src/app/case/recall.c) from the command line: a grid asked for again
# with everything a cell depends on unchanged reuses the cells of the earlier one (the same bytes
# as a fresh computation, a note says so, seconds about 0); any change that alters a cell
# computes afresh, as do 'set recall off', new model parts and grids that failed; sweep and
# compare say which grids they recalled; the setting is shown, saved and kept by 'case'. The
# source of speed and angle (set descent) and the moment tau (set tau) are among the changes.
# Case A with the analytic bag (set bag_model analytic after each 'case A'): recall is the
# subject, whatever the bag; the membrane bag, A's default at the switch, costs ~20 s CPU a grid.
. tests/lib.sh

NOTE='^# recalled: the cells of an identical grid computed earlier in this session'
# one digit per grid summary of $TMP/out: 1 if a recall note precedes its header
recalls() { awk '/^# recalled: / { r[n + 1] = 1 } /^case,wind,speed,angle,face,step,/ { n++ }
                 END { for (i = 1; i <= n; i++) printf "%d", r[i] + 0 }' "$TMP/out"; }
# the summary rows without their seconds, and the cells of the last grid
rows() { grep -A1 '^case,wind,speed,angle,face,step,' "$TMP/out" | grep -v '^case,\|^--' |
         sed 's/,[0-9.]*,[01]$//'; }
cells() { sed -n '/^# grid of case/,$p' "$TMP/out"; }

# a fresh computation of case A's grid, in a process of its own
run -c 'set format csv; set step 0.2; case A; set bag_model analytic; grid; grid cells'
check fresh_status [ "$RC" -eq 0 ]
check fresh_no_note [ "$(recalls)" = 0 ]
cells >"$TMP/fresh_cells"
rows >"$TMP/fresh_row"
check fresh_cells_read [ "$(lines "$TMP/fresh_cells")" -gt 50 ]

# A, then B, then A again: the third grid is recalled, cells and summary as the fresh ones
run -c 'set format csv; set step 0.2; case A; set bag_model analytic; grid; case B; grid; case A; set bag_model analytic; grid; grid cells'
check back_status [ "$RC" -eq 0 ]
check back_recalled_third [ "$(recalls)" = 001 ]
check back_note_text cond 'grep -q "$NOTE.*nothing was simulated now (.set recall off. recomputes)$" "$TMP/out"'
cells >"$TMP/back_cells"
check back_cells_identical cmp -s "$TMP/fresh_cells" "$TMP/back_cells"
rows >"$TMP/back_rows"
check back_rows_same cond '[ "$(sed -n 1p "$TMP/back_rows")" = "$(cat "$TMP/fresh_row")" ] &&
  [ "$(sed -n 3p "$TMP/back_rows")" = "$(cat "$TMP/fresh_row")" ] &&
  [ "$(sed -n 2p "$TMP/back_rows")" != "$(cat "$TMP/fresh_row")" ]'
check back_seconds_small cond 'grep -A1 "^case,wind" "$TMP/out" | sed -n 8p |
  awk -F, "{ exit !(\$10 < 0.05) }"'

# every change of what a cell depends on computes; put back, the grid is recalled (as with
# another number of threads, which the cells do not depend on)
run -c 'set format csv; set step 0.2; case A; set bag_model analytic; grid;
  set face 10; grid; set face 0;
  set step 0.25; grid; set step 0.2;
  set bag_p0 1.05 atm; grid; set bag_p0 1 atm;
  set hic_beta 0.004; grid; set hic_beta 0.00351;
  set pitch 5; grid; set pitch 0;
  set speed 8; grid; set speed auto;
  set wind 2; grid; set wind 0;
  set descent paper; grid; set descent model;
  set tau top; grid; set tau rmax;
  grid; set threads 1; grid'
check changes_status [ "$RC" -eq 0 ]
check changes_not_recalled [ "$(recalls)" = 000000000011 ]
check changes_same_q cond '[ "$(rows | sed -n 1p)" = "$(rows | sed -n 11p)" ] &&
  [ "$(rows | sed -n 11p)" = "$(rows | sed -n 12p)" ]'
# at zero wind tau top is the same grid (but computed, not recalled: tau is part of the key)
check changes_tau_zero_wind_same [ "$(rows | sed -n 1p)" = "$(rows | sed -n 10p)" ]

# recall off computes (the same cells) and keeps nothing; on again, the earlier grid is recalled
run -c 'set format csv; set step 0.2; case A; set bag_model analytic; grid; set recall off; grid; show recall; grid cells;
  set recall on; grid'
check off_status [ "$RC" -eq 0 ]
check off_computes [ "$(recalls)" = 001 ]
check off_cells_identical cond 'sed -n "/^# grid of case/,/^# Q = /p" "$TMP/out" | sed "\$d" |
  cmp -s - "$TMP/fresh_cells"'
check off_shown has "$TMP/out" '^recall  *off$'

# new model parts (even the same text loaded back) make earlier grids stale
run -c "set format csv; set step 0.2; case A; set bag_model analytic; grid; model save $TMP/m.urm; model load $TMP/m.urm;
  grid"
check parts_status [ "$RC" -eq 0 ]
check parts_not_recalled [ "$(recalls)" = 00 ]

# a grid with failed cells is never recalled
printf 'set format csv\ncase C\nset vmax 20\nset step 0.2\ngrid\ngrid\n' >"$TMP/in"
run_in "$TMP/in" -i
check failed_twice [ "$(grep -c '^error: grid: [0-9]* cells failed' "$TMP/err")" -eq 2 ]
check failed_not_recalled [ "$(recalls)" = 00 ]

# sweep and compare name what they recalled, with the same numbers
run -c 'set format csv; set step 0.2; case C; sweep wind 0,4; sweep wind 4,10; compare'
check sweep_status [ "$RC" -eq 0 ]
check sweep_note cond '[ "$(grep -c "^# recalled: " "$TMP/out")" -eq 2 ] &&
  has "$TMP/out" "^# recalled: the grids of wind 4 are identical to grids computed earlier"'
check sweep_same_q cond '[ "$(grep "^C,4,0," "$TMP/out" | sort -u | wc -l)" -eq 1 ] &&
  [ "$(grep -c "^C,4,0," "$TMP/out")" -eq 2 ]'
check compare_note has "$TMP/out" '^# recalled: the grid is identical to one computed earlier'

# the setting: refused values, kept by case, restored by reset, saved
run -c 'set recall maybe'
check bad_value cond '[ "$RC" -eq 1 ] &&
  has "$TMP/err" "set recall: .maybe. is not accepted; accepted: off or on$"'
run -c "show recall; set recall off; case B; show recall; save session $TMP/s.ses; reset; show recall"
check setting_status [ "$RC" -eq 0 ]
check setting_shown cond '[ "$(grep "^recall " "$TMP/out" | tr -s " ")" = "recall on${NL}recall off${NL}recall on" ]'
check setting_saved has "$TMP/s.ses" '^set recall off$'
run "$TMP/s.ses" -c 'show recall'
check setting_replayed has "$TMP/out" '^recall  *off$'
finish
