# test_failed_cells.sh: simulations that fail (here: a joint-speed limit below the drone's
# 39.7 m/s, 'set vmax 20', the check that catches a diverging state) fail their cells with the
# reason; grid lists them and gives no Q,
# grid show marks them, sweep and compare refuse, a single impact says why it failed
. tests/lib.sh

run -c 'case C; set vmax 20; set step 0.2; grid'
nfail=$(sed -n 's/.*grid: \([0-9]*\) cells failed (their simulations are listed above); Q is not complete$/\1/p' "$TMP/err")
listed=$(grep -c '^grid: cell (-\{0,1\}[0-9.]*, -\{0,1\}[0-9.]*) failed: ' "$TMP/err")
check grid_fails [ "$RC" -eq 1 ]
check grid_failed_count cond '[ -n "$nfail" ] && [ "$nfail" -gt 0 ]'
check grid_failed_listed cond '[ "$listed" -gt 0 ] && [ "$listed" -le "$nfail" ]'
check grid_failed_reason has "$TMP/err" \
  '^grid: cell (.*) failed: \(velocity .* beyond vmax\|non-finite .*\) .* at t = [0-9.e-]* s$'
check grid_partial_note has "$TMP/out" "^# PARTIAL grid (complete 0): $nfail cells failed, 0 not computed; q sums the finished cells only, a lower bound of Q$"
check grid_no_q cond 'grep -A1 "^case  *wind .* q  *seconds  *complete$" "$TMP/out" | tail -1 |
  grep -q "^ *C  *0 .* [0-9.]*  *[0-9.]*  *0$"'

# interactively: shown as failed, no Q; compare refuses; exported and loaded back it is partial
printf 'case C\nset vmax 20\nset step 0.2\ngrid\ngrid show\ncompare\nexport grid %s/f.csv\ngrid load %s/f.csv\ngrid show\n' \
  "$TMP" "$TMP" >"$TMP/in"
run_in "$TMP/in" -i
check show_marks_failed cond 'grep -q "^ *-\{0,1\}[0-9.]* .* fail " "$TMP/out" &&
  has "$TMP/out" "; failed fail$"'
check show_no_q has "$TMP/out" ": Q >= [0-9.]* m^2, partial grid ($nfail failed, 0 pending cells not counted)"
check compare_refuses has "$TMP/err" \
  "^error: compare: \(the grid has $nfail failed and 0 pending cells; Q is not complete\|the impact at (0, 0) failed: velocity .* beyond vmax .*\)$"
check reloaded_partial has "$TMP/out" ": Q >= [0-9.]* m^2, partial grid (0 failed, $nfail pending cells not counted)"

# a sweep stops at the first grid with failed cells
run -c 'case C; set vmax 20; set step 0.2; sweep wind 0,2'
check sweep_refuses cond '[ "$RC" -eq 1 ] && has "$TMP/err" "sweep: $nfail cells failed at wind 0; Q is not complete$"'

# one impact that diverges
run -c 'case C; set vmax 20; impact 0.2 0.2'
check impact_fails cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "impact 0.2 0.2: the simulation failed: .* at t = [0-9.e-]* s$"'

finish
