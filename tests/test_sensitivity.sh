# test_sensitivity.sh: 'make sensitivity' (scripts/sensitivity.sh) on coarse 0.2 m grids: the
# shipped variant is the plain grids, ratios are ours over the paper's Table 17, a variant is
# calibrated again to target (b) for case B and picks kappa from its list, unknown variants are
# refused
. tests/lib.sh

S=$TMP/s
sh scripts/sensitivity.sh -s 0.2 -v shipped,arm_k_1000 -o "$S" >"$TMP/out" 2>"$TMP/err"; RC=$?
C=$S/sensitivity.csv
check "sensitivity runs" [ "$RC" -eq 0 ]
check "header" has "$C" '^variant,case,wind,foam_t,kappa,p_centre,q,paper_q,ratio$'
check "15 rows per variant" cond '[ "$(grep -c "^shipped," "$C")" -eq 15 ] &&
  [ "$(grep -c "^arm_k_1000," "$C")" -eq 15 ]'

# the shipped variant's Q is the plain grid's
q=$("$UASRISK" -c 'set format csv; set step 0.2; set wind 4; case B; grid' | awk -F, 'NF == 10 && $1 == "B" { print $9 }')
check "shipped B@4 is the grid's Q" cond '[ -n "$q" ] && grep -q "^shipped,B,4,model,model,[^,]*,$q,0.382," "$C"'

# every ratio is q / paper_q, and paper_q is Table 17's
check "ratios" awk -F, 'NR > 1 { if ($9 - $7 / $8 > 0.0005 || $7 / $8 - $9 > 0.0005) bad = 1 }
  END { exit bad }' "$C"
check "paper values" cond 'grep -q "^shipped,C,0,model,model,[^,]*,[^,]*,0.849," "$C" &&
  grep -q "^shipped,A2,10,model,model,[^,]*,[^,]*,0.452," "$C"'

# the variant is calibrated again: case B at zero wind within 0.002 of P = 0.64, with the found
# foam_t; kappa one of the listed values
check "B calibrated" awk -F, '$1 == "arm_k_1000" && $2 == "B" && $3 == 0 { found = 1
  if ($6 < 0.638 || $6 > 0.642) bad = 1 } END { exit !found || bad }' "$C"
ft=$(awk -F, '$1 == "arm_k_1000" { print $4; exit }' "$C")
p=$("$UASRISK" -c "set format csv; case B; set arm_k 1000; set foam_t $ft; impact 0 0" | awk -F, '$1 == "0" { print $15 }')
check "foam_t reproduces the target" awk -v p="$p" 'BEGIN { exit !(p >= 0.638 && p <= 0.642) }'
check "kappa from the list" awk -F, '$1 == "arm_k_1000" { k[$5] = 1 } END { n = 0; for (x in k) n++
  exit !(n == 1 && (x == 1 || x == 2 || x == 3 || x == 4 || x == 4.5 || x == 5 || x == 5.5 || x == 6 ||
  x == 7 || x == 8)) }' "$C"

# the summary: a row per variant, with its count
check "summary rows" cond 'grep -q "^| shipped | model | model | 0.640 |" "$S/sensitivity.md" &&
  grep -q "^| arm_k_1000 | 0\.0[0-9]* | [0-9.]* | 0.64[0-2] | .* of 15 |" "$S/sensitivity.md"'

# an unknown variant: one line naming the ones there are, status 2
sh scripts/sensitivity.sh -v nope -o "$TMP/x" >"$TMP/out" 2>"$TMP/err"; RC=$?
check "unknown variant refused" cond '[ "$RC" -eq 2 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "no variant .nope.; the variants are: shipped recal arm_k_100"'
finish
