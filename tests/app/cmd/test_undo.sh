# test_undo.sh: case and reset name the settings of the user's they drop (src/app/case/dropped.c,
# case.c, src/app/cmd/cmd.c), and undo (src/app/case/undo.c, cmd/script.c) restores the settings
# as they were before the last command that changed them, level by level, saying how many are
# left; a sourced file is one level; commands that change no setting leave none; what is not a
# setting (a grid, a sweep) stays. The notes of case and reset are for the prompt (-i, lines on
# standard input); a script stays quiet.
. tests/lib.sh

# the lines of $1 at the prompt (uasimpact -i < FILE)
prompt() { printf '%s\n' "$1" | tr ';' '\n' >"$TMP/in"; run_in "$TMP/in" -i; }

# case: the settings the user changed and the new case does not keep, with their values; the
# kept ones (wind, step) and the preset's own are not named
prompt 'set pitch 10; set bag_p0 1.1 atm; set wind 3; set step 0.2; case B'
check case_status [ "$RC" -eq 0 ]
check case_names cond 'grep -q "^case B: drops pitch 10 deg, bag_p0 111458 Pa (settings of yours it does not keep; undo brings them back)$" "$TMP/err"'
check case_keeps cond '! grep -q "wind\|step" "$TMP/err"'
prompt 'case B; case C; case A'
check case_nothing_dropped cond '[ "$RC" -eq 0 ] && ! [ -s "$TMP/err" ]'

# reset: everything the user set, wind and step included
prompt 'case B; set wind 3; set step 0.2; set use_defl 1; reset'
check reset_names cond 'grep -q "^reset: drops wind 3 m/s, step 0.2 m, .*use_defl 1" "$TMP/err"'
check reset_not_case cond '! grep -q "drops.*casename\|chute" "$TMP/err"'
run -c 'set pitch 10; case B; reset'
check script_quiet cond '[ "$RC" -eq 0 ] && ! [ -s "$TMP/err" ]'

# undo, level by level, with the count left
run -c 'set pitch 10; set wind 3; case B; undo; show pitch; show case; undo; show wind; undo; show pitch'
check undo_status [ "$RC" -eq 0 ]
check undo_case cond 'sed -n 1p "$TMP/out" | grep -q "^pitch  *10 deg" && sed -n 2p "$TMP/out" | grep -q "A"'
check undo_wind cond 'sed -n 3p "$TMP/out" | grep -q "^wind  *0 m/s"'
check undo_pitch cond 'sed -n 4p "$TMP/out" | grep -q "^pitch  *0 deg"'
check undo_says cond 'grep -q "^undo: the settings as before .case B. (2 more levels to undo, at most 32 kept)$" "$TMP/err" &&
  grep -q "^undo: the settings as before .set pitch 10. (0 more levels" "$TMP/err"'
run -c 'set pitch 10; undo; undo'
check undo_empty cond '[ "$RC" -eq 1 ] && grep -q "undo: nothing to undo" "$TMP/err"'

# reset undone: the model parameter set before it is back; a command that changes nothing, or
# fails, leaves no level
run -c 'set bag_p0 1.1 atm; show case; reset; undo; show bag_p0; undo; show bag_p0'
check undo_reset cond 'sed -n 2p "$TMP/out" | grep -q "^bag_p0  *111457.5 Pa"'
check undo_skips_unchanged cond 'sed -n 3p "$TMP/out" | grep -q "^bag_p0  *101325 Pa"' 
printf 'set pitch 5\nset roll 3\n' >"$TMP/s.ses"
run -c "set yaw 7; source $TMP/s.ses; undo; show pitch; show roll; show yaw"
check source_one_level cond 'grep -q "^pitch  *0 deg" "$TMP/out" && grep -q "^roll  *0 deg" "$TMP/out" &&
  grep -q "^yaw  *7 deg" "$TMP/out"'

# a level the model no longer takes (its parts changed since: the airbags' parameters are gone)
# is dropped with the reason, one at a time, and the live settings stay as they are
prompt 'set bag_p0 1.1 atm; set pitch 5; model drop airbags; undo; show pitch; undo; show pitch'
check undo_level_dropped cond 'grep -q "^error: undo: refused, the model does not accept it: .*; the settings before .model drop airbags. are dropped (2 more levels to undo)$" "$TMP/err" &&
  grep -q "the settings before .set pitch 5. are dropped (1 more level to undo)$" "$TMP/err" &&
  [ "$(grep -c "^pitch  *5 deg" "$TMP/out")" -eq 2 ]'

# a sweep is not a setting: undo leaves it kept
run -c 'set step 0.3; sweep face 0,90; undo; sweep show'
check undo_keeps_sweep cond '[ "$RC" -eq 0 ] && [ "$(grep -c "^ *A " "$TMP/out")" -ge 4 ]'
finish
