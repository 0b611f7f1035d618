# test_outputs.sh: scripts/outputs.sh, the byte-for-byte check of a change (src/README, section
# 5): two records of the same build compare the same (their wall-clock fields and paths aside),
# and a record with one number changed, or a file missing, is told apart.
. tests/lib.sh

sh scripts/outputs.sh record "$UASIMPACT" "$TMP/a" quick >"$TMP/log" 2>&1
sh scripts/outputs.sh record "$UASIMPACT" "$TMP/b" quick >>"$TMP/log" 2>&1
check recorded cond '[ -s "$TMP/a/caseC.out" ] && [ -s "$TMP/a/gridC.csv" ] &&
  grep -q "^C,0," "$TMP/a/caseC.out" && grep -q "^status 0$" "$TMP/a/caseC.out"'
sh scripts/outputs.sh compare "$TMP/a" "$TMP/b" >"$TMP/cmp" 2>&1
RC=$?
check same_build_same cond '[ $RC -eq 0 ] && grep -q "^same: ./caseC.out$" "$TMP/cmp" &&
  ! grep -q "^DIFF" "$TMP/cmp"'

# one digit of one grid cell changed: found
awk -F, -v OFS=, 'NR == 2 { $NF = $NF "1" } { print }' "$TMP/b/gridC.csv" >"$TMP/g" &&
  mv "$TMP/g" "$TMP/b/gridC.csv"
sh scripts/outputs.sh compare "$TMP/a" "$TMP/b" >"$TMP/cmp" 2>&1
RC=$?
check changed_cell_found cond '[ $RC -eq 1 ] && grep -q "^DIFF: ./gridC.csv$" "$TMP/cmp"'
rm "$TMP/b/caseC.err"
sh scripts/outputs.sh compare "$TMP/a" "$TMP/b" >"$TMP/cmp" 2>&1
RC=$?
check missing_found cond '[ $RC -eq 1 ] && grep -q "^missing: ./caseC.err$" "$TMP/cmp"'
finish
