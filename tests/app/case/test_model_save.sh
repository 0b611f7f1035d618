# test_model_save.sh: model save FILE writes the drone the session has now
# (src/app/case/model_save.c; model.c's model load): the model parameters set by 'set' go into
# their param lines, in each line's own unit, and into the live case's preset line where it sets
# them; settings that are not model text (wind, grid step) leave the file as the model's own.
# Loading the file in a fresh session gives the same parameters and the same impact, bit for bit;
# a session saved after model save and model load (one model load line for the file's parts,
# case/model.c) replays to the same impact row.
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
in_tmp() { (cd "$TMP" && "$U" -n "$@" >"$TMP/out" 2>"$TMP/err"); RC=$?; }

# the model as built in, and with settings that are not model text: the same bytes
in_tmp -c 'model save plain.urm; set wind 2; set step 0.2; set threads 1; model save session_only.urm'
check session_only_out cond '[ "$RC" -eq 0 ] && cmp -s "$TMP/plain.urm" "$TMP/session_only.urm"'
[ "$RC" -eq 0 ] || cat "$TMP/err"

# case B with the thorax spring and the bag pressure set: exactly those lines change, each in its
# own unit (kN/m, atm), and preset B's key (bag_p0=1.0atm) with it; no other preset
in_tmp -c 'case B; set thorax_k 30 kN/m; set bag_p0 1.05 atm; set wind 2; set format csv; model save m.urm; impact 0 0; model load m.urm; save session s.ses; impact 0 0'
cp "$TMP/out" "$TMP/live"
diff "$TMP/plain.urm" "$TMP/m.urm" | grep '^[<>]' | sed 's/  *#.*//; s/ *\\$//' >"$TMP/d"
printf '%s\n' '< param thorax_k 26 kN/m' '> param thorax_k 30 kN/m' '< param bag_p0 1.0 atm' \
  '> param bag_p0 1.05 atm' '< preset B bag_bottom=0 bag_front=0 bag_p0=1.0atm' \
  '> preset B bag_bottom=0 bag_front=0 bag_p0=1.05atm' >"$TMP/want"
check set_lines_written cond '[ "$RC" -eq 0 ] && cmp -s "$TMP/d" "$TMP/want"'
[ "$RC" -eq 0 ] && cmp -s "$TMP/d" "$TMP/want" || { cat "$TMP/err"; diff "$TMP/d" "$TMP/want"; }
# the impact after model load is the one before it
check load_same_live cond '[ "$(grep -c "^0,0," "$TMP/live")" -eq 2 ] &&
  [ "$(grep "^0,0," "$TMP/live" | sort -u | wc -l)" -eq 1 ]'

# a fresh session that loads the file: its parameters (case B's bag_p0 from the saved preset,
# not the built-in one the session started with), and the same impact row
in_tmp -c 'case B; model load m.urm; model params bag_p0; model params thorax_k; set wind 2; set format csv; impact 0 0'
check fresh_params cond '[ "$RC" -eq 0 ] && grep -q "^bag_p0  *106391.25 Pa  (case)$" "$TMP/out" &&
  grep -q "^thorax_k  *30000 N/m  (model)$" "$TMP/out"'
check fresh_same_impact cond '[ "$(grep "^0,0," "$TMP/out")" = "$(grep "^0,0," "$TMP/live" | head -n 1)" ]'
# ... and different from the built-in drone's (thorax_k reaches the VC columns)
in_tmp -c 'case B; set wind 2; set format csv; impact 0 0'
check builtin_differs cond '[ -n "$(grep "^0,0," "$TMP/out")" ] &&
  [ "$(grep "^0,0," "$TMP/out")" != "$(grep "^0,0," "$TMP/live" | head -n 1)" ]'

# the session saved after model save and model load loads the file once for its four parts,
# and replays to the same impact
check session_one_load cond '[ "$(grep -c "^model load" "$TMP/s.ses")" -eq 1 ] &&
  grep -qx "model load .m.urm.   # parts human, ra3, airbags, sim" "$TMP/s.ses"'
in_tmp -c 'source s.ses; set format csv; impact 0 0'
check session_replays cond '[ "$RC" -eq 0 ] && [ "$(grep "^0,0," "$TMP/out")" = "$(grep "^0,0," "$TMP/live" | head -n 1)" ]'
[ "$RC" -eq 0 ] || cat "$TMP/err"

# a file loaded whole and then replaced in part: its RA3 and airbags dropped, a quad loaded (one
# model has one drone). The session drops them again after the file's load, the last first, and
# replays to the same parts (before: it loaded the file whole, then failed on the second drone)
Q="$PWD/sessions/quad/quad.urm"
in_tmp -c "model save w.urm; model load w.urm; model drop airbags; model drop ra3; model load '$Q'; save session q.ses"
check drops_written cond '[ "$RC" -eq 0 ] && grep -A2 "^model load .w.urm.   # parts human, sim$" "$TMP/q.ses" |
  tr "\n" "|" | grep -qx "model load .w.urm.   # parts human, sim|model drop airbags   # a part of that file, dropped later|model drop ra3   # a part of that file, dropped later|"'
in_tmp -c 'source q.ses; model parts'
check drops_replay cond '[ "$RC" -eq 0 ] && [ ! -s "$TMP/err" ] &&
  [ "$(awk "{print \$1}" "$TMP/out" | tr "\n" " ")" = "human sim quad " ]'
[ "$RC" -eq 0 ] || cat "$TMP/err"
# a file's unnamed part (the text before its first part line), dropped: dropped again as ''
printf 'param extra_q 1 m\npart extra2\nparam extra_r 2 m\n' >"$TMP/np2.urm"
in_tmp -c "model load np2.urm; model drop ''; save session u.ses"
check drops_unnamed cond '[ "$RC" -eq 0 ] && grep -qx "model drop '"''"'   # a part of that file, dropped later" "$TMP/u.ses"'
in_tmp -c 'source u.ses; model parts'
check drops_unnamed_replay cond '[ "$RC" -eq 0 ] && [ "$(awk "NF == 1" "$TMP/out" | wc -l)" -eq 0 ] && grep -q "^extra2 " "$TMP/out"'
# a part dropped and brought back by another file is not dropped again
in_tmp -c "model save w.urm; model load w.urm; model drop airbags; model load w.urm; save session r.ses"
check drops_none cond '[ "$RC" -eq 0 ] && ! grep -q "^model drop airbags   #" "$TMP/r.ses"'

# a parameter that follows another (bag_a: $frame_a) set: its line gets the number; set mass
# writes the drone's mass parameter (drone_mass), the descent's mass is the session's
in_tmp -c 'set bag_a 0.3 m; set mass 12; model save f.urm'
check follower_number cond '[ "$RC" -eq 0 ] && grep -q "^param bag_a 0.3 m " "$TMP/f.urm" &&
  grep -q "^param drone_mass 12 kg " "$TMP/f.urm"'
finish
