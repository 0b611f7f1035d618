# test_cmd_impact.sh: what the last impact tells of a hinge that broke (src/app/cmd/cmd_impact.c):
# the example quadcopter with one arm a weak plastic tube whose hinge has fracture=1; at the
# centre its arm breaks in the strike, 'contacts' notes when, the hinge sensor's second channel
# in 'history' says the same time, and the released arm (its tube or its motor) strikes the person
# after it. The drone without fracture (its restraints' fracture=1 taken out) notes nothing.
. tests/lib.sh

Q=sessions/quad/quad.urm
check quad_model_there test -f "$Q"
# arm 1's restraints replaced by a tube hinge of a weak plastic (ultimate 1 MPa) that breaks
awk '/^restraint quad_arm1 / {skip = 2} skip > 0 {skip--; next} {print}
     /^role drone=/ {
       print "material brittle E=2.3e9 nu=0.37 density=1050 yield=5e5 ultimate=1e6"
       print "section arm_s shape=tube D=0.025 t=0.002"
       print "restraint quad_arm1 dof=0 material=brittle section=arm_s length=0.12 fracture=1 c=0.3"
       print "restraint quad_arm1 dof=1 material=brittle section=arm_s length=0.12 fracture=1 c=0.3"
       print "sensor quad_arm1_h type=hinge obj=quad_arm1 dof=0"
     }' "$Q" >"$TMP/q.urm"
check weak_arm_written cond '[ $(grep -c "^restraint quad_arm1 .*fracture=1" "$TMP/q.urm") -eq 2 ] && [ $(grep -c "^restraint quad_arm1 " "$TMP/q.urm") -eq 2 ]'

L="model drop airbags; model drop ra3; model load $TMP/q.urm; case Q"
run -c "$L; impact 0 0; contacts"
check contacts_runs cond '[ $RC -eq 0 ]'
check notes_break grep -q '^# joint quad_arm1 (dof 0) broke at [0-9.]* s after a plastic set of .*released' "$TMP/out"
tb=$(sed -n 's/^# joint quad_arm1 (dof 0) broke at \([0-9.]*\) s.*/\1/p' "$TMP/out")
# the freed arm (its tube or its motor) touches the person after the break
check arm_strikes_after awk -v tb="$tb" '($1 == "quad_arm1_tube" || $1 == "quad_motor1") && $3 + 0 > tb + 0 {n++} END {exit !(tb > 0 && n > 0)}' "$TMP/out"

# the hinge sensor's time channel: 0 while intact, then the break time (as the note rounds it)
run -c "$L; set format csv; impact 0 0; history quad_arm1_h_v"
check history_runs cond '[ $RC -eq 0 ]'
check history_says_when awk -F, -v tb="$tb" '$1 ~ /^[0-9.e-]+$/ && $2 + 0 > 0 {t = $2; n++}
  $1 ~ /^[0-9.e-]+$/ && $2 + 0 == 0 {z++}
  END {exit !(n > 0 && z > 0 && (t - tb)^2 < 1e-8)}' "$TMP/out"

# the drone without fracture: its arms do not break, nothing noted
sed 's/ fracture=1//' "$Q" >"$TMP/q0.urm"
check no_fracture_written cond '! grep -v "^ *#" "$TMP/q0.urm" | grep -q "fracture=1"'
run -c "model drop airbags; model drop ra3; model load $TMP/q0.urm; case Q; impact 0 0; contacts"
check unbroken_no_note cond '[ $RC -eq 0 ] && ! grep -q "broke at" "$TMP/out"'
finish
