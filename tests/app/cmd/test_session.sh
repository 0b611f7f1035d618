# test_session.sh: save session writes every text as one quoted word that neither uasimpact nor a
# shell expands (src/app/session.c): model paths holding $(...), backquotes, quotes, blanks,
# backslashes and ! are written in single quotes (double ones only around a single quote with
# nothing a shell expands), a name that cannot be written so is refused when loaded (a newline,
# a single quote with $), the saved file replays to the same state, and a session saved in the
# old form (double quotes around $(...)) is still read without running anything (issue 30, item 3)
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
finish
