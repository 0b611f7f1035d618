# test_tour.sh: sessions/tour.ses replays without a person (exit status 0, nothing on standard
# error) and shows what it says it shows: the tables, the impact, the grid, three kept sweeps and
# the two text plots. Its grids are coarse (0.25 m), so this takes some 10-20 s of CPU.
. tests/lib.sh

if ! command -v gnuplot >/dev/null 2>&1; then
  skip tour "gnuplot is not installed; the tour plots as text"
  finish
fi
run sessions/tour.ses
check status [ "$RC" -eq 0 ]
check stderr_empty [ ! -s "$TMP/err" ]
check shows_state has "$TMP/out" '^speed  *7.48003 m/s  (derived'
check descent_c_and_b cond 'grep -q "^   C    10  39.700  84.52$" "$TMP/out" &&
  grep -q "^   B    10  12.488  36.80$" "$TMP/out"'
check parametric has "$TMP/out" '^   B     0   7.480  90.00     1.430  3.000    2.550'
check impact_row has "$TMP/out" '^   0      0        1 '
check history_plot cond 'has "$TMP/out" "HIC15 window [0-9.]*-[0-9.]* ms" &&
  has "$TMP/out" "t (ms from tau)"'
check grid_coarse has "$TMP/out" '^   B     0  7.480  90.00     0  0.25 '
check grid_show has "$TMP/out" 'Q = 0\.[0-9]* m^2 over the full plane'
check three_sweeps cond 'has "$TMP/out" "^# 3 sweeps kept" &&
  [ "$(grep -c "^ *\(B\|A\|A1\)   wind  *\(0\|5\|10\)  *0 .* 0.25 .*none  *[0-9.]*  *m/s$" "$TMP/out")" -eq 9 ]'
check sweep_plot cond 'has "$TMP/out" "Q against horizontal wind; cases B, A, A1, face 0 deg" &&
  has "$TMP/out" "case A1"'
finish
