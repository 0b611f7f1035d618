# test_extents.sh: the grid extents are derived quantities that can also be set (along_min,
# along_max, cross_max): show says derived or set, a set extent bounds the lattice (rounded
# outwards), the derived lattice holds every cell where contact is possible, the cells inside a
# set lattice equal those of the derived grid, and bad extents get one clear error line; with
# 'set tau top' the derived lattice moves downstream by R_max/tan(psi)
. tests/lib.sh

# derived: case C at zero wind reaches about 0.7 m each way (drone R_max 0.65 m about the head)
run -c 'case C; show along_min; show along_max; show cross_max'
check derived_status [ "$RC" -eq 0 ]
check derived_said awk '/\(derived: every cell where contact is possible/ { n++ } END { exit n != 3 }' "$TMP/out"
check derived_values awk '$1 == "along_min" { a = $2 } $1 == "along_max" { b = $2 } $1 == "cross_max" { x = $2 }
  END { exit !(a < -0.5 && a > -1.2 && b > 0.5 && b < 1.2 && x > 0.5 && x < 1.5 && a == -b) }' "$TMP/out"

# under 10 m/s wind the lattice reaches upstream (the paper's 10 m/s grids reach -1.6 m)
run -c 'case B; set wind 10; show along_min; show along_max'
check wind_upstream awk '$1 == "along_min" { exit !($2 <= -1.6) } END { }' "$TMP/out"
# and ends one cell past its last contact row, which lies upstream of Delta_par = 0 there
check wind_downstream_end awk '$1 == "along_max" { v = $2; f = 1 } END { exit !(f && v < -0.05 && v > -0.5) }' "$TMP/out"

# tau top (Delta at head-top level, R_max/tan(psi) further along the course): the derived
# lattice moves downstream by that much (within a cell each end); at zero wind it stays
run -c 'case B; set wind 10; set step 0.05; show along_min; show along_max; set tau top;
  show along_min; show along_max; set wind 0; show along_min; set tau rmax; show along_min'
check tau_status [ "$RC" -eq 0 ]
check tau_top_moves awk '$1 == "along_min" { a[++i] = $2 } $1 == "along_max" { b[++j] = $2 }
  END { s = 0.65 / (sin(37 * atan2(1, 1) / 45) / cos(37 * atan2(1, 1) / 45))
        d1 = a[2] - a[1] - s; d2 = b[2] - b[1] - s
        exit !(i == 4 && j == 2 && d1 * d1 < 0.0064 && d2 * d2 < 0.0064 && a[3] == a[4]) }' "$TMP/out"
# a shallow descent (psi 5 deg, shift 7.4 m): the region scanned for the extents moves with it
# (along_max -4.45 m -> 3 m with the RA3 on materials; 3.x before the switch)
run -c 'case B; set angle 5; set speed 12; show along_min; show along_max; set tau top;
  show along_min; show along_max'
check tau_shallow awk '$1 == "along_min" { a[++i] = $2 } $1 == "along_max" { b[++j] = $2 }
  END { s = 0.65 / (sin(5 * atan2(1, 1) / 45) / cos(5 * atan2(1, 1) / 45))
        d1 = a[2] - a[1] - s; d2 = b[2] - b[1] - s
        exit !(i == 2 && j == 2 && d1 * d1 < 0.01 && d2 * d2 < 0.01 && b[2] > 2.5) }' "$TMP/out"

# set: the lattice is bounded (along_max 0.12 rounds out to 0.15) and show says set
run -c 'set format csv; case C; set step 0.1; set along_min -0.1; set along_max 0.12; set cross_max 0.1; show along_max; grid; grid cells'
check set_status [ "$RC" -eq 0 ]
check set_show has "$TMP/out" '^along_max *0\.12 m  (set)$'
check set_note has "$TMP/out" '^# extents set: Q covers only along -0\.1 \.\. 0\.2 m, |cross| <= 0\.1 m'
sed -n '/^# grid of case/,$p' "$TMP/out" | grep -v '^#' | tail -n +2 >"$TMP/set"
check set_lattice awk -F, '{ n++; if ($1 < -0.1001 || $1 > 0.2001 || $2 < -0.1001 || $2 > 0.1001) bad = 1 }
  END { exit !(n == 12 && !bad) }' "$TMP/set"

# the same cells as in the derived grid of the same case and pitch
run -c 'set format csv; case C; set step 0.1; grid; grid cells'
sed -n '/^# grid of case/,$p' "$TMP/out" | grep -v '^#' | tail -n +2 >"$TMP/auto"
check auto_no_note sh -c "! grep -q '^# extents set' '$TMP/out'"
check same_cells sh -c "awk -F, 'NR == FNR { k[\$1 \",\" \$2] = \$0; next } { if (!((\$1 \",\" \$2) in k) || k[\$1 \",\" \$2] != \$0) bad = 1; n++ }
  END { exit !(n == 12 && !bad) }' '$TMP/auto' '$TMP/set'"
# and the derived lattice holds every contact cell with a margin row and column of none
check auto_margin awk -F, -v s=0.1 'NR == 1 { next } { if ($1 > mx) mx = $1; if ($1 < mn || NR == 2) mn = $1; if ($2 > px) px = $2
  if ($3 == 1) { if ($1 > cmx) cmx = $1; if ($1 < cmn || !c) cmn = $1; if ($2 > cpx) cpx = $2; c = 1 } }
  END { exit !(c && mx - cmx > s / 2 && cmn - mn > s / 2 && px - cpx > s / 2) }' "$TMP/auto"

# auto again, and the errors
run -c 'case C; set along_min -0.3; set along_min auto; show along_min'
check auto_again has "$TMP/out" '^along_min .*(derived'
run -c 'case C; set along_min 0.3; set along_max 0.2; grid'
check inverted [ "$RC" -ne 0 ] && check inverted_msg has "$TMP/err" 'along_min 0.3 m is above along_max 0.2 m; accepted'
check inverted_one_line [ "$(lines "$TMP/err")" -eq 1 ]
run -c 'set cross_max -1'
check negative [ "$RC" -ne 0 ] && check negative_msg has "$TMP/err" 'set cross_max: -1 is out of range; accepted: a number in \[0, 100\] m, or auto'
run -c 'set along_min 1e'
check not_number has "$TMP/err" "set along_min: '1e' is not a number"

# case makes them derived again; a saved session replays them
run -c "case C; set along_min -0.2; case B; show along_min"
check case_resets has "$TMP/out" '^along_min .*(derived'
run -c "set along_max 0.35; save session $TMP/s.ses"
check saved grep -q '^set along_max 0\.35$' "$TMP/s.ses"
# a derived extent is the default after reset: a minimal session leaves it out
check saved_auto cond '! grep -q "^set along_min" "$TMP/s.ses"'
run "$TMP/s.ses" -c "show along_min; show along_max"
check saved_replays cond 'has "$TMP/out" "^along_min .*(derived" && has "$TMP/out" "^along_max  *0.35 m  (set)$"' 
finish
