# test_sensitivity.sh: 'make sensitivity' (scripts/sensitivity.sh, sensitivity.awk) on coarse 0.2 m
# grids with two variants: the CSV's header and 15 rows a variant (the shipped models always among
# them), the shipped variant's Q is the plain grid's at the paper's speeds, ratio = q / paper_q
# with paper_q Table 17's, the labels, Table 17 scored as 'make reproduce' scores it (A at 0 m/s
# against the full-plane sum of the paper's Table 4 grid, A1 and A2 at 0 m/s against the printed
# value or twice it: scripts/table17.awk, checked here on made-up values too), a variant's
# settings are applied and derived from the shipped values, the summary counts what the CSV says,
# and an unknown variant is refused with one line listing the variants.
. tests/lib.sh

S=$TMP/s
sh scripts/sensitivity.sh -s 0.2 -v nij_rescale_alt,foam_p_6 -o "$S" >"$TMP/out" 2>"$TMP/err"; RC=$?
C=$S/sensitivity.csv
check "sensitivity runs" [ "$RC" -eq 0 ]
check "header" has "$C" '^variant,case,wind,q,paper_q,ratio,label,ratio_twice,reference,scored_ratio,within_1.3$'
check "15 rows per variant, shipped always run" cond '[ "$(grep -c "^shipped," "$C")" -eq 15 ] &&
  [ "$(grep -c "^nij_rescale_alt," "$C")" -eq 15 ] && [ "$(grep -c "^foam_p_6," "$C")" -eq 15 ] &&
  [ "$(lines "$C")" -eq 46 ]'

# the shipped variant's Q is the plain grid's, at the paper's Table 2 speeds
q=$("$UASIMPACT" -c 'set format csv; set descent paper; set step 0.2; set wind 4; case B; grid' |
  awk -F, 'NF == 11 && $1 == "B" { print $9 }')
q10=$("$UASIMPACT" -c 'set format csv; set descent paper; set step 0.2; set wind 10; case A2; grid' |
  awk -F, 'NF == 11 && $1 == "A2" { print $9 }')
check "shipped is the plain grids' Q" cond '[ -n "$q" ] && [ -n "$q10" ] &&
  grep -q "^shipped,B,4,$q,0.382," "$C" && grep -q "^shipped,A2,10,$q10,0.452," "$C"'

# every ratio is q / paper_q; paper_q is Table 17's
check "ratio = q / paper_q" awk -F, 'NR > 1 { n++; if ($6 - $4 / $5 > 0.0005 || $4 / $5 - $6 > 0.0005) bad = 1 }
  END { exit bad || n != 45 }' "$C"
check "paper values" cond 'grep -q "^shipped,C,0,[^,]*,0.849," "$C" && grep -q "^shipped,A,0,[^,]*,0.031," "$C" &&
  grep -q "^shipped,A1,4,[^,]*,0.086," "$C"'
# training: the 0 m/s values of C, B and A, nothing else
check "labels" awk -F, 'NR > 1 { t = ($3 == 0 && ($2 == "C" || $2 == "B" || $2 == "A")) ? "training" : "validation"
  if ($7 != t) bad = 1 } END { exit bad }' "$C"

# A at 0 m/s against the full-plane sum of Table 4's grid (0.0581 as grid load sums it): the
# declared basis (uasimpact-model(5), CALIBRATION, Scoring)
check "A at 0 m/s scoring" awk -F, '$2 == "A" && $3 == 0 { n++
  if ($9 != "full-plane sum of the printed grid" || $10 - $4 / 0.0581225 > 0.0005 || $4 / 0.0581225 - $10 > 0.0005) bad = 1 }
  END { exit bad || n != 3 }' "$C"
# A1 and A2 at 0 m/s: the ratio to twice the printed value beside, and not counted; every other
# row has no ratio_twice
check "A1, A2 at 0 m/s scoring" awk -F, 'NR > 1 && ($2 == "A1" || $2 == "A2") && $3 == 0 { n++
  if ($8 - $4 / (2 * $5) > 0.0005 || $4 / (2 * $5) - $8 > 0.0005) bad = 1
  if ($11 != "uncounted" || $9 != "not counted (printed / twice it)" || $10 != $6) bad = 1 }
  NR > 1 && !(($2 == "A1" || $2 == "A2") && $3 == 0) && $8 != "" { bad = 1 }
  END { exit bad || n != 6 }' "$C"
check "within = scored ratio in [1/1.3, 1.3]" awk -F, 'NR > 1 && $11 != "uncounted" {
  if ($11 != ($10 >= 1 / 1.3 && $10 <= 1.3 ? "yes" : "no")) bad = 1 } END { exit bad }' "$C"

# the scoring itself, on made-up values (the rule make reproduce uses, scripts/table17.awk)
cat >"$TMP/t.awk" <<'EOF'
BEGIN {
  if (score17("A", 0, 0.0581, 0.031, 0.0581225) != "yes" || S17RATIO != "1.000") exit 1
  if (score17("A", 0, 0.031, 0.031, 0.0581225) != "no" || S17REF != "full-plane sum of the printed grid") exit 2
  if (score17("A1", 0, 0.052, 0.026, "") != "uncounted" || S17RATIO != "2.000" || S17R2 != "1.000" ||
      S17REF != "not counted (printed / twice it)") exit 3
  if (score17("A2", 0, 0.025, 0.025, "") != "uncounted" || S17R2 != "0.500") exit 4
  if (score17("A2", 0, "", 0.025, "") != "") exit 5
  if (score17("B", 4, 0.5, 0.382, "") != "no" || S17REF != "printed" || S17R2 != "") exit 6
  if (score17("A", 4, "", 0.216, "") != "") exit 7
  if (score17("B", 0, 0.2861, 0.256, 0.2861) != "yes" || S17RATIO != "1.000") exit 10
  paper_fullsums("sessions/paper/grids")
  if (sprintf("%.4f", full17("B", 0)) != "0.2861" || full17("A1", 0) != "" || full17("A2", 10) == "") exit 11
  if (setof("q", "A", 0) != "training" || setof("q", "A1", 0) != "validation" || setof("q", "C", 4) != "validation") exit 8
  if (sprintf("%.7f", paper_fullsum("sessions/paper/grids/table04_caseA_wind0.csv")) != "0.0581225") exit 9
}
EOF
check "scoring rule (table17.awk)" awk -f scripts/table17.awk -f "$TMP/t.awk"

# a variant's settings are applied: without the Nij rescale (or with it, if the shipped models
# have none) Q moves; its settings are the other value of the shipped one
r=$("$UASIMPACT" -c 'show nij_rescale' | awk '{ print $2 }')
check "variant applied" awk -F, '$1 == "shipped" { s[$2, $3] = $4 } $1 == "nij_rescale_alt" && s[$2, $3] != $4 { d++ }
  END { exit !(d > 0) }' "$C"
check "variant settings from the shipped values" cond 'has "$S/variants.txt" "^nij_rescale_alt|set nij_rescale $((1 - r))|" &&
  has "$S/sensitivity.md" "^| nij_rescale_alt | .set nij_rescale $((1 - r)). |"'
# the arm damping ratios from the shipped hinge slope (beam theory on the arm's tube, 'model
# notes') and a hinge inertia of 0.07 kg m^2
k=$("$UASIMPACT" -c 'model notes' | awk -F'= ' '/restraint .arm1. dof 0 .*hinge k = 3 E I/ { split($3, a, " "); print a[1]; exit }')
c=$(awk -v k="$k" 'BEGIN { printf "%.3g", 2 * 0.2 * sqrt(k * 0.07) }')
check "arm damping from the shipped hinge" cond '[ -n "$k" ] && has "$S/variants.txt" "^arm_zeta_20|set arm_c $c|"'

# the summary: a row per variant that ran, its count that of the CSV
n=$(awk -F, '$1 == "shipped" && $11 == "yes"' "$C" | wc -l | tr -d ' ')
check "summary" cond 'has "$S/sensitivity.md" "^| shipped | $n of 13 (" &&
  has "$S/sensitivity.md" "^| nij_rescale_alt | [0-9]* of 13 ([0-9], [0-9]*) | [0-9.]*-[0-9.]* | [-+][0-9.]* ([A-C12]*@[0-9]*) |" &&
  [ "$(grep -c "^| [a-z_0-9]* | [0-9]* of 13 " "$S/sensitivity.md")" -eq 3 ]'

# an unknown variant: one line naming the ones there are, status 2, nothing written
sh scripts/sensitivity.sh -v foam_p_6,nope -o "$TMP/x" >"$TMP/out" 2>"$TMP/err"; RC=$?
check "unknown variant refused" cond '[ "$RC" -eq 2 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^sensitivity: no variant .nope.; the variants are: shipped foam_r_01 .* tau_top$" &&
  [ ! -e "$TMP/x" ]'
finish
