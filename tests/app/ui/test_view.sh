# test_view.sh: the grid viewer as a person uses it, in tmux: colours, the cursor and the status
# line, keys, the inspect panel, Ctrl-C, q back to the prompt with the state intact, a too small
# window and resizing, NO_COLOR, scrolling; and grid show in colour on a terminal; Ctrl-C and q
# stop the viewer's waits (a gnuplot that hangs, a slow impact) at once
. tests/lib.sh

T6=sessions/paper/grids/table06_caseC_wind0.csv
T8=sessions/paper/grids/table08_caseA_wind10.csv

# without a terminal or a grid: one clear line
run -c 'view'
check no_grid cond '[ "$RC" -eq 1 ] &&
  has "$TMP/err" "view: no grid yet; run .grid. or .grid load FILE."'
printf 'along,0.00,0.05\n0.05,10,100\n0.00,50,0\n' >"$TMP/tiny.csv"
run -c "grid load $TMP/tiny.csv; view"
check needs_terminal cond '[ "$RC" -eq 1 ] &&
  has "$TMP/err" "view: needs a terminal; use .grid show."'

if ! command -v tmux >/dev/null 2>&1; then
  skip viewer_terminal_checks "tmux is not installed"
  finish
fi
# the paper's grids are part of the repository: their absence is a failure, not a skip
check paper_grids_present cond '[ -r "$T6" ] && [ -r "$T8" ]'

. tests/lib_tmux.sh

# ---- TERM=dumb: no cursor addressing; one line saying so, no escape codes, the prompt again ----
start v0 100 20 TERM=dumb
check dumb_prompt wait_for v0 'uasimpact\[A\]>'
line v0 "grid load $TMP/tiny.csv; view"
check dumb_refused wait_for v0 'error: view: the terminal \(TERM=dumb\) cannot place the cursor'
line v0 "show case"
check dumb_goes_on wait_for v0 '^case +A$'
grab v0 -e
check dumb_no_escapes cond '! grep -q "$ESC\[[0-9;]*[HJ]" "$TMP/screen"'

# ---- a 160x50 terminal ----
start v1 160 50
check prompt wait_for v1 'uasimpact\[A\]>'
line v1 "grid load $T6"
line v1 "grid show"
check show_q wait_for v1 'Q = 0.8469 m\^2 over the full plane'
check show_coloured coloured v1
line v1 "view"
check view_title wait_for v1 'case C, wind 0 m/s, face 0 deg.*Q = 0.8469 m\^2'
check view_coloured coloured v1
check view_legend wait_for v1 '0 / no contact +0-5 % +5-30 % +30-90 % +>=90 %'
check view_start_centre wait_for v1 'dpar 0.00 m  dperp 0.00 m  P 100.0 %'
check view_axes cond 'grep -q "^  dpar.* -0.05  0.00  0.05 " "$TMP/screen" &&
  grep -q "^ -0.70 " "$TMP/screen"'
keys v1 Right
check right_moves wait_for v1 'dpar 0.00 m  dperp 0.05 m'
keys v1 Up
check up_moves wait_for v1 'dpar 0.05 m  dperp 0.05 m'
keys v1 -N 12 Up
keys v1 -N 4 Right
check cell_value wait_for v1 'dpar 0.65 m  dperp 0.25 m  P 12.7 %'
keys v1 j
check vi_j wait_for v1 'dpar 0.60 m  dperp 0.25 m  P 100.0 %'
keys v1 h
check vi_h wait_for v1 'dpar 0.60 m  dperp 0.20 m  P 0.0 %  .* no contact'
keys v1 End
check end_last_row wait_for v1 'dpar -0.70 m  dperp 0.20 m'
keys v1 Home
check home_first_row wait_for v1 'dpar 0.70 m  dperp 0.20 m'
keys v1 NPage
check pgdn_moves wait_for v1 'dpar -0.(3|4|5|6|7)[05] m  dperp 0.20 m'
keys v1 '$'
check last_column wait_for v1 'dperp 0.75 m'
keys v1 c
check centre_key wait_for v1 'dpar 0.00 m  dperp 0.00 m'

# Enter: the panel (stored values, or the impact when simulation is wired); any key closes it
keys v1 Enter
check panel_open wait_for v1 'impact simulation not available|head acceleration vs time' 60
check panel_values wait_for v1 'HIC15 .*window .* ms'
keys v1 Escape
check panel_closed wait_for v1 'Enter inspect  p plot  b bag  q back'

# Ctrl-C is a key here: the viewer stays
keys v1 C-c
check ctrl_c_kept wait_for v1 'Ctrl-C does not stop the viewer; q returns to the prompt'
check ctrl_c_alive cond '[ "$(TM display -p -t v1 "#{pane_dead}")" = 0 ]'

# q: back at the prompt, the state intact
keys v1 q
check q_leaves wait_gone v1 'Enter inspect  p plot  b bag  q back'
line v1 "show case"
check q_prompt wait_for v1 '^case +A$'
line v1 "grid show"
check q_grid_kept wait_for v1 'case C, wind 0 m/s, face 0 deg, .*: Q = 0.8469 m'
# view again, then Esc leaves as well
line v1 "view"
check view_again wait_for v1 'Enter inspect  p plot  b bag  q back'
keys v1 Escape
check esc_leaves wait_gone v1 'Enter inspect  p plot  b bag  q back'
line v1 "show wind"
check esc_prompt wait_for v1 '^wind +0 m/s$'
# a plot without a display fails with one message and the session goes on
line v1 "plot pof"
check plot_no_display wait_for v1 \
  "error: plot: no display; use 'set terminal png' and 'set output FILE.png'"
line v1 "show face"
check after_plot wait_for v1 '^face +0 deg$'
check alive_at_end cond '[ "$(TM display -p -t v1 "#{pane_dead}")" = 0 ]'

# ---- too small, then resized ----
start v2 30 10
check small_prompt wait_for v2 'uasimpact'
line v2 "grid load $T6"
line v2 "view"
check too_small wait_for v2 'need at least 60x12,'
check too_small_have wait_for v2 'have 30x10'
TM resize-window -t v2 -x 120 -y 40
check resized wait_for v2 'Q = 0.8469 m\^2'
check resized_status wait_for v2 'dpar 0.00 m  dperp 0.00 m'
keys v2 q
check small_leaves wait_gone v2 'dpar 0.00 m  dperp 0.00 m'
line v2 "show case"
check small_back wait_for v2 '^case +A$'

# ---- NO_COLOR: no colour escapes, glyphs tell the bands ----
start v3 160 50 NO_COLOR=1
check nc_prompt wait_for v3 'uasimpact'
line v3 "grid load $T6"
line v3 "grid show"
check nc_show wait_for v3 'Q = 0.8469 m\^2 over the full plane'
check nc_show_plain cond '! coloured v3'
line v3 "view"
check nc_view wait_for v3 'Enter inspect'
check nc_view_plain cond '! coloured v3'
# the glyph right before its own number, a blank before it (not '19.9# 74.3')
check nc_glyphs wait_for v3 ' @100 '
check nc_glyph_prefix wait_for v3 ' [.:#@][0-9]+\.[0-9] +[.:#@ ][0-9]'
check nc_glyph_not_suffix cond '! grep -Eq "[0-9][.:#@] " "$TMP/screen"'
check nc_legend wait_for v3 '  0 / no contact . 0-5 % : 5-30 % # 30-90 % @ >=90 %'
keys v3 q

# ---- TERM=vt100 (no alternate screen, no rmcup): on leaving, the viewer does not stay on the
# screen; it is cleared as the colour viewer's is restored, and the prompt comes back on it ----
start vt 100 30 TERM=vt100
check vt_prompt wait_for vt 'uasimpact'
line vt "grid load $T6"
line vt "show wind"
check vt_before wait_for vt '^wind +0 m/s$'
line vt "view"
check vt_view wait_for vt 'Enter inspect  p plot  b bag  q back'
keys vt q
check vt_view_gone wait_gone vt 'Enter inspect|0 / no contact|dpar 0.00 m  dperp 0.00 m'
line vt "show face"
check vt_prompt_back wait_for vt '^face +0 deg$'
check vt_screen_clean cond '! grep -Eq "Enter inspect|no contact|dperp|Q = 0.8469" "$TMP/screen" || { sed "s/^/  | /" "$TMP/screen"; false; }'

# ---- scrolling: Table 8 (48 x 33 cells) in 100 x 30 ----
start v4 100 30
check sc_prompt wait_for v4 'uasimpact'
line v4 "grid load $T8"
line v4 "view"
check sc_view wait_for v4 'case A, wind 10 m/s'
keys v4 End
check sc_end wait_for v4 'dpar -1.60 m'
check sc_end_label wait_for v4 '^ -1.60'
keys v4 Home
check sc_home wait_for v4 '^  0.75'
keys v4 '$'
check sc_right wait_for v4 'dperp 0.80 m'
check sc_right_label wait_for v4 ' 0.80 *$'
keys v4 0
check sc_left wait_for v4 ' -0.80 '
keys v4 q

# ---- the viewer's waits: Ctrl-C stops them, q stops them and leaves (issue 30, item 6) ----
# p waits on gnuplot (here one that hangs, which the viewer would wait on for 60 s) and Enter on
# the cell's impact (here a settling with a 10 us step, several seconds): each key is answered
# well within 2 s, the hung gnuplot is gone and no plot file or temporary file is left
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
mkdir -p "$TMP/bin" "$TMP/pl"
printf '#!/bin/sh
echo $$ >>"%s/gp.pids"
exec sleep 100
' "$TMP" >"$TMP/bin/gnuplot"
chmod +x "$TMP/bin/gnuplot"
gp_gone() { [ -s "$TMP/gp.pids" ] && for p in $(cat "$TMP/gp.pids"); do
  ! kill -0 "$p" 2>/dev/null || return 1; done; }
# the key goes only once the fake gnuplot has written its pid (N lines): pressed earlier, under
# a sanitizer's load, it killed the shell before its echo and gp_gone had no pid to look at
gp_started() { n=0; while [ "$n" -lt 100 ]; do
  [ "$(cat "$TMP/gp.pids" 2>/dev/null | wc -l)" -ge "$1" ] && return 0
  sleep 0.1; n=$((n + 1)); done; return 1; }
start v5 160 50 "PATH=$TMP/bin:/usr/bin:/bin"
check wait_prompt wait_for v5 'uasimpact\[A\]>'
line v5 "grid load $T6; set terminal png; set output $TMP/pl/h.png; view"
check wait_view wait_for v5 'Enter inspect  p plot  b bag  q back'
keys v5 p
check wait_plotting wait_for v5 'plotting in gnuplot\.\.\. \(Ctrl-C stops it, q stops it and leaves\)' 30
check wait_plot_started gp_started 1
t0=$(now_ms); keys v5 C-c
check wait_plot_ctrl_c wait_for v5 'plot history: interrupted \(Ctrl-C\); gnuplot was stopped' 2
MS=$(( $(now_ms) - t0 )); echo "  (Ctrl-C while gnuplot hangs in the viewer: answered after $MS ms)"
check wait_plot_ctrl_c_bound [ "$MS" -lt 2000 ]
check wait_plot_gnuplot_gone gp_gone
check wait_plot_no_file cond '[ -z "$(ls "$TMP/pl")" ]'
check wait_plot_stays cond 'alive v5 && grep -q "dpar 0.00 m  dperp 0.00 m" "$TMP/screen"'
keys v5 p
check wait_plotting_again wait_for v5 'plotting in gnuplot\.\.\.' 30
check wait_plot_started_again gp_started 2
t0=$(now_ms); keys v5 q
check wait_plot_q wait_for v5 '^uasimpact\[A\]> *$' 2
MS=$(( $(now_ms) - t0 )); echo "  (q while gnuplot hangs in the viewer: left after $MS ms)"
check wait_plot_q_bound [ "$MS" -lt 2000 ]
check wait_plot_q_gnuplot_gone gp_gone
line v5 "show case"
check wait_plot_q_prompt wait_for v5 '^case +A$'
# a slow impact: the settling of the stance with a 10 us step
line v5 "set dt 1e-5; set settle_dt 1e-5; view"
check wait_view_again wait_for v5 'Enter inspect  p plot  b bag  q back'
keys v5 Enter
check wait_running wait_for v5 'running the impact of this cell\.\.\. \(Ctrl-C stops it' 5
t0=$(now_ms); keys v5 C-c
check wait_impact_ctrl_c wait_for v5 'inspect: .*interrupted \(Ctrl-C\)' 2
MS=$(( $(now_ms) - t0 )); echo "  (Ctrl-C during Enter's impact: answered after $MS ms)"
check wait_impact_ctrl_c_bound [ "$MS" -lt 2000 ]
keys v5 Enter
check wait_running_again wait_for v5 'running the impact of this cell' 5
t0=$(now_ms); keys v5 q
check wait_impact_q wait_for v5 '^uasimpact\[A[^]]*\]> *$' 2
MS=$(( $(now_ms) - t0 )); echo "  (q during Enter's impact: left after $MS ms)"
check wait_impact_q_bound [ "$MS" -lt 2000 ]
line v5 "show settle_dt"
check wait_impact_q_prompt wait_for v5 '^settle_dt +1e-05 s$'
check wait_alive_at_end alive v5

finish
