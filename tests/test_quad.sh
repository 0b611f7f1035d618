# test_quad.sh: the example drone that is not the RA3 (sessions/quad.ses, sessions/quad/quad.urm):
# it loads in place of the RA3 (no body called main: its roles say which is the drone), its
# session runs falling and flying impacts, the aim mode hits its shell on the head, a heavier
# quad hurts more; a saved session drops and loads the parts again and replays the same rows;
# loading it beside the RA3 is refused with the way out. It is built on its materials (issue 33):
# its arm hinges are the beam-theory ones of its PA6-GF30 box (closed forms computed here from the
# file's own b, h, t, L, E and strength), its shell's compliance and crush those of its ABS wall,
# and it declares no law of the person: every head pair's law is derived from his scalp layer.
. tests/lib.sh

run sessions/quad.ses
check session_runs cond '[ $RC -eq 0 ] && [ ! -s "$TMP/err" ]'
check no_main cond '! grep -q "body main" sessions/quad/quad.urm && grep -q "^role drone=quad_hub" sessions/quad/quad.urm'
check parts has "$TMP/out" '^quad  *sessions/quad/quad.urm$'
check descent_rows cond '[ "$(grep -c "^ *Q  *\(0\|10\)  " "$TMP/out")" -ge 2 ]'
check grid_q grep -q '^ *Q  *0  .* 0\.1  .*[0-9]\.[0-9]*  ' "$TMP/out"
check shell_on_head grep -q '^ *quad_shell  *head_cranium ' "$TMP/out"
check motor_glancing grep -q '^ *quad_motor[1-4]  *head_cranium ' "$TMP/out"
# the glancing blow 10 cm to the side breaks the arm whose motor struck (PA6-GF30 breaks at M_p)
check arm_breaks grep -q '^# joint quad_arm[1-4] (dof [01]) broke at ' "$TMP/out"
# HIC of the flights: aimed at the centre (1.38 kg), and the last (2 kg): heavier hurts more
awk '/aim head/ {f = 1; next} f && /^ *[-0-9]/ {print $4; f = 0}' "$TMP/out" >"$TMP/hic"
check flights cond '[ "$(lines "$TMP/hic")" -eq 4 ]'
check heavier_more awk 'NR==1{a=$1} END{exit !($1 > a)}' "$TMP/hic"

# built on materials: no law of the person in the file (no law at all, none with the scalp's E)
F=sessions/quad/quad.urm
Q='model drop airbags; model drop ra3; model load sessions/quad/quad.urm'
check no_person_law cond '! grep -q "^law " $F && ! grep -q "E1=2.23e7" $F'
run -c "$Q; model notes"
check notes_run cond '[ $RC -eq 0 ] && [ ! -s "$TMP/err" ]'
check head_from_scalp grep -q "pairs 'qh', quad_shell on head_cranium (layer scalp, material quad_abs): Hertz" "$TMP/out"
check body_from_layers cond 'grep -q "pairs .qb., quad_shell on thorax (layer skin_thorax, material quad_abs): Hertz" "$TMP/out" && ! grep -q "law=tissue" $F'
# the arm hinge: closed forms of the file's box (sheet E.1: I = (b h^3 - b_i h_i^3)/12, Z_p =
# (b h^2 - b_i h_i^2)/4) with its length, E and strength: k = 3EI/L, M_p = yield Z_p, breaking at
# ultimate Z_p; to 1e-5 (the notes print 6 digits)
key() { awk -v k="$2" -v n="$3" '$1 == k && $2 == n { for (i = 3; i <= NF; i++) if (index($i, "'"$1"'=") == 1) { sub(/^[^=]*=/, "", $i); print $i; exit } }' $F; }
B=$(key b section quad_arm_box); H=$(key h section quad_arm_box); T=$(key t section quad_arm_box)
E=$(key E material quad_pa6gf30); SY=$(key yield material quad_pa6gf30); SU=$(key ultimate material quad_pa6gf30)
L=$(awk '$1 == "param" && $2 == "quad_arm_len" {print $3}' $F)
read -r K MP MU <<EOT
$(awk -v b="$B" -v h="$H" -v t="$T" -v E="$E" -v sy="$SY" -v su="$SU" -v L="$L" 'BEGIN {
  bi = b - 2 * t; hi = h - 2 * t; I = (b * h^3 - bi * hi^3) / 12; Zp = (b * h^2 - bi * hi^2) / 4
  printf "%.6g %.6g %.6g\n", 3 * E * I / L, sy * Zp, su * Zp }')
EOT
note() { awk -F'= ' -v w="$1" 'index($0, "restraint '"'"'quad_arm1'"'"' dof 0") && index($0, w) { split($NF, a, " "); print a[1]; exit }' "$TMP/out"; }
near() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b > 0 && (a - b)^2 <= (1e-5 * b)^2) }'; }
check arm_values_read cond '[ -n "$B" ] && [ -n "$H" ] && [ -n "$T" ] && [ -n "$E" ] && [ -n "$SY" ] && [ -n "$SU" ] && [ -n "$L" ]'
check hinge_k near "$(note "hinge k = 3 E I")" "$K"
check hinge_mp near "$(note "hinge M_p")" "$MP"
check hinge_fracture near "$(note "hinge fracture M_u")" "$MU"
check eight_hinges_break cond '[ "$(grep -c "restraint .quad_arm[1-4]. dof [01] .*hinge fracture M_u" "$TMP/out")" -eq 8 ]'
# the shell: Reissner's k_s = 4 E t^2 / (R sqrt(3 (1 - nu^2))) and the crush load pi yield t^2 / 2
# of the file's ABS wall (sheet E.3), to 1e-5
TS=$(key t section quad_shell_wall); RS=$(key R section quad_shell_wall)
EA=$(key E material quad_abs); NA=$(key nu material quad_abs); YA=$(key yield material quad_abs)
read -r KS FC <<EOT
$(awk -v t="$TS" -v R="$RS" -v E="$EA" -v nu="$NA" -v sy="$YA" 'BEGIN { pi = atan2(0, -1)
  printf "%.6g %.6g\n", 4 * E * t^2 / (R * sqrt(3 * (1 - nu^2))), pi * sy * t^2 / 2 }')
EOT
shell_note() { awk -v w="$1" 'index($0, "quad_shell on head_cranium") && index($0, w) { sub(/.*= /, ""); print $1; exit }' "$TMP/out"; }
check shell_k near "$(shell_note "shell k_s")" "$KS"
check shell_crush near "$(shell_note "shell crush F_c")" "$FC"
# falling at 5 m/s on the head, the shell crushes to its contents (its crush is in the run)
run -c "$Q; case Q; set speed 5; impact 0 0"
check shell_crushes grep -q "qh_head_cranium_quad_shell crushed its shell 0.02 m to the bottom" "$TMP/out"

# a session saved with the quad replays it (the RA3's parts dropped, the quad loaded; saved
# outside the model's folder, the model's path is absolute)
run -c "model drop airbags; model drop ra3; model load sessions/quad/quad.urm; case QF; set mass 1.5; save session $TMP/q.ses; set format csv; impact aim head 0.02 0"
grep '^[-0-9]' "$TMP/out" >"$TMP/r1"
check save_drops cond 'grep -q "^model drop airbags$" "$TMP/q.ses" && grep -q "^model drop ra3$" "$TMP/q.ses" && grep -qx "model load .$(pwd -P)/sessions/quad/quad.urm.   # part quad" "$TMP/q.ses" && ! grep -q "^model load \"" "$TMP/q.ses"'
run -c "source $TMP/q.ses; set format csv; impact aim head 0.02 0"
grep '^[-0-9]' "$TMP/out" >"$TMP/r2"
check replay_same cond '[ $RC -eq 0 ] && [ -s "$TMP/r1" ] && cmp -s "$TMP/r1" "$TMP/r2"'
# saved without a 'case' after the swap, the state still names the RA3's case A, which the quad
# has no preset of: the session does not replay 'case A' (it would fail), and replays the state
run -c "model drop airbags; model drop ra3; model load sessions/quad/quad.urm; set mass 1.5; set wind 3; save session $TMP/q2.ses; show; set format csv; impact 0.02 0"
cp "$TMP/out" "$TMP/s1"
check save_nocase cond '! grep -q "^case " "$TMP/q2.ses" && grep -q "^# case A: not a case of the loaded model" "$TMP/q2.ses"'
run -c "source $TMP/q2.ses; show; set format csv; impact 0.02 0"
check replay_nocase cond '[ $RC -eq 0 ] && grep -q "^0.02,0," "$TMP/out" && cmp -s "$TMP/s1" "$TMP/out"'

# beside the RA3: refused, nothing changes; dropping a part others use: refused
run -c 'model load sessions/quad/quad.urm'
check two_drones has "$TMP/err" "role drone: the model has a drone already (body 'main'); one model has one drone: drop the other drone's parts first"
run -c 'model drop ra3'
check drop_needed_part has "$TMP/err" "model drop ra3: refused, the other parts do not compile alone: airbags:"
run -c 'model drop nosuch'
check drop_unknown has "$TMP/err" "model drop: no part 'nosuch'; 'model parts' lists them"
finish
