# test_design.sh: each design parameter's path into the models (src/app/case/design.c, preset.c,
# cmd_aim.c): at a fixed speed and angle, 'set mass' changes the multibody drone (doubling it
# raises HIC) and 'show mass' says so; drone_size, arm_k, foam_t and bag_p0 change the impact;
# width and area_chute do not (show marks them) while area_chute changes the derived speed; a
# saved session replays the design; presets are the model's; horizontal flights are run by aim
# and refused as offsets; a drone model without a 'main' body works through its roles.
. tests/lib.sh

# the HIC15 of each impact row of a CSV output, one per line
hics() { awk -F, '/^[-0-9]/ {print $4}' "$1"; }
B='set format csv; case B; set speed 7.48; set angle 90'

# mass: the multibody drone follows; doubling the mass raises HIC; the first row is the RA3
run -c "$B; impact 0 0; set mass 10; impact 0 0; set mass 20; impact 0 0; show mass; model params"
hics "$TMP/out" >"$TMP/h"
check mass_runs cond '[ $RC -eq 0 ] && [ "$(lines "$TMP/h")" -eq 3 ]'
check mass_changes_hic cond '[ "$(sed -n 1p "$TMP/h")" != "$(sed -n 2p "$TMP/h")" ]'
check mass_doubling_raises_hic awk 'NR==2{a=$1} NR==3{b=$1} END{exit !(b > a)}' "$TMP/h"
check show_mass_multibody has "$TMP/out" '^mass  *20 kg  (multibody drone: 20 kg)'
check drone_mass_set has "$TMP/out" '^drone_mass  *20 kg  (set)'

# the same mass again changes nothing (a saved session sets every setting)
run -c "$B; set mass 15; model params"
check same_mass_no_override has "$TMP/out" '^drone_mass .*kg  (model)'

# drone_size, arm_t (an arm on the head: its tube wall sets the hinge), foam_t (the cargo box), bag_p0 (case A's bag)
run -c "$B; impact 0 0; set drone_size 1.2; impact 0 0"
check drone_size_changes_hic cond '[ "$(hics "$TMP/out" | sort -u | wc -l)" -eq 2 ]'
run -c "$B; impact 0 0.6; set arm_t 0.5 mm; impact 0 0.6"
check arm_t_changes_hic cond '[ "$(hics "$TMP/out" | sort -u | wc -l)" -eq 2 ]'
run -c "$B; impact 0 0; set foam_t 0.05; impact 0 0"
check foam_t_changes_hic cond '[ "$(hics "$TMP/out" | sort -u | wc -l)" -eq 2 ]'
run -c "set format csv; case A; set speed 7.48; set angle 90; impact 0 0; set bag_p0 1.3 atm; impact 0 0"
check bag_p0_changes_hic cond '[ "$(hics "$TMP/out" | sort -u | wc -l)" -eq 2 ]'

# width and area_chute do not reach the multibody model (marked), area_chute the descent
run -c "$B; impact 0 0; set width 2; set length 2; set area_chute 3; impact 0 0; show width; show area_chute"
check width_not_multibody cond '[ "$(hics "$TMP/out" | sort -u | wc -l)" -eq 1 ]'
check show_marks_width has "$TMP/out" '^width .*(not used by the multibody model)'
check show_marks_chute has "$TMP/out" '^area_chute .*(not used by the multibody model)'
run -c 'case B; show speed; set area_chute 3; show speed'
check chute_changes_speed cond '[ "$(grep -c "^speed" "$TMP/out")" -eq 2 ] && [ "$(grep "^speed" "$TMP/out" | sort -u | wc -l)" -eq 2 ]'

# a saved session replays the design: the same row
run -c "$B; set mass 11; set drone_size 0.9; save session $TMP/d.ses; impact 0.1 0"
sed -n '/^[-0-9]/p' "$TMP/out" >"$TMP/row1"
run -c "source $TMP/d.ses; set format csv; impact 0.1 0"
sed -n '/^[-0-9]/p' "$TMP/out" >"$TMP/row2"
check session_replays_design cond '[ $RC -eq 0 ] && [ -s "$TMP/row1" ] && cmp -s "$TMP/row1" "$TMP/row2"'

# the speed vector set directly: speed and angle both set from it (3-4-5), and a flight
run -c 'set velocity 3,4; show speed; show angle; set velocity 8,0; show angle'
check velocity_speed has "$TMP/out" '^speed  *5 m/s  (set)$'
check velocity_angle has "$TMP/out" '^angle  *53.1301 deg  (set)$'
check velocity_level has "$TMP/out" '^angle  *0 deg  (set)$'
run -c "set format csv; case B; set velocity 8,0; impact aim head 0 0.05; set speed 8; set angle 0; impact aim head 0 0.05"
check velocity_same_impact cond '[ "$(grep -c "^0,0.05," "$TMP/out")" -eq 2 ] && [ "$(grep "^0,0.05," "$TMP/out" | sort -u | wc -l)" -eq 1 ]'
run -c 'set velocity -1,2'
check velocity_refused has "$TMP/err" "set velocity: '-1,2' is not accepted; accepted: VH,VD (the horizontal speed along the course and the downward speed, each >= 0) in m/s, or followed by km/h or kt"

# the cases are the model's presets; an unknown one lists them
run -c 'case Z'
check case_unknown_lists_presets has "$TMP/err" "unknown case 'Z'; accepted: A, B, C, A1 or A2"

# horizontal flight: aim runs it, an offset or a grid is refused with the way out
run -c "set format csv; case B; set angle 0; set speed 8; impact aim head 0 0; contacts"
check aim_horizontal_head cond '[ $RC -eq 0 ] && grep -q "^[a-z_0-9]*,head_cranium," "$TMP/out"'
check aim_contacts_note has "$TMP/out" '^# impact aimed at the head, up and side (0, 0) m: '

# level flight takes a declared cruise speed: the descent's derived speed (C's 39.7 m/s fall)
# is refused with the way out; declared in km/h it runs
run -c 'case C; set angle 0; impact aim head 0 0'
check level_needs_speed cond '[ $RC -eq 1 ] && has "$TMP/err" "impact aim: a flight at angle 0 deg needs a declared cruise speed; the derived 39.7 m/s is the descent.s fall" &&
  has "$TMP/err" "set speed V"'
run -c 'case C; set angle 0; set speed 54 km/h; set format csv; impact aim head 0 0'
check level_declared cond '[ $RC -eq 0 ] && grep -q "^0,0," "$TMP/out"'
run -c 'case C; set angle 30; set format csv; impact aim head 0 0'
check descent_speed_at_angle cond '[ $RC -eq 0 ]'

run -c 'case B; set angle 0; impact 0 0'
check offset_refused_at_angle0 has "$TMP/err" "angle 0 deg: an offset Delta needs a descent.*impact aim head UP SIDE"
run -c 'case B; set angle 0; set step 0.3; grid'
check grid_refused_at_angle0 cond '[ $RC -ne 0 ] && grep -q "needs a descent" "$TMP/err"'
run -c 'impact aim nose 0 0'
check aim_usage has "$TMP/err" "impact aim: usage: impact aim head UP SIDE"
run -c 'impact aim head 0 x'
check aim_number has "$TMP/err" "impact aim: 'x' is not a number"

finish
