# test_repl.sh: the interactive loop (ui/repl.c). The history: ~/.uasimpact_history is written
# when a session ends; while it does not exist, the history kept under the tool's former name
# (~/.uasrisk_history) is read once and left as it is; once the new file exists, the old one is
# not read again. The conventions: a greeting line with the version and how to get help and
# quit; q ends the session; an ambiguous prefix lists its commands and the session goes on;
# Tab completes set output (file names), set terminal (terminal names), set bag_model and its
# words (named.c), sweep NAME (wind, face,
# the parameters) and plot sweep NAME (the kept sweeps).
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

# the greeting, completion, an ambiguous prefix, q
start r3 100 30
check greeting wait_for r3 '^uasimpact [0-9.]+ \(commit [^)]*\); type help for the commands, q to quit$' 20
check greeting_once cond '[ "$(grep -c "q to quit" "$TMP/screen")" -eq 1 ]'
line r3 'des'
check ambiguous_listed wait_for r3 "error: ambiguous command 'des': descent or design\\? type more"
keys r3 -l 'set out'
keys r3 Tab
keys r3 -l 'tests/app/ui/test_rep'
keys r3 Tab
check complete_output_file wait_for r3 'uasimpact\[A\]> set output tests/app/ui/test_repl.sh$'
keys r3 C-u
keys r3 -l 'set terminal pngc'
keys r3 Tab
check complete_terminal wait_for r3 'uasimpact\[A\]> set terminal pngcairo$'
keys r3 C-u
keys r3 -l 'set bag_mo'
keys r3 Tab
check complete_named_param wait_for r3 'uasimpact\[A\]> set bag_model ?$'
keys r3 -l 'mem'
keys r3 Tab
check complete_named_word wait_for r3 'uasimpact\[A\]> set bag_model membrane ?$'
keys r3 C-u
keys r3 -l 'sweep fa'
keys r3 Tab
check complete_sweep_name wait_for r3 'uasimpact\[A\]> sweep face$'
keys r3 C-u
keys r3 -l 'sweep drone_si'
keys r3 Tab
check complete_sweep_param wait_for r3 'uasimpact\[A\]> sweep drone_size$'
keys r3 C-u
keys r3 -l 'sweep wind drone_si'
keys r3 Tab
check no_names_in_list cond '! wait_for r3 "sweep wind drone_siz" 1 >/dev/null'
keys r3 C-u
line r3 'set step 0.3; sweep drone_size 1,1.1'
wait_for r3 '^ *A +1.1 ' 30
keys r3 -l 'plot sweep dr'
keys r3 Tab
check complete_kept_sweep wait_for r3 'uasimpact\[A\]> plot sweep drone_size$'
keys r3 C-u
line r3 q
check q_ends ended r3
finish
