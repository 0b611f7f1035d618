# test_pager.sh: the workbench at an ordinary 80x24 terminal, in tmux (issue 26): output taller
# than the screen through the pager (less -FRSX, $PAGER, set pager off) and never off a
# terminal; the compact impact row and wrapped notes and help in 80 columns; history's summary;
# show PREFIX; compare under wind says why p_centre is 0; the viewer's lines fit; the prompt names
# the live model; off a terminal (-c, pipes) the full row as before; a pager that fails or dies
# leaves the output on the screen with a note
. tests/lib.sh

# ---- off a terminal: the full impact row, the samples of history all, no pager ----
run -c 'case C; impact 0 0'
check pipe_full_row cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^dpar  dperp  contact  *hic15  *nij  *nij_tf"'
run -c 'case C; impact 0 0; history'
check pipe_history_summary cond 'has "$TMP/out" "^ *head_acc  *-*[0-9.e+]*  *m/s^2  *[0-9.]*$" &&
  has "$TMP/out" "^ *HIC15  *[0-9.]*  *[0-9.]*-[0-9.]* ms  *[01]\.[0-9]*$" && [ "$(lines "$TMP/out")" -lt 30 ]'
run -c 'case C; impact 0 0; history all'
check pipe_history_all cond '[ "$(lines "$TMP/out")" -gt 100 ] && has "$TMP/out" "^ *t  *head_acc_x  *head_acc_y"'
run -c 'case C; impact 0 0; history head_acc neck_fz 11:12'
check history_channels_range cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^ *t  *head_acc  *neck_fz$" &&
  [ "$(grep -c "^0\.011[0-9]* " "$TMP/out")" -ge 10 ] && ! grep -q "^0\.01[02-9]" "$TMP/out"'
run -c 'case C; impact 0 0; history 5:1'
check history_bad_range cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "history: .5:1. is not a time range; accepted: FROM:TO in ms"'
run -c 'show bag'
# only the parameters that start with the prefix, and (for bag) the '# derived' lines of the
# airbags (issue 32: which values are derived)
check show_prefix cond '[ "$RC" -eq 0 ] && [ "$(lines "$TMP/out")" -ge 5 ] &&
  ! grep -v "^# derived, " "$TMP/out" | grep -qv "^bag_" && has "$TMP/out" "^bag_p0  *101325 Pa$"'
run -c 'model params bag'
check model_params_prefix cond '[ "$RC" -eq 0 ] && [ "$(lines "$TMP/out")" -ge 5 ] &&
  ! grep -v "^# derived, " "$TMP/out" | grep -qv "^bag_" && has "$TMP/out" "^bag_p0  *101325 Pa  (case)$"'
run -c 'model params zz'
check model_params_none cond '[ "$RC" -eq 1 ] && has "$TMP/err" "no model parameter starts with .zz."'
run -c 'set bag_p0 3 kg'
check unit_of_another_kind cond '[ "$RC" -eq 1 ] &&
  has "$TMP/err" "set bag_p0: the unit .kg. is in kg, not Pa; accepted: a unit of Pa"'
run -c 'show thorax_k; set neck_k_flex 0.2 kN*m/rad; show neck_k_flex; model params'
check units_shown cond 'has "$TMP/out" "^thorax_k  *26000 N/m$" && has "$TMP/out" "^neck_k_flex  *200 N\*m/rad$" &&
  has "$TMP/out" "^neck_k_flex  *200 N\*m/rad  (set)$" && ! grep -q "(SI" "$TMP/out"'
PAGER=false run -c 'help'
check help_unwrapped_off_terminal has "$TMP/out" "^  set NAME VALUE \[UNIT\]      change a parameter of the live case (see 'show' for names, units and ranges); model parameters take"

if ! command -v tmux >/dev/null 2>&1; then
  skip pager_terminal_checks "tmux is not installed"
  finish
fi
if ! command -v less >/dev/null 2>&1; then
  skip pager_less_checks "less is not installed"
  finish
fi
. tests/lib_tmux.sh
# every line of the screen (wrapped lines joined) at most 80 characters
fits80() { grab "$1" -J; ! awk 'length > 80 { bad = 1 } END { exit !bad }' "$TMP/screen"; }

start p1 80 24 PAGER=
check prompt wait_for p1 'uasimpact\[A\]> *$'
line p1 "case C"
line p1 "impact 0 0"
check impact_compact wait_for p1 '^dpar +dperp +hic15 +nij +vc_th +vc_ab +p_hic +p_nij +p_vc +p$' 60
check impact_values wait_for p1 '^ +0 +0 +[0-9]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[01]\.[0-9]{3} +[01]\.[0-9]{3} +[01]\.[0-9]{3} +[01]\.[0-9]{3}$'
check impact_nij_note wait_for p1 '^# Nij (NTF|NTE|NCF|NCE) \(NTF '
check impact_fits fits80 p1
# set format wide: every column at the prompt too
keys p1 C-l
line p1 "set format wide; impact 0 0; set format table"
check impact_wide wait_for p1 '^dpar +dperp +contact +hic15 +nij +nij_tf' 60

# history: a summary that fits the screen, the samples through less
keys p1 C-l
line p1 "history"
check history_summary wait_for p1 '^ +P +- +- +[01]\.[0-9]{4}$'
check history_fits fits80 p1
line p1 "history all"
check history_pages wait_for p1 '^:$' 10
check history_paged_top cond 'grep -q "^ *t  *head_acc_x" "$TMP/screen"'
keys p1 q
check pager_quits wait_for p1 'uasimpact\[C\]> *$'
line p1 "set pager off"
line p1 "history all"
check pager_off wait_for p1 'uasimpact\[C\]> *$'
check pager_off_no_less cond '! grep -q "^:$" "$TMP/screen" && grep -q "^0\.[0-9]* " "$TMP/screen"'
line p1 "set pager on"

# Tab completes the last impact's channels after history and plot history
keys p1 C-l
keys p1 -l "history head_a"
keys p1 Tab
check history_tab wait_for p1 'uasimpact\[C\]> history head_acc *$'
keys p1 C-u
keys p1 -l "plot history chest_d"
keys p1 Tab
check plot_history_tab wait_for p1 'uasimpact\[C\]> plot history chest_defl *$'
keys p1 C-u

# show PREFIX at the prompt; a slip gets a suggestion (a prefix whose lines fit the 24-line screen:
# 'show bag' no longer does, and would leave the next keys to less)
line p1 "show bag_front_k"
check show_bag wait_for p1 '^bag_front_kappa +[0-9.]+$'
line p1 "set wnd 5"
check did_you_mean wait_for p1 "^error: set: unknown parameter 'wnd' \(did you mean 'wind'\?\)"

# help wraps at 80 between words
keys p1 C-l
line p1 "help set"
check help_wrapped wait_for p1 '^usage: set NAME VALUE \[UNIT\]'
check help_fits fits80 p1

# compare under wind: why p_centre is 0, wrapped in 80 columns
keys p1 C-l
line p1 "case A; set bag_model analytic; set wind 10; set step 0.1; compare"
check compare_why wait_for p1 '^# p_centre 0: the impact at \(0, 0\) does not touch the person;' 120
check compare_peak cond 'grep -q "peak P [0-9.]* at (" "$TMP/screen"'
check compare_fits fits80 p1

# the viewer at 80x24: title, values and keys all on screen
line p1 "view"
check view_keys wait_for p1 '^c centre  Enter inspect  p plot  b bag  q back'
check view_values cond 'grep -q "^dpar [-0-9.]* m  dperp [-0-9.]* m  P " "$TMP/screen" &&
  grep -q "^VC thorax [-0-9.]* m/s abdomen [-0-9.]* m/s" "$TMP/screen"'
check view_orientation cond 'grep -q "dperp m (+ left of course), rows dpar m (+ ahead)" "$TMP/screen"'
check view_fits fits80 p1
keys p1 q
check view_back wait_for p1 'uasimpact\[A\|modified\]> *$' # the analytic bag: a change from case A

# the prompt names the live model where it is not the case's
line p1 "case A"
check prompt_case wait_for p1 'uasimpact\[A\]> *$'
line p1 "set bag_p0 1.2 atm"
check prompt_modified wait_for p1 'uasimpact\[A\|modified\]> *$'
line p1 "case A"
check prompt_case_again wait_for p1 'uasimpact\[A\]> *$'
printf 'part bag2\n' >"$TMP/bag2.urm"
line p1 "model load $TMP/bag2.urm"
check prompt_loaded wait_for p1 'uasimpact\[A\|bag2\]> *$'

# PAGER names the pager (sh -c, as git does); one that cannot run leaves the text on screen
start p2 80 24 "PAGER='sed -n 1p'"
check prompt2 wait_for p2 'uasimpact\[A\]> *$'
line p2 "show"
check pager_env wait_for p2 '^case +A$'
check pager_env_used cond '[ "$(grep -c . "$TMP/screen")" -le 4 ]'
# the whole help listing (PAGER=cat: all of it on screen and in the scrollback) in 80 columns
line p2 "set pager off"
keys p2 C-l
line p2 "help"
check help_all wait_for p2 '^  exit +leave uasimpact$'
TM capture-pane -p -J -S -300 -t p2 >"$TMP/screen"
check help_all_fits cond '! awk "length > 80 { bad = 1 } END { exit !bad }" "$TMP/screen" &&
  grep -q "^ *nij_ce,vc_thorax" "$TMP/screen"'
# (each waits for show's last line: the lines above it depend on the model, and a membrane bag's
# derived lines push 'window' off a 24-line screen)
start p3 80 24 PAGER=/nonexistent/pager
check prompt3 wait_for p3 'uasimpact\[A\]> *$'
line p3 "show"
check pager_missing_prints wait_for p3 '^# input distributions of montecarlo \(dist\): none$'
TM capture-pane -p -J -S -2000 -t p3 >"$TMP/screen" # the note scrolled up: the scrollback
check pager_missing_note cond 'grep -q "^pager: the pager ./nonexistent/pager. was not found; the output follows here" "$TMP/screen"'
# issue 30: a pager that fails without reading (false exits 1) or dies loses nothing: a note
# says so and the output follows on the screen
start p4 80 24 PAGER=false
check prompt4 wait_for p4 'uasimpact\[A\]> *$'
line p4 "show"
check pager_false_prints wait_for p4 '^# input distributions of montecarlo \(dist\): none$'
TM capture-pane -p -J -S -2000 -t p4 >"$TMP/screen"
check pager_false_note cond 'grep -q "^pager: the pager .false. failed (exit status 1); the output follows here (PAGER=cat or .set pager off. prints without a pager)$" "$TMP/screen"'
start p5 80 24 "PAGER='kill -9 \$\$'"
check prompt5 wait_for p5 'uasimpact\[A\]> *$'
line p5 "show"
check pager_killed_prints wait_for p5 '^# input distributions of montecarlo \(dist\): none$'
TM capture-pane -p -J -S -2000 -t p5 >"$TMP/screen"
check pager_killed_note cond 'grep -q "^pager: the pager .kill -9 \$\$. was ended by signal 9; the output follows here" "$TMP/screen"'
finish
