# test_model.sh: the model set as a session changes it (src/app/case/model.c): 'model load' is
# transactional (a part that leaves the model unable to run impacts, or that breaks another part
# in some case, is refused naming the loaded file and line, and the session is exactly as
# before); a model parameter must hold in every case (an airbag's pressure set in case B);
# the simulation options have bounds that say why (tmax, settle_dt, dt); impossible inertias are
# refused; the largest model within the limits loads (its time printed), beyond them one line;
# Ctrl-C stops a load that waits (issue 24, items 3, 5 and 8)
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
fails_with() { [ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && has "$TMP/err" "$1"; }
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }

# ---- a drone part without bodies: refused in any case, the file and line named (the first
# thing missing: in case B the drone, in case A the frame the bag's shape names) ----
printf '# no drone here\npart ra3\nparam xx 1\n' >"$TMP/nobodies.urm"
run -c "case B; model load $TMP/nobodies.urm"
check nobodies_case_b fails_with \
  "^-c:1: model load: .*/nobodies.urm:2: part 'ra3' does not fit the model: the model declares no drone: add 'role drone=BODY'"
run -c "case A; model load $TMP/nobodies.urm"
check nobodies_case_a fails_with \
  "^-c:1: model load: .*/nobodies.urm:2: part 'ra3' does not fit the model: airbags:[0-9]*: .*unknown parameter 'frame_a'"

# interactively: the session is exactly as it was (parts, parameters, the last impact)
printf 'case B\nimpact 0 0\nmodel parts\nshow\nmodel load %s\nmodel parts\nshow\ncontacts\nimpact 0 0\nset bag_p0 -1\nsave session %s/s.ses\n' \
  "$TMP/nobodies.urm" "$TMP" >"$TMP/in"
run_in "$TMP/in" -i
awk '/^uasimpact\[/{next} /^human /{n++} n==1{print >f1} n==2{print >f2}' f1="$TMP/a1" f2="$TMP/a2" "$TMP/out"
check nobodies_state_kept cond '[ -s "$TMP/a1" ] && head -n "$(wc -l <"$TMP/a1")" "$TMP/a2" |
  cmp -s - "$TMP/a1" && has "$TMP/a2" "^ra3  *built-in$"'
check nobodies_impact_kept cond 'has "$TMP/out" "^# impact at (0, 0) m: [0-9]* pair"'
check nobodies_one_error cond '[ "$(grep -c "^error: " "$TMP/err")" -eq 2 ]'
run "$TMP/s.ses" -c 'show case; impact 0 0'
check nobodies_session_replays cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^case  *B$"'

# a part that is fine is still loaded, and a part with an error of its own names its line
sed -n '/^part ra3/,$p' src/models/ra3.urm >"$TMP/ra3.urm"
run -c "model load $TMP/ra3.urm; model parts"
check good_part_loads cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^ra3  *.*ra3.urm$"'
printf 'part extra\nparam a 1\nbody b parent=nobody joint=fixed pos=0,0,0 mass=1\n' >"$TMP/bad.urm"
run -c "model load $TMP/bad.urm"
check own_error_line fails_with "^-c:1: .*/bad.urm:3: .*dangling reference to body 'nobody'"

# ---- a model parameter must hold in every case: bag_p0 -1 is refused in case B ----
run -c 'case B; set bag_p0 -1'
check bag_p0_case_b fails_with \
  "set bag_p0: refused, the model does not accept it: model: in case A: airbags:[0-9]*: airbag 'bag_bottom': p0 must be > 0"
run -c 'case B; set bag_p0 1.2 atm; show bag_p0'
check bag_p0_good cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^bag_p0  *121590 Pa$"'

# ---- simulation options: bounds that say why ----
run -c 'set tmax 1e9'
check tmax_bound fails_with "set tmax: refused.*tmax 1e+09 s is out of range; accepted: (0, 1\] s (an impact is over"
run -c 'set settle_dt 1e-5'
check settle_dt_bound fails_with "settle_dt 1e-05 s is out of range; accepted: \[dt, 0.01\] s = \[5e-05, 0.01\] s (the stance"
run -c 'set dt 0.01'
check dt_bound fails_with "dt 0.01 s is out of range; accepted: (0, 1e-3\] s (a contact pulse"
run -c 'set dt 1e-6'
check steps_bound fails_with "tmax/dt = 4e+05 steps; accepted: at most 1e5 steps" # case A: tmax 0.4 s
run -c 'set dt 1e-5; set settle_dt 1e-5; show settle_dt'
check settle_dt_in_order cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^settle_dt  *1e-05"'

# ---- impossible inertias ----
printf 'part extra\nbody rod parent=world joint=free pos=0,0,9 mass=1 inertia=1,1,3\n' >"$TMP/i.urm"
run -c "model load $TMP/i.urm"
check inertia_triangle fails_with "i.urm:2: body 'rod': inertia is not that of a real body: a principal moment exceeds"
printf 'part extra\nbody rod parent=world joint=free pos=0,0,9 mass=1 inertia=1,1,2\n' >"$TMP/i2.urm"
run -c "model load $TMP/i2.urm"
check inertia_thin_rod_ok [ "$RC" -eq 0 ]

# ---- size: the largest model within the limits loads (its time printed); beyond, one line ----
awk 'BEGIN { print "part big"; print "body b0 parent=world joint=free pos=0,0,5 mass=1 inertia=1,1,1"
  for (i = 1; i < 900; i++) printf "body b%d parent=b%d joint=revolute pos=0,0,0.01 mass=1 axis=1,0,0\n", i, i - 1
  for (i = 0; i < 1800; i++) printf "ellipsoid e%d body=b%d pos=0,0,0 size=0.01,0.01,0.01\n", i, i % 900
  for (i = 0; i < 3500; i++) printf "param p%d %d\n", i, i }' >"$TMP/big.urm"
t0=$(now_ms); run -c "model load $TMP/big.urm"; MS=$(( $(now_ms) - t0 ))
echo "  (a model of 900 bodies, 1800 ellipsoids, 3500 parameters more: $MS ms)"
# (its time is printed, not held: speed is a benchmark, never a test; it failed at 15 s beside
# three test suites on 2 cores)
check big_model_loads [ "$RC" -eq 0 ]
awk 'BEGIN { print "part big"; print "body b0 parent=world joint=free pos=0,0,5 mass=1 inertia=1,1,1"
  for (i = 1; i < 100000; i++) printf "body b%d parent=b%d joint=revolute pos=0,0,0.01 mass=1 axis=1,0,0\n", i, i - 1 }' \
  >"$TMP/huge.urm"
t0=$(now_ms); run -c "model load $TMP/huge.urm"; MS=$(( $(now_ms) - t0 ))
echo "  (a model of 100000 bodies refused after $MS ms)"
check huge_model_refused fails_with "huge.urm:[0-9]*: more than 1000 bodies in the model; accepted: at most 1000 (uasimpact-model(5), LIMITS)"
awk 'BEGIN { for (i = 0; i < 300; i++) printf "part p%d\n", i }' >"$TMP/parts.urm"
run -c "model load $TMP/parts.urm"
check too_many_parts fails_with "parts.urm:257: more than 256 parts"

# ---- Ctrl-C while a load waits (a FIFO nobody writes) ----
# the signal is sent once the program waits in the kernel (waiting_in, tests/lib.sh), not after
# a fixed time: starting up compiles the default case, whose membrane airbag is inflated first
mkfifo "$TMP/fifo"
"$U" -c "model load $TMP/fifo" >"$TMP/out" 2>"$TMP/err" & PID=$!
waiting_in $PID 'wait_for_partner|fifo_open'
t0=$(now_ms); kill -INT $PID; wait $PID; RC=$?; MS=$(( $(now_ms) - t0 ))
# within 1 s, as the other interrupt checks (a hang still fails; 200 ms failed on a loaded machine)
check load_interrupted cond '[ "$RC" -eq 130 ] && [ "$MS" -lt 1000 ] &&
  has "$TMP/err" "model load: interrupted (Ctrl-C) while opening"'
# ... and while it reads one that is written slowly
( printf 'part extra\n'; sleep 5; printf 'param a 1\n' ) >"$TMP/fifo" &
W=$!
"$U" -c "model load $TMP/fifo" >"$TMP/out" 2>"$TMP/err" & PID=$!
waiting_in $PID '(anon_)?pipe_read|pipe_wait|wait_woken'
t0=$(now_ms); kill -INT $PID; wait $PID; RC=$?; MS=$(( $(now_ms) - t0 ))
kill $W 2>/dev/null; wait $W 2>/dev/null
check read_interrupted cond '[ "$RC" -eq 130 ] && [ "$MS" -lt 1000 ] &&
  has "$TMP/err" "model load: interrupted (Ctrl-C) while reading"'

# ---- what the model language derives (issue 33): 'model notes', 'model params', 'show' ----
# a part with a hinge from beam theory (carbon tube, Table B1's 59.3 MPa) and an ABS shell pod
# (2 mm, R 0.1 m, yield 40 MPa) on the scalp; each value against its closed form (awk)
cat >"$TMP/derive.urm" <<'EOF'
part derive
material abs E=2.3e9 nu=0.4 density=1050 yield=4e7
material cf E=5.48e10 nu=0.34 density=1600 yield=5.93e7 ultimate=6e8
section wall shape=shell t=0.002 R=0.1 h=0.02
section arm_t shape=tube D=0.03 t=0.002
body boom parent=main joint=revolute pos=0,0,0.05 mass=0.1 inertia=1e-4,1e-4,1e-4
restraint boom dof=0 material=cf section=arm_t length=0.41 fracture=1
ellipsoid pod body=main pos=0,0,-0.1 size=0.05,0.05,0.03 material=abs section=wall
pair podh a=head_cranium b=pod
EOF
# the number after "... = " on the first derived line matching $2, against $3 to 1e-5
derived_is() {
  v=$(grep "^derived .*$2" "$1" | sed 's/.* = \([-0-9.e+]*\) .*/\1/' | head -n 1)
  awk -v v="$v" -v w="$3" 'BEGIN { exit !(v != "" && (v - w) ^ 2 <= (1e-5 * w) ^ 2) }'
}
PI=3.141592653589793
run -c "model load $TMP/derive.urm; model notes"
check derived_hinge_k cond '[ "$RC" -eq 0 ] && derived_is "$TMP/out" "boom.*hinge k = 3 E I / L" \
  "$(awk -v p=$PI "BEGIN { print 3 * 5.48e10 * p * (0.03^4 - 0.026^4) / 64 / 0.41 }")"'
check derived_hinge_mp cond 'derived_is "$TMP/out" "boom.*hinge M_p = sigma_y Z_p" \
  "$(awk "BEGIN { print 5.93e7 * (0.03^3 - 0.026^3) / 6 }")"'
check derived_hertz cond 'derived_is "$TMP/out" "podh.*Hertz E\*" \
  "$(awk "BEGIN { print 1 / ((1 - 0.29^2) / 2.23e7 + (1 - 0.4^2) / 2.3e9) }")" &&
  derived_is "$TMP/out" "podh.*Hertz R = " "$(awk "BEGIN { print 1 / (1 / 0.0875 + 1 / 0.1) }")"'
check derived_shell cond 'derived_is "$TMP/out" "podh.*shell k_s" \
  "$(awk "BEGIN { print 4 * 2.3e9 * 0.002^2 / (0.1 * sqrt(3 * (1 - 0.16))) }")" &&
  derived_is "$TMP/out" "podh.*shell crush F_c" "$(awk -v p=$PI "BEGIN { print 2 * p * 40 }")" &&
  has "$TMP/out" "bottoming after 0.02 m of crush (h)"'
check notes_kept cond 'has "$TMP/out" "^note  *pairs .*overrides the layer"'
# the full listings carry them, marked derived; a prefix, which names parameters, does not
run -c "model load $TMP/derive.urm; model params"
check params_derived cond '[ "$(grep -c "^# derived, .*\(boom\|podh\)" "$TMP/out")" -eq 9 ]'
run -c "model load $TMP/derive.urm; show"
check show_derived cond '[ "$(grep -c "^# derived, .*\(boom\|podh\)" "$TMP/out")" -eq 9 ]'
run -c "model load $TMP/derive.urm; model params arm"
check prefix_no_derived cond '[ "$RC" -eq 0 ] && ! has "$TMP/out" "derived"'
run -c "model load $TMP/derive.urm; set format json; model notes"
check notes_json cond 'has "$TMP/out" "\"kind\":\"derived\",\"text\":\"pair .podh., pod on head_cranium"'
# no yield: the shell stays elastic, and says so
sed 's/ yield=4e7//' "$TMP/derive.urm" >"$TMP/derive2.urm"
run -c "model load $TMP/derive2.urm; model notes"
check no_yield_no_crush cond 'has "$TMP/out" "podh.*shell crush none (material abs gives no yield)" &&
  ! has "$TMP/out" "F_c ="'
# the built-in RA3's foam rests on a backing derived from the person's layers: on the head the
# scalp on carbon, flat, at the head's radius (4/3 E* sqrt(R)); on the thorax at its curvature;
# on the rest of his body his soft-tissue law's loading curve. Its frame and arms meet the head
# through laws derived from the scalp layer (no law of their own since the switch to the RA3 on
# materials) and name the person's tissue law on the thorax: overrides, noted
run -c "model notes"
check builtin_backing_head cond '[ "$RC" -eq 0 ] && derived_is "$TMP/out" \
  "cg., foam on layer scalp: backing K" \
  "$(awk "BEGIN { print 4 / 3 / ((1 - 0.29^2) / 2.23e7 + (1 - 0.34^2) / 5.48e10) * sqrt(0.0875) }")"'
check builtin_backing_thorax has "$TMP/out" \
  "foam on layer skin_thorax: backing K = 4/3 E\* sqrt(R), E\* 250783 Pa .*R the curvature of the person.s part"
check builtin_backing_law cond '[ "$(grep -c "foam on layer soft_body: backing beyond the lock strain = the loading curve of law tissue" "$TMP/out")" -eq 1 ]'
check builtin_overrides cond 'has "$TMP/out" "^note  *pairs .fb.: its declared law .tissue. overrides the layer of .thorax." &&
  has "$TMP/out" "^note  *pairs .ab.: its declared law .tissue. overrides the layer of .thorax." &&
  has "$TMP/out" "pairs .fh., frame on head_cranium (layer scalp, material carbon): Hertz" &&
  [ "$(grep -c "^note" "$TMP/out")" -eq 2 ]'
# no drone file copies the person's soft-tissue law or rests its foam on a scalp law of its own
check builtin_no_person_law cond '! grep -q "tissue_load\|backing=frame_head" src/models/ra3.urm sessions/quad/quad.urm'

# ---- a parameter whose default is another (param pod_a $frame_a m, in a part of its own): it
# follows frame_a, also after 'set frame_a', until it is set; show and model params say so while
# it follows ----
printf 'part pod\nparam pod_a $frame_a m \\\n  range=0.1,0.65 why=a pod under the frame\nparam pod_b $frame_b m\n' >"$TMP/pod.urm"
L="model load $TMP/pod.urm"
FA=$("$UASIMPACT" -c 'show frame_a' | awk '{ print $2 }')
F='(derived: frame_a.s value, the model.s \$frame_a; set it to give its own)'
run -c "$L; show pod_a; model params pod_a; set frame_a 0.4; show pod_a; model params pod_a;
  set pod_a 0.3; show pod_a; model params pod_a; set frame_a 0.35; show pod_a; show frame_a"
check follow_show cond '[ "$RC" -eq 0 ] && [ -n "$FA" ] && [ "$(grep -c "^pod_a  *$FA m  $F\$" "$TMP/out")" -eq 1 ] &&
  [ "$(grep -c "^pod_a  *0.4 m  $F\$" "$TMP/out")" -eq 1 ]'
check follow_params cond 'grep -q "^pod_a  *$FA m  (model: \$frame_a)\$" "$TMP/out" &&
  grep -q "^pod_a  *0.4 m  (model: \$frame_a)\$" "$TMP/out"'
check own_value cond '[ "$(grep -c "^pod_a  *0.3 m\$" "$TMP/out")" -eq 2 ] &&
  grep -q "^pod_a  *0.3 m  (set)\$" "$TMP/out" && ! grep -q "^pod_a  *0.35" "$TMP/out" &&
  grep -q "^frame_a  *0.35 m\$" "$TMP/out"'
run -c "$L; set format json; show pod_b; model params pod_b"
check follow_json cond 'has "$TMP/out" "\"source\":\"derived: frame_b.s value, the model.s \$frame_b; set it to give its own\"" &&
  has "$TMP/out" "\"set_by\":\"model: \$frame_b\""'
# an unknown parameter named as a default: one line, with the file and line
printf 'part follow\nparam pod_a $no_such m\n' >"$TMP/follow.urm"
run -c "model load $TMP/follow.urm"
check follow_unknown cond '[ "$RC" -ne 0 ] && [ "$(grep -c . "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "follow.urm:2: param .pod_a.: unknown parameter .no_such."'

finish
