# test_grid.sh: the grid command's acceptance from the command line (issue #6): 'case C; grid' at
# the paper's pitch prints one summary row with a numeric Q, and 'grid cells' prints the same bytes
# with one worker thread and with two
. tests/lib.sh

# the acceptance command as given: case C, zero wind, 0.05 m pitch
run -c 'set format csv; case C; grid'
check grid_c_status [ "$RC" -eq 0 ]
check grid_c_header has "$TMP/out" '^case,wind,speed,angle,face,step,cells,contact_cells,q,seconds$'
check grid_c_q awk -F, '$1 == "C" { n++; if (NF != 10 || $9 !~ /^[0-9]+\.[0-9]+$/ || !($9 > 0.1 && $9 < 3)) bad = 1 }
  END { exit !(n == 1 && !bad) }' "$TMP/out"

# 1 and 2 threads on a coarse grid under wind at face 45 (both sides simulated): identical cells
for n in 1 2; do
  run -c "set format csv; case A; set wind 4; set face 45; set step 0.2; set threads $n; grid; grid cells"
  check "grid_threads_$n" [ "$RC" -eq 0 ]
  sed -n '/^# grid of case/,$p' "$TMP/out" >"$TMP/cells$n"
done
check grid_cells_hit awk -F, 'NF == 8 && $3 == 1 && $8 > 0 { n++ } END { exit !(n >= 10) }' "$TMP/cells1"
check grid_cells_same_threads cmp -s "$TMP/cells1" "$TMP/cells2"
finish
