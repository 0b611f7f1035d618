# test_quad.sh: the example drone that is not the RA3 (sessions/quad.ses, sessions/quad/quad.urm):
# it loads in place of the RA3 (no body called main: its roles say which is the drone), its
# session runs falling and flying impacts, the aim mode hits its shell on the head, a heavier
# quad hurts more; a saved session drops and loads the parts again and replays the same rows;
# loading it beside the RA3 is refused with the way out.
. tests/lib.sh

run sessions/quad.ses
check session_runs cond '[ $RC -eq 0 ] && [ ! -s "$TMP/err" ]'
check no_main cond '! grep -q "body main" sessions/quad/quad.urm && grep -q "^role drone=quad_hub" sessions/quad/quad.urm'
check parts has "$TMP/out" '^quad  *sessions/quad/quad.urm$'
check descent_rows cond '[ "$(grep -c "^ *Q  *\(0\|10\)  " "$TMP/out")" -ge 2 ]'
check grid_q grep -q '^ *Q  *0  .* 0\.1  .*[0-9]\.[0-9]*  ' "$TMP/out"
check shell_on_head grep -q '^ *quad_shell  *head_cranium ' "$TMP/out"
check motor_glancing grep -q '^ *quad_motor[1-4]  *head_cranium ' "$TMP/out"
# HIC of the flights: aimed at the centre (1.38 kg), and the last (2 kg): heavier hurts more
awk '/aim head/ {getline; getline; print $4}' "$TMP/out" >"$TMP/hic"
check flights cond '[ "$(lines "$TMP/hic")" -eq 4 ]'
check heavier_more awk 'NR==1{a=$1} END{exit !($1 > a)}' "$TMP/hic"

# a session saved with the quad replays it (the RA3's parts dropped, the quad loaded)
run -c "model drop airbags; model drop ra3; model load sessions/quad/quad.urm; case QF; set mass 1.5; save session $TMP/q.ses; set format csv; impact aim head 0.02 0"
grep '^[-0-9]' "$TMP/out" >"$TMP/r1"
check save_drops cond 'grep -q "^model drop airbags$" "$TMP/q.ses" && grep -q "^model drop ra3$" "$TMP/q.ses" && grep -qx "model load .sessions/quad/quad.urm.   # part quad" "$TMP/q.ses" && ! grep -q "^model load \"" "$TMP/q.ses"'
run -c "source $TMP/q.ses; set format csv; impact aim head 0.02 0"
grep '^[-0-9]' "$TMP/out" >"$TMP/r2"
check replay_same cond '[ $RC -eq 0 ] && [ -s "$TMP/r1" ] && cmp -s "$TMP/r1" "$TMP/r2"'

# beside the RA3: refused, nothing changes; dropping a part others use: refused
run -c 'model load sessions/quad/quad.urm'
check two_drones has "$TMP/err" "role drone: the model has a drone already (body 'main'); one model has one drone: drop the other drone's parts first"
run -c 'model drop ra3'
check drop_needed_part has "$TMP/err" "model drop ra3: refused, the other parts do not compile alone: airbags:"
run -c 'model drop nosuch'
check drop_unknown has "$TMP/err" "model drop: no part 'nosuch'; 'model parts' lists them"
finish
