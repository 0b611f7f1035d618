# test_repl.sh: the history of interactive sessions (ui/repl.c): ~/.uasimpact_history is written
# when a session ends; while it does not exist, the history kept under the tool's former name
# (~/.uasrisk_history) is read once and left as it is; once the new file exists, the old one is
# not read again.
. tests/lib.sh
if ! command -v tmux >/dev/null 2>&1; then
  skip repl_history "tmux is not installed"
  finish
fi
. tests/lib_tmux.sh

# wait until the program in S has ended (at most 5 s)
ended() { n=0; while alive "$1" && [ "$n" -lt 50 ]; do sleep 0.1; n=$((n + 1)); done; ! alive "$1"; }

printf 'show wind\n' >"$TMP/.uasrisk_history"
start r1 100 30
wait_for r1 'uasimpact\[A\]>' 20
keys r1 Up
check old_history_read wait_for r1 'uasimpact\[A\]> show wind$'
keys r1 C-u
line r1 'show face'
line r1 quit
check first_session_ends ended r1
check new_history_written cond 'grep -qx "show wind" "$TMP/.uasimpact_history" &&
  grep -qx "show face" "$TMP/.uasimpact_history"'
check old_history_kept cond '[ "$(cat "$TMP/.uasrisk_history")" = "show wind" ]'

# the new file exists: the old one, changed since, is not read
printf 'show pitch\n' >"$TMP/.uasrisk_history"
start r2 100 30
wait_for r2 'uasimpact\[A\]>' 20
keys r2 Up Up
check new_history_read wait_for r2 'uasimpact\[A\]> show face$'
keys r2 C-u
line r2 quit
check second_session_ends ended r2
check old_not_read_again cond '! grep -q "show pitch" "$TMP/.uasimpact_history"'
finish
