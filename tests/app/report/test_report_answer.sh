#!/bin/sh
# test_report_answer.sh: the dossier's question and answer as an authority's reviewer reads them
# (coarse 0.3 m grids, a few seconds): the iGRC with its basis (column, dimension, speed, row,
# density), the quantitative iGRC with its density, TLOS and compensation, the M2 line claiming
# only what the factor shows (no "meets criterion #1 at level none"; a deterministic factor
# without a pretend interval), the risk per flight hour with its formula, lambda_system and
# P_shelter and the density up to which the target is met, each number recomputed here from the
# sora table; Table 17's ratio on the basis the calibration declares (A at 0 m/s against the
# full plane of the paper's grid, 0.0581, not the caption's half plane 0.031); another drone's
# question naming what it carries and flagging the RA3's default dimension; SORA 2.5's 250 g
# note and a final GRC beyond 7 (the certified category).
. tests/lib.sh

txt() { tr -d '\n' <"$1"; }
# the sora table's cell of case $1, model $2, column $3 (stdout of a csv run)
sora_cell() { awk -F, -v c="$1" -v m="$2" -v col="$3" '/^case,model,ca,/ { for (i = 1; i <= NF; i++) ix[$i] = i; n = 1; next }
  n && $1 == c && $2 == m { print $ix[col]; exit }' "$TMP/out"; }

run -c "set step 0.3; case A; set p_chute 0.95; set p_bag 0.9; set pop_density 50,500,5000;
  set lambda_system 1e-3; set p_shelter 0.3; set ua_max_speed 20; set format csv; grid; sora;
  report $TMP/a.html"
H="$TMP/a.html"
[ "$RC" -eq 0 ] || cat "$TMP/err"
QA=$(sora_cell A q ca)
QC=$(sora_cell C q ca)
GQ=$(awk -F, '$1 == "A" && $2 == "0" && $6 == "0.3" { print $9; exit }' "$TMP/out")
echo "Q of A mixed $QA, C $QC, grid of A $GQ"
check runs cond '[ "$RC" -eq 0 ] && [ -s "$H" ] && [ -n "$QA" ] && [ -n "$QC" ] && [ -n "$GQ" ]'
check question_carries cond 'txt "$H" | grep -qF "carrying a parachute deploying with probability 0.95 and 1 airbag deploying with probability 0.9 each"'
check igrc_basis cond 'txt "$H" | grep -qF "7; basis: column 3 m / 35 m/s, the rightmost matching both the characteristic dimension 1.3 m (width, length) and the maximum speed 20 m/s (ua_max_speed), row &lt; 50 000 (high-density metropolitan) for the highest density 5000 ppl/km^2"'
check quant_basis cond 'txt "$H" | grep -q "Annex F.s formula at 5000 ppl/km^2, TLOS 1e-06 /h, compensation 0"'
check m2_no_claim cond '! txt "$H" | grep -qF "meets integrity criterion #1 at level" &&
  txt "$H" | grep -qF "that integrity criterion #1 asks for at medium: no M2 credit" &&
  txt "$H" | grep -qF "deterministic, no interval"'
# eq. (1.1) recomputed: 1e-3 /h x 5000e-6 km^-2... x (1 - 0.3) x Q, printed to 4 digits
EA=$(awk -v q="$QA" 'BEGIN { printf "%.4g", 1e-3 * 5000e-6 * 0.7 * q }')
EC=$(awk -v q="$QC" 'BEGIN { printf "%.4g", 1e-3 * 5000e-6 * 0.7 * q }')
LA=$(awk -v q="$QA" 'BEGIN { printf "%.4g", 1e-6 / (1e-3 * 1e-6 * 0.7 * q) }')
echo "eq. (1.1) at 5000: A $EA, C $EC /h; A meets up to $LA ppl/km^2"
check risk_formula cond 'txt "$H" | grep -qF "Risk per flight hour, eq. (1.1) of the paper, E{n_F} = lambda_system x density x (1 - P_shelter) x Q, with lambda_system 0.001 /h, P_shelter 0.3, Q in m^2"'
check risk_q_basis cond 'txt "$H" | grep -qF "inputs, not results; Q: the deterministic grids (the design"'
check risk_values cond 'txt "$H" | grep -qF "case A at 5000 ppl/km^2: $EA per flight hour (Q $QA m^2; meets: yes)" &&
  txt "$H" | grep -qF "case C at 5000 ppl/km^2: $EC per flight hour (Q $QC m^2; meets: no)" &&
  txt "$H" | grep -qF "The target is met up to case A $LA ppl/km^2"'
# Table 17: A at 0 m/s against the full plane of Table 4's grid
RATIO=$(awk -v q="$GQ" 'BEGIN { printf "%.2f", q / 0.0581 }')
ROW=$(txt "$H" | grep -o "<tr><td>A</td><td>0</td><td>[^<]*</td><td>[^<]*</td><td>[^<]*</td><td>[^<]*</td>")
echo "Table 17 row: $ROW (want ratio $RATIO)"
check table17_basis cond 'echo "$ROW" | grep -qF "<td>0.031</td><td>$GQ</td><td>0.0581 (grid, full plane)</td><td>$RATIO</td>"'

# another drone: the quad with a bag on its top, 4 kg, no parachute, dimension not set
cat >"$TMP/top.urm" <<'EOB'
part quad_bags
ellipsoid quad_top_shape body=quad_hub pos=0,0,0.1 size=0.12,0.1,0.06
airbag quad_top geom=quad_top_shape p0=101325 patm=101325 v0=0.003 gamma=1.4 kappa=1.5 \
       thickness=0.06 mu=0.4 v_eps=0.01 targets=head_cranium,head_face,neck,shoulder_l,shoulder_r \
       membrane=1 size=0.12,0.10 depth=0.06 mount=0,0,0.055 rot=1,0,0,180 mesh=4 support=quad_shell
EOB
Q='model drop airbags; model drop ra3; model load sessions/quad/quad.urm'
run -c "$Q; model load $TMP/top.urm; case Q; set mass 4; set step 0.3; set pop_density 50,500,5000;
  set ua_max_speed 22; sora; report $TMP/q.html"
[ "$RC" -eq 0 ] || cat "$TMP/err"
check own_question cond '[ "$RC" -eq 0 ] && txt "$TMP/q.html" | grep -qF "(4 kg; width 1.3 m, length 1.1 m: the workbench" &&
  txt "$TMP/q.html" | grep -qF "not this drone" && txt "$TMP/q.html" | grep -qF "carrying no parachute (area_chute 0) and no deployable airbag" &&
  ! txt "$TMP/q.html" | grep -qF "parachute deployment probability"'
check own_assumptions cond 'txt "$TMP/q.html" | grep -qF "Deployment: none; the drone carries no parachute (area_chute 0)" &&
  txt "$TMP/q.html" | grep -qF "M2 baseline: none (nothing deployable to compare with)"'
check own_answer cond 'txt "$TMP/q.html" | grep -qF "case Q at 50 ppl/km^2: " &&
  txt "$TMP/q.html" | grep -qF "M2: no reduction factor" && txt "$TMP/q.html" | grep -qF "(warning: not the drone"'

# SORA 2.5's note under Table 2: at most 250 g and 25 m/s is iGRC 1 (here the table says 6)
run -c "$Q; case Q; set mass 0.25; set step 0.3; set pop_density 5000; set ua_max_speed 20;
  set ua_dimension 0.3; set format csv; sora"
[ "$RC" -eq 0 ] || cat "$TMP/err"
check small_ua cond '[ "$RC" -eq 0 ] && [ "$(sora_cell none q igrc_sora25)" = 1 ] &&
  grep -qF "igrc_sora25 1: a take-off mass of 0.25 kg (<= 250 g)" "$TMP/out" && grep -q "the table.s cell is 6" "$TMP/out"'
run -c "$Q; case Q; set mass 0.3; set step 0.3; set pop_density 5000; set ua_max_speed 20;
  set ua_dimension 0.3; set format csv; sora"
check not_small cond '[ "$RC" -eq 0 ] && [ "$(sora_cell none q igrc_sora25)" = 6 ] && ! grep -qF "250 g" "$TMP/out"'

# a final GRC above 7 is outside the SORA: the RA3 over assemblies of people
run -c "set step 0.3; case A; set pop_density 60000; set ua_max_speed 20; sora; report $TMP/f.html"
[ "$RC" -eq 0 ] || cat "$TMP/err"
check final_beyond cond '[ "$RC" -eq 0 ] && grep -qF "# final_grc above 7: outside the scope of the SORA" "$TMP/out" &&
  txt "$TMP/f.html" | grep -qF "final GRC 8 (above 7: outside the SORA, the certified category)"'
finish
