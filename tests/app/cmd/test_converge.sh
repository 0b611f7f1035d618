# test_converge.sh: converge against the commands it stands for: Q coarse and fine equal the
# grids at the step and at half of it, the shared cells agree exactly, P at the centre with the
# model's dt equals 'impact 0 0', and with dt / 2 equals 'impact 0 0' after 'set dt' to half;
# the live state (step, dt) is back afterwards; dry mode refuses. With a membrane bag, the mesh
# rows: Q at twice bag_mesh equals that grid run by hand, and the report quotes the row; without
# one, a note says the mesh is not refined. A warning when halving the step or doubling the mesh
# moves Q by more than 10 % of the finer result, none within. Coarse grids keep it short.
. tests/lib.sh

col() {
  awk -F, -v k="$2" -v n="$3" '/^#/ { next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next }
    $1 == k { print $(c[n]); exit }' "$1"
}
# converge's row: conv FILE CHECK WHAT COLUMN
conv() {
  awk -F, -v a="$2" -v b="$3" -v n="$4" '/^#/ { next } !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next }
    $1 == a && $2 == b { print $(c[n]); exit }' "$1"
}

# the analytic bag first (set bag_model analytic): no membrane, so converge notes an unrefined
# mesh; the membrane bag, A's default at the switch, comes below with its mesh rows
run -c 'set format csv; case A; set bag_model analytic; set step 0.3; grid'
Q1=$(col "$TMP/out" A q)
run -c 'set format csv; case A; set bag_model analytic; set step 0.15; grid'
Q2=$(col "$TMP/out" A q)
run -c 'set format csv; case A; set bag_model analytic; impact 0 0'
P1=$(col "$TMP/out" 0 p)
run -c 'set format csv; case A; set bag_model analytic; set dt 2.5e-5; impact 0 0'
P2=$(col "$TMP/out" 0 p)
run -c 'set format csv; case A; set bag_model analytic; set step 0.3; converge; show step; show dt'
cp "$TMP/out" "$TMP/c"
check status [ "$RC" -eq 0 ]
check header grep -q '^check,what,dpar,dperp,coarse,fine,change,rel_change$' "$TMP/c"
check q_coarse cond '[ "$(printf %.4f "$(conv "$TMP/c" step q coarse)")" = "$Q1" ]'
check q_fine cond '[ "$(printf %.4f "$(conv "$TMP/c" step q fine)")" = "$Q2" ]'
check shared cond '[ "$(conv "$TMP/c" step shared change)" = 0 ]'
check p_dt cond '[ "$(conv "$TMP/c" dt p_centre coarse)" = "$P1" ] &&
  [ "$(conv "$TMP/c" dt p_centre fine)" = "$P2" ]'
check worst_row cond '[ -n "$(conv "$TMP/c" dt p_worst fine)" ] &&
  [ "$(conv "$TMP/c" dt p_worst dpar)" = "$(conv "$TMP/c" step p_new dpar)" ]'
check restored cond 'grep -q "^step *0.3 m" "$TMP/c" && grep -q "^dt *5e-05 s" "$TMP/c"'
check no_mesh cond 'grep -q "^# mesh: the case has no membrane airbag; the bag.s mesh is not refined" "$TMP/c" &&
  [ -z "$(conv "$TMP/c" mesh q coarse)" ]'

# a membrane bag: the grid again at twice bag_mesh (3 -> 6), same step and dt; its Q must be
# the grid's run by hand with bag_mesh 6 (the same simulation: equal to the printed digits),
# the coarse Q the live grid's; the report quotes the row
run -c 'set format csv; case A; set bag_membrane 1; set bag_mesh 6; set step 0.2; grid'
QM=$(col "$TMP/out" A q)
run -c "set format csv; case A; set bag_membrane 1; set bag_mesh 3; set step 0.2; converge;
  model params bag_mesh; report $TMP/mesh.html"
cp "$TMP/out" "$TMP/m"
check mesh_status [ "$RC" -eq 0 ]
check mesh_q cond '[ "$(printf %.4f "$(conv "$TMP/m" mesh q fine)")" = "$QM" ] &&
  [ "$(conv "$TMP/m" mesh q coarse)" = "$(conv "$TMP/m" step q coarse)" ]'
check mesh_worst cond '[ -n "$(conv "$TMP/m" mesh p_worst dpar)" ] && [ -n "$(conv "$TMP/m" mesh p_worst fine)" ]'
check mesh_note grep -q "^# mesh: the membrane bag.s mesh refined: .* bag_mesh 3 (coarse) and 6 (fine)" "$TMP/m"
check mesh_restored grep -q "^bag_mesh *3 *(set)" "$TMP/m"
check mesh_report cond 'grep -q "doubling the membrane bag.s mesh changes Q by $(conv "$TMP/m" mesh q rel_change)\. These discretisation" "$TMP/mesh.html"'

# a warning when Q moves by more than 10 % of the finer result, with the numbers of the row; none
# within it (case C at 0.1 m moves by about 1 %)
pct() { awk -v r="$(conv "$1" "$2" q rel_change)" 'BEGIN { printf "%.0f", 100 * r }'; }
big() { awk -v r="$(conv "$1" "$2" q rel_change)" 'BEGIN { exit !(r > 0.1 || r < -0.1) }'; }
check warn_step cond 'big "$TMP/c" step && grep -q "^# warning: halving the step moves Q by $(pct "$TMP/c" step) % of the finer result ($(conv "$TMP/c" step q coarse) -> $(conv "$TMP/c" step q fine) m^2), more than 10 %" "$TMP/c"'
check warn_mesh cond 'big "$TMP/m" mesh && grep -q "^# warning: doubling bag_mesh moves Q by $(pct "$TMP/m" mesh) % of the finer result" "$TMP/m" &&
  grep -q "converge: warning: doubling bag_mesh moves Q" "$TMP/mesh.html"'
run -c 'set format csv; case C; set step 0.1; converge'
cp "$TMP/out" "$TMP/q"
[ "$RC" -eq 0 ] || cat "$TMP/err"
check warn_none cond '[ "$RC" -eq 0 ] && [ -n "$(conv "$TMP/q" step q rel_change)" ] && ! big "$TMP/q" step &&
  ! grep -q "warning: halving the step" "$TMP/q"'

run -c 'converge now'
check args cond '[ "$RC" -eq 1 ] && has "$TMP/err" "converge"'

finish
