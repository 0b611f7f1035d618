# test_interrupt.sh: Ctrl-C (SIGINT) during a grid, a sweep, the settling and a blocked read:
# the work stops well under a second after the signal, finished cells are kept and the grid is
# reported partial without a Q; a script ends with status 130; at the prompt Ctrl-C clears the
# line and never exits (tmux)
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }

# start uasimpact with ARGS in the background (stdin from $IN when set); it writes $TMP/ready.ses
# when the work to interrupt is about to start; with $1 = grid we wait until its worker threads
# run (the grid's cells are being computed, not its extents), then $2 seconds more
start_bg() { what=$1; delay=$2; shift 2
  rm -f "$TMP/ready.ses"
  if [ -n "${IN:-}" ]; then "$U" "$@" <"$IN" >"$TMP/out" 2>"$TMP/err" &
  else "$U" "$@" >"$TMP/out" 2>"$TMP/err" & fi
  PID=$!
  n=0
  while [ ! -e "$TMP/ready.ses" ] && [ "$n" -lt 1200 ]; do sleep 0.1; n=$((n + 1)); done
  while [ "$what" = grid ] && [ "$(ls "/proc/$PID/task" 2>/dev/null | wc -l)" -lt 2 ] &&
        [ "$n" -lt 2400 ]; do
    sleep 0.02; n=$((n + 1))
  done
  sleep "$delay"
}
# SIGINT now; RC and MS (milliseconds until the process ended)
interrupt() {
  t0=$(now_ms)
  kill -INT "$PID"
  wait "$PID"; RC=$?
  MS=$(( $(now_ms) - t0 ))
  echo "  (SIGINT: ended after $MS ms, status $RC)"
}

# ---- a grid in a script: stops at once, partial report, no Q, status 130 ----
printf 'case C\nset step 0.01\nset threads 2\nimpact 0 0\nsave session %s/ready.ses\ngrid\ngrid cells\n' \
  "$TMP" >"$TMP/g.ses"
IN= start_bg grid 0.3 "$TMP/g.ses"
interrupt
check grid_status [ "$RC" -eq 130 ]
check grid_prompt [ "$MS" -lt 1000 ]
check grid_message cond '[ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "g.ses:6: grid: interrupted (Ctrl-C); [1-9][0-9]* of [0-9]* cells finished, kept as a partial grid (no Q)$"'
check grid_partial_note has "$TMP/out" "^# PARTIAL grid (complete 0): 0 cells failed, [1-9][0-9]* not computed; q sums the finished cells only, a lower bound of Q$"
check grid_no_q cond 'grep -A1 "^case  *wind .* q  *seconds  *complete$" "$TMP/out" | tail -1 |
  grep -q "^ *C  *0 .* [0-9.]*  *[0-9.]*  *0$"'
check grid_script_stopped cond '! has "$TMP/out" "status: "'

# ---- interactively: the finished cells are kept (grid cells lists them), the session goes on ----
printf 'case C\nset step 0.01\nset threads 2\nimpact 0 0\nsave session %s/ready.ses\ngrid\ngrid cells\nshow case\n' \
  "$TMP" >"$TMP/in"
IN=$TMP/in start_bg grid 0.3 -i
interrupt
done_cells=$(sed -n 's/.*grid: interrupted (Ctrl-C); \([0-9]*\) of .*/\1/p' "$TMP/err")
rows=$(awk '/status: PARTIAL/{on=1; next} on && /^ *-?[0-9]/{n++} END{print n+0}' "$TMP/out")
check repl_grid_status [ "$RC" -eq 0 ]
check repl_grid_prompt [ "$MS" -lt 1000 ]
check repl_grid_message has "$TMP/err" "^error: grid: interrupted (Ctrl-C); [1-9][0-9]* of"
check repl_cells_kept cond '[ -n "$done_cells" ] && [ "$rows" -eq "$done_cells" ]'
check repl_goes_on has "$TMP/out" "^case  *C$"

# ---- a sweep: the grid under way stops, the sweep says how far it got ----
printf 'case C\nset step 0.01\nset threads 2\nimpact 0 0\nsave session %s/ready.ses\nsweep wind 0,2\n' \
  "$TMP" >"$TMP/s.ses"
IN= start_bg grid 0.3 "$TMP/s.ses"
interrupt
check sweep_status [ "$RC" -eq 130 ]
check sweep_prompt [ "$MS" -lt 1000 ]
check sweep_message cond '[ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "s.ses:6: sweep: interrupted (Ctrl-C) at wind 0; 0 of 2 grids finished (grid: interrupted"'
check sweep_no_empty_header cond '! grep -q "^case  *wind  *face" "$TMP/out"'

# ---- the settling of the stance (a fine settling step makes it long): stops at its next step ----
printf 'set bag_model analytic\nset dt 1e-5\nset settle_dt 1e-5\nsave session %s/ready.ses\nimpact 0 0\n' "$TMP" >"$TMP/st.ses"
IN= start_bg settle 0.3 "$TMP/st.ses"
interrupt
check settle_stopped cond '[ "$RC" -eq 130 ] && [ "$MS" -lt 1000 ] &&
  has "$TMP/err" "st.ses:5: interrupted (Ctrl-C) while settling the standing posture$"'

# ---- a read that blocks (a FIFO nobody writes): interrupted, not hung ----
mkfifo "$TMP/fifo"
"$U" -c "source $TMP/fifo" >"$TMP/out" 2>"$TMP/err" & PID=$!
waiting_in $PID 'wait_for_partner|fifo_open' # once it waits there (start-up inflates the bag)
interrupt
check fifo_interrupted cond '[ "$RC" -eq 130 ] && [ "$MS" -lt 1000 ] &&
  has "$TMP/err" "interrupted (Ctrl-C) while opening"'

# ... and a grid file that is a FIFO nobody writes
"$U" -c "grid load $TMP/fifo" >"$TMP/out" 2>"$TMP/err" & PID=$!
waiting_in $PID 'wait_for_partner|fifo_open'
interrupt
check fifo_grid_interrupted cond '[ "$RC" -eq 130 ] && [ "$MS" -lt 1000 ] &&
  has "$TMP/err" "grid load: interrupted (Ctrl-C) while opening"'

# ---- at the prompt, on a terminal (tmux) ----
if ! command -v tmux >/dev/null 2>&1; then
  skip terminal_checks "tmux is not installed"
  finish
fi
SOCK="uasimpact-int-$$"
TM() { tmux -L "$SOCK" -f /dev/null "$@"; }
trap 'tmux -L "$SOCK" kill-server 2>/dev/null; rm -rf "$TMP"' EXIT
grab() { TM capture-pane -p -S -100 -t t >"$TMP/screen"; }
# wait up to $2 seconds (10) until the screen matches $1
wait_for() { n=0; lim=$(( ${2:-10} * 20 ))
  while [ "$n" -lt "$lim" ]; do
    grab; grep -Eq -- "$1" "$TMP/screen" && return 0
    sleep 0.05; n=$((n + 1))
  done
  echo "  (waited for '$1'; the screen was:)"; sed 's/^/  | /' "$TMP/screen"; return 1
}
alive() { [ "$(TM display -p -t t "#{pane_dead}")" = 0 ]; }
# PAGER=cat: grid show's long output straight to the screen (the pager is test_pager.sh's)
TM new-session -d -s t -x 150 -y 50 -c "$PWD" "env HOME=$TMP PAGER=cat $U"
TM set -t t remain-on-exit on
check tty_prompt wait_for 'uasimpact\[A\]>'
TM send-keys -t t -l 'show wi'
TM send-keys -t t C-c
check tty_ctrl_c_line_dropped wait_for '^uasimpact\[A\]> show wi\^C$'
TM send-keys -t t C-c
sleep 0.3
check tty_second_ctrl_c_alive alive
TM send-keys -t t -l 'show face'
TM send-keys -t t Enter
check tty_prompt_works wait_for '^face +0 deg$'

# Ctrl-C during a grid: the error appears well under a second later, the cells stay
TM send-keys -t t -l 'case C; set step 0.01; set threads 2; grid'
TM send-keys -t t Enter
check tty_grid_running wait_for 'grid: [1-9][0-9]*/[0-9]* impacts' 60
t0=$(now_ms)
TM send-keys -t t C-c
check tty_grid_stopped wait_for '^error: grid: interrupted \(Ctrl-C\)'
MS=$(( $(now_ms) - t0 ))
echo "  (Ctrl-C in tmux: the message after $MS ms)"
check tty_grid_prompt [ "$MS" -lt 1000 ]
check tty_grid_partial wait_for '^# PARTIAL grid \(complete 0\): 0 cells failed'
TM send-keys -t t -l 'grid show'
TM send-keys -t t Enter
check tty_grid_kept wait_for ': Q >= [0-9.]* m\^2, partial grid \(0 failed, [1-9][0-9]* pending'
TM send-keys -t t C-c
TM send-keys -t t C-c
sleep 0.3
check tty_alive_at_end alive

finish
