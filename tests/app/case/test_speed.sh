# test_speed.sh: speeds typed in km/h or kt (src/app/case/speed.c, src/app/cmd/cmd.c, cmd_sweep.c,
# case/model.c): set wind, set winds, sweep wind and the other settings in m/s convert to m/s
# before they are checked and kept (closed forms: 36 km/h = 10 m/s, 1 kt = 1852/3600 m/s); a unit
# that is not m/s, km/h or kt is refused naming those; a model parameter in another unit refuses
# them; the range is checked in m/s after conversion.
. tests/lib.sh

run -c 'set wind 36 km/h; show wind; set wind 10 kt; show wind; set wind 3 m/s; show wind'
check set_status [ "$RC" -eq 0 ]
check kmh_exact cond 'sed -n 1p "$TMP/out" | grep -q "^wind  *10 m/s$"'
# show prints what a person reads (6 significant digits for a converted value, 10 at most where
# they are the value but for rounding noise); format csv and save session keep every digit
check kt_value cond 'sed -n 2p "$TMP/out" | grep -q "^wind  *5.14444 m/s$"'
check ms_still cond 'sed -n 3p "$TMP/out" | grep -q "^wind  *3 m/s$"'

run -c 'set winds 0,7.2,36 km/h; show winds'
check list_kmh cond '[ "$RC" -eq 0 ] && grep -q "^winds  *0,2,10 m/s$" "$TMP/out"'
run -c 'set speed 72 km/h; show speed'
check speed_kmh cond '[ "$RC" -eq 0 ] && grep -q "^speed  *20 m/s" "$TMP/out"'

run -c 'set winds 0,10,20 kt; show winds; set format csv; show wind; show winds'
check list_kt_shown cond 'sed -n 1p "$TMP/out" | grep -q "^winds  *0,5.14444,10.2889 m/s$"'
check csv_exact cond 'sed -n 2p "$TMP/out" | grep -q "^wind  *0 m/s$" &&
  sed -n 3p "$TMP/out" | grep -q "^winds  *0,5.144444444444445,10.28888888888889 m/s$"'
# model parameters in another unit: 30 deg, 1.1 atm (1.1 x 101325 = 111457.5 Pa but for the
# last bit), 26.3333 kN/m; model params prints them so too
sets='set bag_lock 30 deg; set bag_p0 1.1 atm; set thorax_k 26.3333 kN/m'
run -c "$sets; show bag_lock; show bag_p0; show thorax_k; model params bag_lock; set format json; show bag_lock"
check model_deg cond 'sed -n 1p "$TMP/out" | grep -q "^bag_lock  *0.523599 rad$" &&
  sed -n 2p "$TMP/out" | grep -q "^bag_p0  *111457.5 Pa$" &&
  sed -n 3p "$TMP/out" | grep -q "^thorax_k  *26333.3 N/m$" &&
  sed -n 4p "$TMP/out" | grep -q "^bag_lock  *0.523599 rad  (set)$" &&
  grep -q "\"value\":0.5235987756," "$TMP/out"'

# saved sessions keep m/s: the value replays without a unit, every digit kept
run -c "set wind 10 kt; set bag_lock 30 deg; save session $TMP/s.ses"
check saved_si cond 'grep -q "^set wind 5.144444444444445$" "$TMP/s.ses" &&
  grep -q "^set bag_lock 0.5235987755982988 rad$" "$TMP/s.ses"'

# refusals: an unknown unit, a value out of range once converted, a list for a number
run -c 'set wind 3 mph'
check unknown_unit cond '[ "$RC" -eq 1 ] && has "$TMP/err" "set wind: unknown unit .mph.; accepted: m/s, km/h or kt"'
run -c 'set wind 3 KT'
check strict_case has "$TMP/err" "unknown unit .KT."
run -c 'set wind 200 kt'
check range_after has "$TMP/err" "set wind: 200 kt (102.889 m/s) is out of range; accepted: 0 to 60 m/s (0 to 116.6 kt)"
run -c 'set wind 1,2 kt'
check number_only has "$TMP/err" "set wind: '1,2' is not a number"
run -c 'set winds 0,x kt'
check list_why has "$TMP/err" "set winds: '0,x' is not a list of numbers (value 2 of 2"
run -c 'set step 0.1 kt'
check not_a_speed has "$TMP/err" "set step: takes no unit but its own"
run -c 'set drone_mass 3 kt'
check model_other_unit has "$TMP/err" "set drone_mass: the unit 'kt' is in m/s, not kg"

# sweep wind LIST km/h: the grids at 0 and 1 m/s, the table in m/s (case B: the unit is the
# subject; A's membrane bag, its default at the switch, costs ~10 s CPU per coarse grid)
run -c 'case B; set step 0.3; sweep wind 0,3.6 km/h'
check sweep_kmh cond '[ "$RC" -eq 0 ] && awk "NR==2{a=\$2} NR==3{b=\$2} END{exit !(a==0 && b==1)}" "$TMP/out"'
run -c 'sweep wind 0,4 mph'
check sweep_unit has "$TMP/err" "sweep wind: unknown unit 'mph'"
# set velocity VH,VD in km/h: both components converted (36 km/h level: 10 m/s at 0 deg)
run -c 'set velocity 36,0 km/h; show speed; show angle; set velocity 1,1 mph'
check velocity_kmh cond 'sed -n 1p "$TMP/out" | grep -q "^speed  *10 m/s  (set)$" &&
  sed -n 2p "$TMP/out" | grep -q "^angle  *0 deg  (set)$" &&
  has "$TMP/err" "set velocity: .1,1 mph. is not accepted; .* in m/s, or followed by km/h or kt"'

# SORA's maximum speed in knots; unset, show says what sora derives (not a grid extent)
run -c 'show ua_max_speed; show ua_dimension; set ua_max_speed 20 kt; show ua_max_speed'
check sora_speed_show cond 'sed -n 1p "$TMP/out" | grep -q "^ua_max_speed  *auto m/s  (derived at sora: the unmitigated drone.s impact speed)$" &&
  sed -n 2p "$TMP/out" | grep -q "^ua_dimension  *1.3 m  (derived: the larger of the drone.s width and length)$" &&
  sed -n 3p "$TMP/out" | grep -q "^ua_max_speed  *10.2889 m/s  (set)$"'
finish
