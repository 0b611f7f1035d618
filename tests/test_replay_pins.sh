# test_replay_pins.sh: scripts/replay-pins.sh, the defaults the committed fits ran under
# (src/models/replay.pins): the shipped file parses, and every pin names a parameter of the
# built-in model (a pin that no longer exists would silently stop pinning); NAME=NUMBER lines
# come out on one line, comments and blanks dropped; anything else is refused with its line.
. tests/lib.sh
P=scripts/replay-pins.sh
pins=$(sh "$P"); RC=$?
check "the shipped pins parse" cond '[ "$RC" -eq 0 ]'
ok=1
for kv in $pins; do
  run -c "show ${kv%%=*}"
  [ "$RC" -eq 0 ] || { ok=0; echo "no parameter ${kv%%=*}"; }
done
check "every pin names a parameter" cond '[ "$ok" -eq 1 ]'
printf '# a comment\n\n  a_1=1.5   # why\nb=-2e-3\n' >"$TMP/p"
check "pins on one line" cond '[ "$(sh "$P" "$TMP/p")" = "a_1=1.5 b=-2e-3" ]'
printf 'a=1\nb=1; rm -f x\n' >"$TMP/bad"
sh "$P" "$TMP/bad" >"$TMP/out" 2>"$TMP/err"; RC=$?
check "a line that is not NAME=NUMBER refused" cond '[ "$RC" -ne 0 ] && [ ! -s "$TMP/out" ] &&
  grep -q "bad:2: expected NAME=NUMBER" "$TMP/err"'
sh "$P" "$TMP/none" >"$TMP/out" 2>"$TMP/err"; RC=$?
check "a missing file refused" cond '[ "$RC" -ne 0 ] && grep -q "cannot read" "$TMP/err"'
finish
