# test_risk_branch.sh: which airbags risk, sora and montecarlo treat as deployment devices
# (src/app/cmd/risk/risk_branch.c). An airbag is a device when a parameter bag_bottom or
# bag_front switches it (enable=$bag_bottom); an airbag of one's own drone switched by another
# parameter (or by none) is fitted in every branch, branch none included, and p_bag does not
# apply to it: each of the three says so in a note naming it, where before risk said only
# "nothing to deploy". The same bag switched by bag_bottom is a device (branches with and
# without it, no note), and the RA3's cases get no note. The example quadcopter with a small
# analytic side bag, 0.3 m grids: a few seconds.
. tests/lib.sh

QUAD=$(pwd)/sessions/quad/quad.urm
# a side bag on the quad's hub, switched by SWITCH (sb_on, or bag_bottom)
sidebag() {
  cat <<EOF
part sidebag
param $1 1
ellipsoid sb_shape body=quad_hub pos=0,0.15,0 size=0.10,0.06,0.06 enable=\$$1
airbag side_bag geom=sb_shape p0=106391 patm=101325 v0=0.004 gamma=1.4 kappa=1.7 \\
   thickness=0.06 fabric_k=2000 fabric_c=20 mu=0.4 v_eps=0.01 \\
   targets=head_cranium,head_face,neck,thorax enable=\$$1
sensor sb_p type=airbag obj=side_bag enable=\$$1
EOF
}
sidebag sb_on >"$TMP/sb_on.urm"
sidebag bag_bottom >"$TMP/bag_bottom.urm"
LOAD="model drop airbags; model drop ra3; model load $QUAD; case Q; set step 0.3"
NOTE="fitted in every branch, not a device: airbag side_bag (no parameter bag_bottom or bag_front"

# no parachute: risk's one branch keeps the bag; sora and montecarlo say the same
run -c "$LOAD; model load $TMP/sb_on.urm; set p_bag 0.5; set format csv; grid; risk; sora; \
  dist wind uniform 0 1; set mc_method exact; montecarlo 2"
check own_bag_status [ "$RC" -eq 0 ]
check own_bag_risk_note cond '[ "$(grep -c "^# $NOTE" "$TMP/out")" -ge 2 ]'
check own_bag_mc_note grep -q "^# inputs: .*; $NOTE" "$TMP/out"
# the note's claim: branch none is the grid with the bag fitted (grid prints Q to 4 decimals)
QG=$(awk -F, '$1 == "Q" && NF >= 11 { print $9; exit }' "$TMP/out")
QN=$(awk -F, '$1 == "none" && NF == 3 { print $3; exit }' "$TMP/out")
check own_bag_none_is_fitted cond '[ -n "$QG" ] && [ -n "$QN" ] &&
  awk -v a="$QG" -v b="$QN" "BEGIN { d = a - b; exit !(d <= 5e-5 && d >= -5e-5) }"'

# with a parachute: the note follows the deployment notes
run -c "$LOAD; model load $TMP/sb_on.urm; set area_chute 1; set p_bag 0.5; risk"
check own_bag_chute_note cond '[ "$RC" -eq 0 ] && grep -q "^# $NOTE" "$TMP/out" &&
  grep -q "^# deployment: .*(each of 0 airbags)" "$TMP/out"'

# the same bag switched by bag_bottom is a device: branches with and without it, no note
run -c "$LOAD; model load $TMP/bag_bottom.urm; set area_chute 1; set p_bag 0.5; risk"
check device_bag cond '[ "$RC" -eq 0 ] && grep -q "^chute+bag_bottom " "$TMP/out" &&
  grep -q "(each of 1 airbag)" "$TMP/out" && ! grep -q "not a device" "$TMP/out"'

# the name of the branch without devices: none, in sora's rows, risk's, the notes and the grid
run -c "$LOAD; model load $TMP/bag_bottom.urm; set area_chute 1; set p_bag 0.5; set format csv;
  sora; risk; grid show"
check none_sora_rows cond '[ "$RC" -eq 0 ] && grep -q "^none,q," "$TMP/out" &&
  grep -q "^none,annex_f," "$TMP/out" && ! grep -q "^C," "$TMP/out"'
check none_notes cond 'grep -q "no parachute, no airbag: branch none" "$TMP/out" &&
  grep -q "the drone falls without them at" "$TMP/out" && ! grep -q "case C" "$TMP/out"'
check none_last_grid grep -q "^case none, wind 0 m/s" "$TMP/out"
# the RA3 keeps its case C
run -c "set step 0.3; case B; set p_chute 0.9; set format csv; sora; grid show"
check ra3_case_c cond '[ "$RC" -eq 0 ] && grep -q "^C,q," "$TMP/out" &&
  grep -q "no parachute, no airbag: case C" "$TMP/out" && grep -q "^case C, wind 0 m/s" "$TMP/out"'

# the RA3: its bags are devices
run -c "set step 0.3; case A2; set bag_model analytic; set p_bag 0.9; risk"
check ra3_no_note cond '[ "$RC" -eq 0 ] && grep -q "^chute+bag_bottom+bag_front " "$TMP/out" &&
  ! grep -q "not a device" "$TMP/out"'
finish
