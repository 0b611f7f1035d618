# test_workbench.sh: the workbench as a person uses it, in tmux: a computed grid in the viewer
# (case B; grid; view), back to the prompt with the state intact, plot history to a PNG, Tab
# completion of commands, keywords, parameter names and file names, uasimpact -i FILE, the history
# file, Ctrl-D; and the 'no display' message at the prompt
. tests/lib.sh

if ! command -v tmux >/dev/null 2>&1; then
  skip workbench_checks "tmux is not installed"
  finish
fi
. tests/lib_tmux.sh
png_magic() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; }

# ---- the acceptance walk: case B, grid, view, q, plot history ----
# a coarse 0.1 m grid keeps this short (the default 0.05 m takes a few times longer)
start w1 160 50
check prompt wait_for w1 'uasimpact\[A\]>'
line w1 "set step 0.1"
line w1 "case B"
check prompt_shows_case wait_for w1 'uasimpact\[B\]> *$'
line w1 "grid"
check grid_q wait_for w1 '^ +B +0 +7\.480 +90\.00 +0 +0\.1 .* 0\.[0-9]{4} ' 120
Q=$(sed -n 's/^ *B  *0  *7\.480  *90\.00  *0  *0\.1 .* \(0\.[0-9]\{4\}\)  *[0-9.]*$/\1/p' "$TMP/screen" |
    tail -1)
check grid_q_read [ -n "$Q" ]
line w1 "view"
check view_title wait_for w1 "^case B, wind 0 m/s, face 0 deg, .*Q = $Q m\\^2  \\[computed\\]"
check view_coloured coloured w1
check view_axes wait_for w1 '^  dpar .* -0\.10  0\.00  0\.10 '
check view_status wait_for w1 '^dpar 0\.00 m  dperp 0\.00 m  P [0-9.]+ %  HIC15 '
keys w1 Right Up
check view_moves wait_for w1 '^dpar 0\.10 m  dperp 0\.10 m  P '
keys w1 c Enter
check view_inspect wait_for w1 'HIC15 .*window .* ms' 60
check view_trace wait_for w1 'head acceleration vs time, HIC15 window shaded'
keys w1 Escape
check view_panel_closed wait_for w1 'Enter inspect  p plot  b bag  q back'
keys w1 q
check view_left wait_gone w1 'Enter inspect  p plot  b bag  q back'
line w1 "show case"
check state_case wait_for w1 '^case +B$'
line w1 "show step"
check state_step wait_for w1 '^step +0\.1 m$'
line w1 "grid show"
check state_grid wait_for w1 "^case B, wind 0 m/s, face 0 deg, .*: Q = $Q m\\^2 over the full plane"

# the viewer's Enter ran the impact at (0, 0): plot history draws it into a PNG
line w1 "set terminal png"
line w1 "set output $TMP/history.png"
line w1 "plot history head_acc"
line w1 "show output"
check plot_back wait_for w1 "^output +$TMP/history.png$" 30
check history_png png_magic "$TMP/history.png"
check history_png_size [ "$(wc -c <"$TMP/history.png")" -gt 5000 ]
[ -n "$KEEP_PNG" ] && cp "$TMP/history.png" "$KEEP_PNG"

# without a display or a file: the message says how to get a file; the session goes on
line w1 "set terminal default"
line w1 "set output none"
line w1 "plot history head_acc"
check no_display wait_for w1 \
  "^error: plot: no display; use 'set terminal png' and 'set output FILE.png'$"
check alive_after_plot alive w1

# ---- Tab completion: commands, keywords, parameters, case names, file names ----
: >"$TMP/tab-session.ses"
complete() { # $1 typed, $2 expected line after Tab
  keys w1 C-u; TM send-keys -t w1 -l "$1"; keys w1 Tab
  wait_for w1 "^uasimpact\\[B\\]> $2 ?\$" 3; r=$?; keys w1 C-u; return $r; }
check tab_command complete "ca" "case"
check tab_keyword complete "plot sw" "plot sweep"
check tab_second_keyword complete "plot sweep w" "plot sweep wind"
check tab_param complete "set area_c" "set area_chute"
check tab_injury_param complete "show hic_w" "show hic_window"
check tab_model_param complete "set bag_ka" "set bag_kappa"
check tab_enum complete "set format c" "set format csv"
check tab_help_command complete "help vi" "help view"
check tab_file complete "source $TMP/tab-se" "source $TMP/tab-session.ses"
check tab_file_after_keyword complete "grid load $TMP/tab-se" "grid load $TMP/tab-session.ses"

# Ctrl-D leaves; the history file holds the lines typed
keys w1 C-d
n=0; while alive w1 && [ "$n" -lt 50 ]; do sleep 0.1; n=$((n + 1)); done
check ctrl_d_leaves cond '! alive w1'
check history_file cond 'grep -q "^case B$" "$TMP/.uasimpact_history" &&
  grep -q "^plot history head_acc$" "$TMP/.uasimpact_history"'

# ---- without gnuplot: one clear line, and the session goes on ----
start w3 120 30 PATH=/nonexistent
check nogp_prompt wait_for w3 'uasimpact\[A\]>'
line w3 "set output $TMP/x.png"
line w3 "plot pof"
check nogp_message wait_for w3 \
  '^error: plot pof: gnuplot not found; install it \(Debian: gnuplot-nox\) or use export$'
line w3 "case C"
check nogp_goes_on wait_for w3 'uasimpact\[C\]> *$'
check nogp_no_file [ ! -e "$TMP/x.png" ]
line w3 "quit"

# ---- uasimpact -i FILE: the script, then the prompt on its state ----
printf 'case C\nset wind 3\n' >"$TMP/start.ses"
start w2 120 30 -- -i "$TMP/start.ses"
check i_prompt wait_for w2 'uasimpact\[C\]>'
line w2 "show wind"
check i_state wait_for w2 '^wind +3 m/s$'
line w2 "quit"
n=0; while alive w2 && [ "$n" -lt 50 ]; do sleep 0.1; n=$((n + 1)); done
check i_quit cond '! alive w2'

finish
