# test_abbrev.sh: the names a command may be typed by (src/app/cmd/abbrev.c): its full name, q for
# quit, a prefix only one command begins with (desc: descent); an ambiguous prefix (des) lists the
# commands it begins and runs nothing; scripts take the same forms; an unknown name still gets
# "did you mean".
. tests/lib.sh

run -c 'desc'
check prefix_runs cond '[ "$RC" -eq 0 ] && head -1 "$TMP/out" | grep -q "^case  *wind  *speed  *angle"'
run -c 'des'
check ambiguous_fails cond '[ "$RC" -eq 1 ] && ! [ -s "$TMP/out" ]'
check ambiguous_lists has "$TMP/err" "ambiguous command 'des': descent or design? type more"
run -c 'help des'
check help_ambiguous has "$TMP/err" "help: ambiguous command 'des': descent or design?"
run -c 'help desi'
check help_prefix has "$TMP/out" "^usage: design save"
run -c 'sh wind'
check prefix_show cond '[ "$RC" -eq 0 ] && grep -q "^wind  *0 m/s" "$TMP/out"'

# q, quit and exit end the run: what follows them is not run
for w in q quit exit qui; do
  run -c "$w; show wind"
  check "$w ends" cond '[ "$RC" -eq 0 ] && ! [ -s "$TMP/out" ] && ! [ -s "$TMP/err" ]'
done

# in a script, with the handler seeing the full name (its messages name the command)
printf 'se step 0.3\nsho step\nsweep wind 0,x\n' >"$TMP/s.ses"
run "$TMP/s.ses"
check script_prefix cond 'grep -q "^step  *0.3 m" "$TMP/out"'
check script_error_line has "$TMP/err" "s.ses:3: sweep wind: value 2 of 2"

# an unknown name: no prefix of anything, the suggestion as before
run -c 'dscent'
check unknown_suggests cond '[ "$RC" -eq 1 ] && has "$TMP/err" "unknown command .dscent." &&
  has "$TMP/err" "descent"'
finish
