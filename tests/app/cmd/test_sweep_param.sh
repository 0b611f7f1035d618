# test_sweep_param.sh: sweep NAME LIST [UNIT] over any numeric parameter (src/app/cmd/sweep_param.c):
# columns case,NAME,wind,face,speed,angle,q; each Q is the grid the same setting gives; the
# live state comes back; sweep show and export sweep list the values in their unit; plot sweep
# NAME draws Q against it; bad names, values and units are refused before any grid runs.
. tests/lib.sh

mkdir -p "$TMP/bin"
# a fake gnuplot: keeps the scripts, writes a PNG (signature and end chunk) where they say
cat >"$TMP/bin/gnuplot" <<EOF
#!/bin/sh
tee -a "$TMP/plot.gp" >"$TMP/last.gp"
out=\$(sed -n "s/^set output '\\(.*\\)'\\\$/\\1/p" "$TMP/last.gp")
[ -n "\$out" ] && printf '\\211PNG\\r\\n\\032\\n\\0\\0\\0\\0IEND\\256B\`\\202' >"\$out"
exit 0
EOF
chmod +x "$TMP/bin/gnuplot"
U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")

# the analytic bag: the sweep's mechanics, not the bag, are checked here, and the membrane bag
# (A's default at the switch) costs ~10 s CPU per coarse grid; a setting made is a change the
# 'changes' column names (bag_membrane=0)
S='set format csv; set step 0.3; case A; set bag_model analytic'
run -c "$S; show bag_p0; sweep bag_p0 1.0,1.2 atm; show bag_p0; set bag_p0 1.2 atm; grid; sweep show; export sweep $TMP/s.csv"
check sweep_runs cond '[ $RC -eq 0 ]'
check sweep_header has "$TMP/out" '^case,bag_p0,wind,face,speed,angle,q$'
check sweep_rows cond '[ "$(grep -c "^A,1\(\.2\)\?,0,0," "$TMP/out")" -eq 2 ]'
check live_state_back cond '[ "$(grep -c "^bag_p0  *101325 Pa$" "$TMP/out")" -eq 2 ]'
# the grid at 1.2 atm gives the Q of the sweep's second row
qs=$(awk -F, '/^A,1.2,/ {print $7}' "$TMP/out")
check sweep_q_is_grid_q cond '[ -n "$qs" ] && grep -q "^A,bag_p0,0,0,[^,]*,[^,]*,0.3,$qs,bag_membrane=0,1.2,atm$" "$TMP/out"'
check export_has_unit has "$TMP/s.csv" '^A,bag_p0,0,0,.*,1,atm$'
run -c "$S; set bag_p0 1.2 atm; grid"
check grid_equals_sweep has "$TMP/out" ",$qs\(,\|$\)"

# plot sweep NAME
PATH="$TMP/bin:$PATH" "$U" -c "set step 0.3; case C; set terminal png; set output $TMP/p.png; sweep mass 10,20; plot sweep mass" >"$TMP/out" 2>"$TMP/err"; RC=$?
check plot_sweep_name cond '[ $RC -eq 0 ] && [ -s "$TMP/p.png" ] && grep -q "Q against mass" "$TMP/plot.gp" && grep -q "^10 " "$TMP/plot.gp"'

# refusals, nothing run
run -c "$S; sweep nosuch 1,2"
check unknown_name has "$TMP/err" "sweep: 'nosuch' is not accepted; accepted: .*sweep NAME LIST"
run -c "$S; sweep bag_p0 1,x atm"
check bad_list has "$TMP/err" "sweep bag_p0: value 2 of 2, 'x', is not a number; accepted: comma-separated numbers$"
# issue 30: more than 64 values (the old limit) are taken; a bad value of a long list is named
L70=$(yes 10 | head -70 | paste -sd, -)
run -c "set format csv; set step 0.6; case C; sweep mass $L70; sweep show"
check sweep_70_values cond '[ "$RC" -eq 0 ] && [ "$(grep -c "^C,mass,0,0,.*,10,kg$" "$TMP/out")" -eq 70 ]'
run -c "$S; sweep bag_p0 $(seq -s, 1 0.001 1.3),zz atm"
check long_list_item has "$TMP/err" "sweep bag_p0: value 302 of 302, 'zz', is not a number; accepted: comma-separated numbers$"
run -c "$S; sweep bag_p0 1 furlong"
check bad_unit has "$TMP/err" "sweep bag_p0: set bag_p0: unknown unit 'furlong'"
run -c "$S; sweep angle 30,120"
check out_of_range has "$TMP/err" "sweep angle: set angle: 120 is out of range"
# the kept-sweeps limit counts both kinds: after 32 parameter sweeps a wind sweep is refused
L="set format csv; set step 0.6; case C"
for i in $(seq 1 32); do L="$L; set face $i; sweep mass 10"; done
run -c "$L; set face 0; sweep wind 1"
check sweep_limit_both_kinds has "$TMP/err" "sweep: 32 sweeps are kept already; 'sweep clear' forgets them"
finish
