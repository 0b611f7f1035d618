# test_ranges.sh: extreme settings get the right reason, never a silent answer (issue 30, item 7).
# A model parameter has a physical range with its reason (param ... range= why=,
# src/core/modellang_stmt.c): 'set' outside it is one line naming the parameter, the range, its
# unit and the reason (src/app/model.c), dist truncates to it and refuses what lies outside
# (risk_dist.c), and a montecarlo draw outside it (the model changed after dist) names its sample
# (cmd_montecarlo.c). Where no range holds a value back: a stance that cannot be balanced names
# the parameters set, in montecarlo also the sample and its drawn values; a run that reaches tmax
# before the drone touched or passed the person fails instead of giving P = 0 (core impact.c); a
# model without a contact pair between drone and person is refused, and a person ellipsoid above
# the head top is noted once (impact_setup.c).
. tests/lib.sh

one_error() { [ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && has "$TMP/err" "$1"; }

# ---- the issue's settings are refused with their range, unit and reason ----
run -c 'set drone_size 10'
check drone_size_10 one_error "^-c:1: set drone_size: 10 is out of range; accepted: 0.25 to 3 (no unit): the RA3 scaled from 0.33 m to 3.9 m across: beyond 3 its shapes lie"
run -c 'set frame_a 100'
check frame_a_100 one_error "^-c:1: set frame_a: 100 m is out of range; accepted: 0.15 to 0.65 m: the main frame reaches the arm roots"
run -c 'set drone_size 1e6'
check drone_size_1e6 one_error "^-c:1: set drone_size: 1e6 is out of range; accepted: 0.25 to 3 (no unit): "
run -c 'set thorax_k 1e300'
check thorax_k_1e300 one_error "^-c:1: set thorax_k: 1e300 N/m is out of range; accepted: 2600 to 260000 N/m: Lobdell's 26 kN/m"
run -c 'set neck_k_flex 1e20'
check neck_k_flex_1e20 one_error "^-c:1: set neck_k_flex: 1e20 N\*m/rad is out of range; accepted: 10 to 1000 N\*m/rad: "
run -c 'set frame_a 65 cm; show frame_a; set thorax_k 260 kN/m; show thorax_k'
check range_ends_taken cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^frame_a  *0.65 m$" &&
  has "$TMP/out" "^thorax_k  *260000 N/m$"'
run -c 'set thorax_k 260.001 kN/m'
check just_beyond one_error "set thorax_k: 260.001 kN/m is out of range"

# every shipped value lies inside its range (the model compiles), every range has a reason
for f in human ra3 airbags; do
  awk '/^param / { p = 1 } p { s = s " " $0 } p && !/\\[ \t]*(#.*)?$/ { print s; s = ""; p = 0 }' \
    "src/models/$f.urm"
done >"$TMP/params"
check ranges_shipped cond '[ "$(grep -c "range=" "$TMP/params")" -ge 30 ] &&
  ! grep "range=" "$TMP/params" | grep -qv "why="'
for n in drone_size frame_a frame_b thorax_k abdomen_k neck_k_flex neck_k_ext spine_k arm_t; do
  grep -q "^ *param $n .*range=.*why=" "$TMP/params" || echo "$n" >>"$TMP/unranged"
done
check issue_params_ranged [ ! -s "$TMP/unranged" ]

# ---- dist: draws truncated to the range, a uniform beyond it refused with the reason ----
run -c 'dist thorax_k uniform 1000 2e6'
check dist_outside one_error "dist thorax_k: uniform LO HI needs LO < HI within the accepted range \[2600, 260000\] (2600 to 260000 N/m: Lobdell"

# ---- a person without ranges (the built-in human with range= and why= taken out) ----
awk '/^param .*\\[ \t]*(#.*)?$/ { sub(/[ \t]*\\.*/, ""); print; skip = 1; next }
     skip { if ($0 !~ /\\[ \t]*$/) skip = 0; next } { print }' src/models/human.urm >"$TMP/human.urm"
check unranged_human cond '! grep -q "range=\|why=" "$TMP/human.urm" && grep -q "^param thorax_k 26 kN/m$" "$TMP/human.urm"'
H="model load $TMP/human.urm"

# a stance that cannot be balanced names the parameter and value set
run -c "$H; set neck_k_flex 1e20; impact 0 0"
check stance_names_param one_error "^-c:1: model: the standing posture cannot be balanced (it falls) with neck_k_flex = 1e+20 N\*m/rad (set)$"

# in montecarlo, also the sample and its drawn values (exact), or the surface's node
run -c "$H; set mc_method exact; set step 0.3; dist neck_k_flex uniform 1e19 1e20; dist wind uniform 0 2; montecarlo 2"
check mc_names_sample one_error "^-c:1: montecarlo: sample 0 (neck_k_flex = [0-9.e+]* N\*m/rad, wind = [0-9.]* m/s): model: the standing posture cannot be balanced (it falls) with neck_k_flex = [0-9.e+]* N\*m/rad (set)$"
# (the surface's check samples run before its grids: without them the first grid fails first)
run -c "$H; set step 0.3; set surface_check 0; dist neck_k_flex uniform 1e19 1e20; montecarlo 2"
check mc_names_node one_error "^-c:1: montecarlo: the response surface's grid 1 of [0-9]* at neck_k_flex = [0-9.e+]* N\*m/rad: model: the standing posture cannot be balanced"
run -c "$H; set step 0.3; dist neck_k_flex uniform 1e19 1e20; montecarlo 2"
check mc_names_check_sample one_error "^-c:1: montecarlo: sample 0 (neck_k_flex = [0-9.e+]* N\*m/rad): model: the standing posture cannot be balanced"

# a draw outside the range: declared, then the model narrowed it
printf 'part narrow\nparam drone_size 1 range=0.5,1.5 why=a narrower design space\n' >"$TMP/narrow.urm"
run -c "dist drone_size uniform 2 3; model load $TMP/narrow.urm; montecarlo 2"
check mc_draw_outside one_error "^-c:1: montecarlo: sample 0 (drone_size = [0-9.]*): drone_size = [0-9.]* is out of range; accepted: 0.5 to 1.5 (no unit): a narrower design space (the model changed since 'dist drone_size' was declared: declare it again)$"

# ---- a run that reaches tmax before the drone touched or passed the person fails ----
run -c 'set format csv; case B; set tmax 0.001 s; impact 0 0'
check tmax_impact one_error "^-c:1: impact 0 0: the simulation failed: the run reached tmax (0.001 s) before the drone touched or passed the person; accepted: a larger tmax"
run -c 'set format csv; case B; set step 0.3; set along_min -0.3; set along_max 0.3; set cross_max 0.3; set tmax 0.001 s; grid'
check tmax_grid_no_q cond '[ "$RC" -eq 1 ] && has "$TMP/err" "grid: cell (0, 0) failed: the run reached tmax (0.001 s)" &&
  grep -q "^B,0,.*,0$" "$TMP/out" && ! grep -q "^B,0,.*,1$" "$TMP/out"'
run -c 'set format csv; case B; impact 0 0'
check tmax_default_touches cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^0,0,1,"'

# ---- a drone with no contact pair with the person is refused when loaded ----
sed -n '/^part ra3/,/^# ---- pairs/p' src/models/ra3.urm >"$TMP/nopairs.urm"
run -c "model drop airbags; model load $TMP/nopairs.urm"
check no_pairs_refused one_error "part 'ra3' does not fit the model: the model has no contact pair between the drone and the person (every impact would pass through the person and give P = 0); accepted: "

# ---- a person ellipsoid above the head top: noted once, impacts still run ----
printf 'part hat\nellipsoid hat body=head pos=0,0,0.3 size=0.05,0.05,0.05\npair hat_frame a=hat b=frame law=tissue\n' >"$TMP/hat.urm"
run -c "case B; model load $TMP/hat.urm; impact 0 0; impact 0.1 0"
check overlap_noted_once cond '[ "$RC" -eq 0 ] && [ "$(grep -c "note: ellipsoid .hat. of the person reaches 0.1[0-9]* m above the top of the head" "$TMP/err")" -eq 1 ]'
run -c 'case B; impact 0 0'
check no_note_shipped cond '[ "$RC" -eq 0 ] && ! has "$TMP/err" "note"'
finish
