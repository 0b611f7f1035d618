# test_session.sh: save session writes every text as one quoted word that neither uasimpact nor a
# shell expands (src/app/session.c): model paths holding $(...), backquotes, quotes, blanks,
# backslashes and ! are written in single quotes (double ones only around a single quote with
# nothing a shell expands), a name that cannot be written so is refused when loaded (a newline,
# a single quote with $), the saved file replays to the same state, and a session saved in the
# old form (double quotes around $(...)) is still read without running anything (issue 30, item 3);
# a session replays from any current folder: a relative model path in a script is looked for in
# the script's folder first, then the current one, and save session writes the paths relative to
# the session's folder (absolute outside it); resolving writes nothing and runs nothing
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
D="$TMP/d"
mkdir "$D"

# model files whose names a shell would expand; each adds a part with one parameter
i=0
for name in 'a$(touch pwned1)b.urm' 'c`touch pwned2`d.urm' 'e f"g.urm' "h'i.urm" 'j\k!l$HOME.urm'; do
  i=$((i + 1))
  printf 'part extra%d\nparam extra_x%d %d\n' "$i" "$i" "$i" >"$D/$name"
done
cmds='model load "a$(touch pwned1)b.urm"; model load "c`touch pwned2`d.urm"'
cmds="$cmds; model load 'e f\"g.urm'; model load \"h'i.urm\"; model load 'j\\k!l\$HOME.urm'"
(cd "$D" && "$U" -c "$cmds; set extra_x2 7; set wind 3; model parts; save session s.ses") \
  >"$TMP/out" 2>"$TMP/err"
RC=$?
check loads_odd_names cond '[ "$RC" -eq 0 ] && [ "$(grep -c "^extra[1-5] " "$TMP/out")" -eq 5 ]'
S="$D/s.ses"
check saved cond '[ -s "$S" ] && [ "$(grep -c "^model load " "$S")" -eq 5 ]'

# no word of the file in double quotes holds what a shell expands there
check no_shell_active cond '! grep -n "\"[^\"]*[\$\`\\\\!][^\"]*\"" "$S"'
check single_quoted cond 'grep -qx "model load '"'"'a\$(touch pwned1)b.urm'"'"'   # part extra1" "$S" &&
  grep -qx "model load \"h'"'"'i.urm\"   # part extra4" "$S"'

# a shell reading the model load lines sees each path as written and runs nothing
model() { printf '%s\n' "$2" >>"$TMP/paths"; }
: >"$TMP/paths"
(cd "$D" && grep "^model load " "$S" | while IFS= read -r line; do eval "$line"; done)
(cd "$D" && for f in *.urm; do printf '%s\n' "$f"; done) | sort >"$TMP/want"
sort "$TMP/paths" >"$TMP/got"
check shell_reads_paths cmp -s "$TMP/want" "$TMP/got"
check shell_ran_nothing cond '[ ! -e "$D/pwned1" ] && [ ! -e "$D/pwned2" ]'

# the saved session replays to the same state: saved again, the same bytes
(cd "$D" && "$U" -c "source s.ses; save session s2.ses; show extra_x2; show wind") \
  >"$TMP/out" 2>"$TMP/err"
RC=$?
check replays cond '[ "$RC" -eq 0 ] && cmp -s "$S" "$D/s2.ses" && has "$TMP/out" "^extra_x2  *7$" &&
  has "$TMP/out" "^wind  *3 "'
check replay_ran_nothing cond '[ ! -e "$D/pwned1" ] && [ ! -e "$D/pwned2" ]'

# a session saved by an earlier version (double quotes around $(...)) is read as before
printf 'reset\nmodel load "a$(touch pwned1)b.urm"   # part extra1\ncase A\nset extra_x1 5\n' \
  >"$D/old.ses"
(cd "$D" && "$U" old.ses -c 'model parts; show extra_x1') >"$TMP/out" 2>"$TMP/err"
RC=$?
check old_form_reads cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^extra1  *a\$(touch pwned1)b.urm$" &&
  has "$TMP/out" "^extra_x1  *5$" && [ ! -e "$D/pwned1" ]'

# names that no quoting keeps inert are refused when loaded, naming what is accepted
printf 'part extra9\nparam extra_x9 9\n' >"$D/m'\$(touch pwned3).urm"
(cd "$D" && "$U" -c "model load \"m'\$(touch pwned3).urm\"") >"$TMP/out" 2>"$TMP/err"
RC=$?
check quote_dollar_refused cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "model load: cannot use .*a single quote with a double quote, \\$, backquote, backslash or !; accepted: a file name that save session can write back"'
nl='n
o.urm'
printf 'part extra8\nparam extra_x8 8\n' >"$D/$nl"
(cd "$D" && "$U" -c "model load \"$nl\"") >"$TMP/out" 2>"$TMP/err"
RC=$?
check newline_refused cond '[ "$RC" -eq 1 ] && has "$TMP/err" "model load: cannot use .n.x0ao.urm.: the name holds a control character"'

# ---- where a session finds its models ----
E="$TMP/e"
F="$TMP/f"
mkdir "$E" "$F"
printf 'part extraq\nparam extra_q 1\n' >"$E/q.urm"
(cd "$E" && "$U" -c "model load q.urm; set extra_q 4; save session s.ses; save session ../p.ses;
  save session $F/o.ses") >"$TMP/out" 2>"$TMP/err"
RC=$?
EP=$(cd "$E" && pwd -P)
check saved_paths cond '[ "$RC" -eq 0 ] && grep -qx "model load '"'"'q.urm'"'"'   # part extraq" "$E/s.ses" &&
  grep -qx "model load '"'"'e/q.urm'"'"'   # part extraq" "$TMP/p.ses" &&
  grep -qx "model load '"'"'$EP/q.urm'"'"'   # part extraq" "$F/o.ses"'
# replayed from another folder (the form of the files before, too: a bare name beside them)
(cd "$F" && "$U" "$E/s.ses" -c 'show extra_q' && "$U" ../p.ses -c 'show extra_q' &&
  "$U" o.ses -c 'show extra_q' && cd / && "$U" -c "source $E/s.ses; show extra_q") \
  >"$TMP/out" 2>"$TMP/err"
RC=$?
check replays_elsewhere cond '[ "$RC" -eq 0 ] && [ "$(grep -c "^extra_q  *4$" "$TMP/out")" -eq 4 ]'
# the script's folder before the current one: its own model, not a namesake where it is run
printf 'part extraq\nparam extra_q 2\nparam extra_other 1\n' >"$F/q.urm"
(cd "$F" && "$U" "$E/s.ses" -c 'model parts') >"$TMP/out" 2>"$TMP/err"
check own_folder_first cond 'has "$TMP/out" "^extraq  *$E/q.urm$"'
(cd "$F" && "$U" -c 'model load q.urm; show extra_q') >"$TMP/out" 2>"$TMP/err"
check prompt_current_folder cond 'has "$TMP/out" "^extra_q  *2$"'
# a folder whose name a shell would expand: found, and nothing run or written beside it
G="$TMP/g\$(touch pwned5)"
mkdir "$G"
cp "$E/s.ses" "$E/q.urm" "$G/"
(cd "$F" && "$U" "$G/s.ses" -c 'show extra_q') >"$TMP/out" 2>"$TMP/err"
check odd_folder cond 'has "$TMP/out" "^extra_q  *4$" && [ ! -e "$F/pwned5" ] && [ ! -e "$TMP/pwned5" ] &&
  [ "$(ls "$G" | wc -l)" -eq 2 ]'
finish
