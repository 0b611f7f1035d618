# test_plot.sh: plot through gnuplot: PNG and text files written complete, what is sent (a fake
# gnuplot captures the script), no display, gnuplot missing, failing, killed or leaving early
# (SIGPIPE), and the placeholders that are not wired yet. A plot file is written whole or not at
# all (issue 30, item 5): gnuplot writes a temporary file beside it, renamed only when complete;
# a full disk (a small tmpfs where one can be mounted; a gnuplot that leaves a truncated PNG and
# exits 0, as the real one does on a full disk) is an error, a failed, interrupted or killed plot
# leaves an old file as it was, and /dev/stdout, /dev/fd/N, FIFOs and devices are refused
. tests/lib.sh

# uasimpact by absolute path, so that PATH can be changed
U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
# the paper's Table 6 (sessions/paper/grids, part of the repository: its absence is a failure)
T6=sessions/paper/grids/table06_caseC_wind0.csv
Q=0.8469
check paper_grid_present [ -r "$T6" ]
png_magic() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; }
size() { wc -c <"$1" | tr -d ' '; }
# the command failed with status 1 and one line of error holding $1
fails_with() { [ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && has "$TMP/err" "$1"; }

if command -v gnuplot >/dev/null 2>&1; then
  # plot grid to a PNG: complete when the command returns
  run -c "grid load $T6; set terminal png; set output $TMP/grid.png; plot grid"
  check grid_png_status [ "$RC" -eq 0 ]
  check grid_png_stderr_empty [ ! -s "$TMP/err" ]
  check grid_png_magic png_magic "$TMP/grid.png"
  check grid_png_size [ "$(size "$TMP/grid.png")" -gt 3000 ]

  # plot pof to a PNG; the terminal follows the file name when not set
  run -c "set output $TMP/pof.png; plot pof"
  check pof_png_status [ "$RC" -eq 0 ]
  check pof_png_magic png_magic "$TMP/pof.png"
  check pof_png_size [ "$(size "$TMP/pof.png")" -gt 5000 ]

  # svg and pdfcairo, named or chosen by the extension
  run -c "set terminal svg; set output $TMP/pof.svg; plot pof; set terminal pdfcairo; set output $TMP/pof.pdf; plot pof; set terminal default; set output $TMP/ext.pdf; plot pof; set output $TMP/ext.svg; plot pof"
  check svg_pdf_status [ "$RC" -eq 0 ]
  check svg_file cond 'grep -q "<svg" "$TMP/pof.svg" && grep -q "<svg" "$TMP/ext.svg"'
  check pdf_file cond '[ "$(head -c 5 "$TMP/pof.pdf")" = "%PDF-" ] && [ "$(head -c 5 "$TMP/ext.pdf")" = "%PDF-" ]'

  # the dumb terminal into text files: titles, labels and Q are there
  run -c "grid load $T6; set terminal \"dumb size 100,40\"; set output $TMP/grid.txt; plot grid"
  check grid_txt_status [ "$RC" -eq 0 ]
  check grid_txt_q has "$TMP/grid.txt" "Q = $Q m^2"
  check grid_txt_axes cond 'has "$TMP/grid.txt" "cross offset dperp (m)" &&
    has "$TMP/grid.txt" "P{F|Delta} (%)"'
  run -c "set terminal \"dumb size 120,50\"; set output $TMP/pof.txt; plot pof"
  check pof_txt_panels cond 'has "$TMP/pof.txt" "HIC15 -> P_HIC" &&
    has "$TMP/pof.txt" "Nij -> P_NI" && has "$TMP/pof.txt" "VC -> P_VC"'

  # a text terminal without a file draws on standard output
  run -c 'set terminal "dumb size 90,30"; plot pof'
  check dumb_stdout cond '[ "$RC" -eq 0 ] && has "$TMP/out" "HIC15 -> P_HIC"'

  # an unknown terminal is refused when set; gnuplot's own refusals name the setting
  run -c "set terminal nosuchterm; set output $TMP/x.png; plot pof"
  check bad_terminal fails_with "set terminal: unknown terminal 'nosuchterm'; accepted: NAME"
  run -c "set terminal 'png ansi'; set output $TMP/x.png; plot pof"
  check bad_terminal_option cond '[ "$RC" -eq 1 ] && has "$TMP/err" "set terminal png ansi: "'
  run -c "set terminal png; set output /nonexistent/dir/x.png; plot pof"
  check bad_output fails_with "plot pof: cannot write ./nonexistent/dir/x.png.: No such file or directory"

  # a good plot replaces an old file whole and keeps its mode
  printf 'OLD CONTENT\n' >"$TMP/old.png"
  chmod 640 "$TMP/old.png"
  run -c "set output $TMP/old.png; plot pof"
  check replaced_whole cond '[ "$RC" -eq 0 ] && png_magic "$TMP/old.png" &&
    [ "$(stat -c %a "$TMP/old.png")" = 640 ] && ! ls "$TMP" | grep -q "old.png.tmp"'

  # a full disk: a 64 KiB tmpfs (we may not be allowed to mount one: then skipped). Gnuplot
  # itself exits 0 there with a truncated file; the plot is an error, the old file stays
  mkdir -p "$TMP/full"
  trap 'umount "$TMP/full" 2>/dev/null; rm -rf "$TMP"' EXIT
  if mount -t tmpfs -o size=64k uasimpact-test "$TMP/full" 2>/dev/null; then
    printf 'OLD CONTENT\n' >"$TMP/full/p.png"
    printf 'OLD CONTENT\n' >"$TMP/full/p.txt"
    run -c "set terminal 'pngcairo size 3000,3000'; set output $TMP/full/p.png; plot pof"
    check full_disk_png fails_with "plot pof: cannot write '.*/full/p.png': No space left on device: gnuplot wrote an incomplete PNG file ([0-9]* bytes, no end marker); the file is unchanged$"
    run -c "set terminal 'dumb size 1000,1000'; set output $TMP/full/p.txt; plot pof"
    check full_disk_text fails_with "plot pof: cannot write '.*/full/p.txt': No space left on device: gnuplot wrote [0-9]* bytes and filled the disk; the file is unchanged$"
    check full_disk_old_intact cond '[ "$(cat "$TMP/full/p.png")" = "OLD CONTENT" ] &&
      [ "$(cat "$TMP/full/p.txt")" = "OLD CONTENT" ] && [ "$(ls "$TMP/full" | wc -l)" -eq 2 ]'
    # with room again, the same plot is written
    rm -f "$TMP/full/p.txt"
    run -c "set terminal 'dumb size 80,25'; set output $TMP/full/p.txt; plot pof"
    check full_disk_room_again cond '[ "$RC" -eq 0 ] && has "$TMP/full/p.txt" "HIC15 -> P_HIC"'
    umount "$TMP/full"
  else
    skip full_disk_tmpfs "cannot mount a tmpfs here (not root, or no mount namespace)"
  fi
else
  skip real_gnuplot_checks "gnuplot is not installed"
fi

# refused before gnuplot starts
run -c "set terminal png; plot pof"
check file_terminal_needs_output fails_with "terminal .png. writes a file; use .set output FILE."
run -c "set output $TMP/x.weird; plot pof"
check unknown_extension cond '[ "$RC" -eq 1 ] && has "$TMP/err" "no terminal for output"'
run -c 'plot grid'
check grid_needs_grid cond '[ "$RC" -eq 1 ] && has "$TMP/err" "plot grid: no grid yet"'
run -c 'plot bogus'
check unknown_plot fails_with \
  "plot: unknown plot .bogus.; accepted: pof, grid, history \[SIGNAL...|all\], sweep \[wind|face|NAME\]"
run -c 'plot history head_acc'
check history_not_yet cond '[ "$RC" -eq 1 ] && has "$TMP/err" "plot history: no impact yet"'
run -c 'plot sweep'
check sweep_not_yet cond '[ "$RC" -eq 1 ] && has "$TMP/err" "plot sweep: no sweep yet"'

# ---- gnuplot receives no command from a setting (issue 24, item 1) ----
# a terminal size that is an expression, a font that is a function call, an output that is a
# pipe, a backquote in an output name: refused when set (or passed as a plain string), never run;
# a session file holding them stops at its line; with a real gnuplot when there is one
mkdir -p "$TMP/atk"
( cd "$TMP/atk" &&
  "$U" -c "set terminal 'dumb size 80+0*strlen(system(\"touch pwned1\")),24'; plot pof" \
    >"$TMP/out" 2>"$TMP/err"; echo $? >"$TMP/rc" )
RC=$(cat "$TMP/rc")
check inject_size_refused fails_with "set terminal: option 'size': size needs W,H: two positive"
( cd "$TMP/atk" &&
  "$U" -c "set terminal \"pngcairo font system('touch pwned2')\"; set output f.png; plot pof" \
    >"$TMP/out" 2>"$TMP/err"; echo $? >"$TMP/rc" )
RC=$(cat "$TMP/rc")
check inject_font_refused fails_with "set terminal: option 'font': font needs a quoted 'NAME,SIZE'"
( cd "$TMP/atk" &&
  "$U" -c "set terminal dumb; set output '|touch pwned3'; plot pof" >"$TMP/out" 2>"$TMP/err"
  echo $? >"$TMP/rc" )
RC=$(cat "$TMP/rc")
check inject_pipe_refused fails_with "set output: '|touch pwned3' is refused: it starts with '|'"
( cd "$TMP/atk" && "$U" -c "set terminal dumb; set output ' |touch pwned4'; plot pof" \
    >/dev/null 2>&1 )
( cd "$TMP/atk" && "$U" -c "set terminal dumb; set output 'x\`touch pwned5\`.txt'; plot pof" \
    >"$TMP/out" 2>"$TMP/err"; echo $? >"$TMP/rc" )
printf '%s\n' "set terminal 'dumb size 80+0*strlen(system(\"touch pwned6\")),24'" 'plot pof' \
  >"$TMP/atk/evil.ses"
( cd "$TMP/atk" && "$U" evil.ses >"$TMP/out" 2>"$TMP/err2"; echo $? >"$TMP/rc2" )
check inject_session_stops cond '[ "$(cat "$TMP/rc2")" -eq 1 ] &&
  has "$TMP/err2" "^evil.ses:1: set terminal: option .size."'
check inject_nothing_ran cond '! ls "$TMP/atk" | grep -q "^pwned"'
if command -v gnuplot >/dev/null 2>&1; then
  check inject_backquote_plain cond '[ "$(cat "$TMP/rc")" -eq 0 ] &&
    [ -s "$TMP/atk/x\`touch pwned5\`.txt" ]'
fi
# what reaches gnuplot: the terminal as uasimpact writes it, the output in single quotes
run -c "set terminal 'pngcairo  font \"Arial,10\" size 640,480 noenhanced'; show terminal"
check terminal_normalised has "$TMP/out" "^terminal  *pngcairo font 'Arial,10' size 640,480 noenhanced$"

# ---- save session writes the terminal back so that it replays (item 7); the output file is
# the last plot's, not part of the state a session recreates (issue 26) ----
run -c "set terminal 'pngcairo font \"Arial,10\"'; set output \"it's.png\"; save session $TMP/q.ses"
check save_quoted cond 'grep -qx "set terminal \"pngcairo font '"'"'Arial,10'"'"'\"" "$TMP/q.ses" &&
  ! grep -q "^set output" "$TMP/q.ses"'
run "$TMP/q.ses" -c 'show terminal; show output'
check save_replays cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^terminal  *pngcairo font .Arial,10.$" &&
  has "$TMP/out" "^output  *none$"'

# gnuplot missing: one clear line, status 1
env PATH=/nonexistent "$U" -c "set terminal png; set output $TMP/m.png; plot pof" \
  >"$TMP/out" 2>"$TMP/err"; RC=$?
check missing_status [ "$RC" -eq 1 ]
check missing_one_line [ "$(lines "$TMP/err")" -eq 1 ]
check missing_message has "$TMP/err" \
  "plot pof: gnuplot not found; install it (Debian: gnuplot-nox) or use export"
env PATH=/nonexistent "$U" -c "grid load $T6; plot grid" >"$TMP/out" 2>"$TMP/err"; RC=$?
check missing_window cond '[ "$RC" -eq 1 ] && has "$TMP/err" "gnuplot not found"'

# a fake gnuplot: records its arguments and script, and acts as FAKE_GP says
mkdir -p "$TMP/bin"
cat >"$TMP/bin/gnuplot" <<'EOF'
#!/bin/sh
echo "$@" >"$FAKE_DIR/args"
case "$FAKE_GP" in
  capture) cat >"$FAKE_DIR/script"
           out=$(sed -n "s/^set output '\(.*\)'\$/\1/p" "$FAKE_DIR/script")
           [ -n "$out" ] && printf '\211PNG\r\n\032\n\0\0\0\0IEND\256B`\202' >"$out"; exit 0 ;;
  nowrite) cat >/dev/null; exit 0 ;;
  trunc) cat >"$FAKE_DIR/script"
         out=$(sed -n "s/^set output '\(.*\)'\$/\1/p" "$FAKE_DIR/script")
         head -c 3000 /dev/zero | { printf '\211PNG\r\n\032\n'; cat; } >"$out"; exit 0 ;;
  fail) head -c 2000 >"$FAKE_DIR/script"
        out=$(sed -n "s/^set output '\(.*\)'\$/\1/p" "$FAKE_DIR/script")
        [ -n "$out" ] && : >"$out"  # gnuplot opens (and so empties) the output, then fails
        echo '"/dev/stdin" line 7: fake failure' >&2; exit 1 ;;
  kill) kill -9 $$ ;;
  early) sleep 0.2; exit 3 ;;
  hang) echo $$ >"$FAKE_DIR/gp.pid"; exec sleep 100 ;;
esac
EOF
chmod +x "$TMP/bin/gnuplot"
fake() { mode=$1; shift; rm -f "$TMP/script" "$TMP/args"
  env PATH="$TMP/bin:/usr/bin:/bin" FAKE_DIR="$TMP" FAKE_GP="$mode" DISPLAY= WAYLAND_DISPLAY= \
    "$U" "$@" >"$TMP/out" 2>"$TMP/err"; RC=$?; }

# what plot grid sends: settings first, one datablock line per cell of the full plane
fake capture -c "grid load $T6; set terminal png; set output $TMP/f.png; plot grid"
check fake_status [ "$RC" -eq 0 ]
check fake_terminal [ "$(sed -n 1p "$TMP/script")" = "set terminal png" ]
check fake_output cond 'sed -n 2p "$TMP/script" | grep -qx "set output .$TMP/f.png.tmp.[A-Za-z0-9]\{6\}."'
check fake_renamed cond 'png_magic "$TMP/f.png" && ! ls "$TMP" | grep -q "f.png.tmp"'

check fake_unset_output [ "$(tail -1 "$TMP/script")" = "unset output" ]
check fake_no_persist_for_files [ "$(cat "$TMP/args")" = "/dev/stdin" ]
rows=$(sed -n '/^\$D << EOD$/,/^EOD$/p' "$TMP/script" | grep -c '^-\{0,1\}[0-9]')
check fake_cells [ "$rows" -eq $((29 * 31)) ]
# the cell (0.65, +-0.25) is 12.7 % on both sides; (0.70, 0) is 0
check fake_cell_right grep -q '^0.25 0.65 12.7$' "$TMP/script"
check fake_cell_left grep -q '^-0.25 0.65 12.7$' "$TMP/script"
check fake_cell_zero grep -q '^0 0.7 0$' "$TMP/script"
check fake_image has "$TMP/script" '^plot \$D using 1:2:3 with image'
check fake_palette has "$TMP/script" "^set cbtics (0, 5, 30, 90, 100)"

# no display and no file: gnuplot is not started
fake capture -c 'plot pof'
check no_display_status [ "$RC" -eq 1 ]
check no_display_message has "$TMP/err" \
  "^-c:1: plot: no display; use 'set terminal png' and 'set output FILE.png'$"
check no_display_not_started [ ! -e "$TMP/args" ]

# with a display, a window plot persists
rm -f "$TMP/args"
env PATH="$TMP/bin:/usr/bin:/bin" FAKE_DIR="$TMP" FAKE_GP=capture DISPLAY=:99 "$U" -c 'plot pof' \
  >"$TMP/out" 2>"$TMP/err"; RC=$?
check window_persist cond '[ "$RC" -eq 0 ] && [ "$(cat "$TMP/args")" = "-persist /dev/stdin" ]'
check window_no_output cond '! grep -q "^set output" "$TMP/script"'

# gnuplot failing, writing nothing, killed, or leaving before reading a large script
printf 'OLD CONTENT\n' >"$TMP/f.png"
fake fail -c "set terminal png; set output $TMP/f.png; plot pof"
check fail_message fails_with "plot pof: gnuplot failed.*: fake failure"
check fail_old_intact cond '[ "$(cat "$TMP/f.png")" = "OLD CONTENT" ] && ! ls "$TMP" | grep -q "f.png.tmp"'
rm -f "$TMP/f.png"
fake nowrite -c "set terminal png; set output $TMP/f.png; plot pof"
check nowrite_message fails_with "plot pof: cannot write '.*/f.png': gnuplot wrote nothing; the file is unchanged$"
check nowrite_no_file cond '[ ! -e "$TMP/f.png" ] && ! ls "$TMP" | grep -q "f.png.tmp"'

fake kill -c "set terminal png; set output $TMP/f.png; plot pof"
check killed_message cond '[ "$RC" -eq 1 ] && has "$TMP/err" "gnuplot was killed by signal 9"'
awk 'BEGIN { print "dpar,dperp,p"; for (i = 0; i < 200; i++) for (j = -100; j <= 100; j++)
       printf "%.2f,%.2f,%.3f\n", i * 0.05, j * 0.05, (i + j + 300) % 100 / 100 }' >"$TMP/big.csv"
fake early -c "grid load $TMP/big.csv; set terminal png; set output $TMP/f.png; plot grid"
check sigpipe_survived [ "$RC" -eq 1 ]
check sigpipe_message has "$TMP/err" "plot grid: gnuplot failed (it stopped reading)"

# a gnuplot that hangs: Ctrl-C stops the wait (and gnuplot) within 0.2 s, not at the timeout;
# the old file stays as it was and no temporary file is left
printf 'OLD CONTENT\n' >"$TMP/h.png"
rm -f "$TMP/gp.pid"
env PATH="$TMP/bin:/usr/bin:/bin" FAKE_DIR="$TMP" FAKE_GP=hang DISPLAY= WAYLAND_DISPLAY= \
  "$U" -c "set terminal png; set output $TMP/h.png; plot pof" >"$TMP/out" 2>"$TMP/err" & PID=$!
# Ctrl-C once gnuplot hangs (it wrote its pid), not after a guessed delay, which a loaded machine
# can outlast
n=0
while [ ! -s "$TMP/gp.pid" ] && [ "$n" -lt 1000 ]; do sleep 0.01; n=$((n + 1)); done
t0=$(date +%s%N); kill -INT $PID; wait $PID; RC=$?; MS=$(( ($(date +%s%N) - t0) / 1000000 ))
echo "  (SIGINT while gnuplot hangs: ended after $MS ms)"
# within 1 s, as the other interrupt checks (a hang still fails)
check hang_interrupted cond '[ "$RC" -eq 130 ] && [ "$MS" -lt 1000 ] &&
  has "$TMP/err" "plot pof: interrupted (Ctrl-C); gnuplot was stopped$"'
check hang_gnuplot_gone cond '[ -s "$TMP/gp.pid" ] && ! kill -0 "$(cat "$TMP/gp.pid")" 2>/dev/null'
check hang_old_intact cond '[ "$(cat "$TMP/h.png")" = "OLD CONTENT" ] && ! ls "$TMP" | grep -q "h.png.tmp"'

# ---- a plot file is written whole or not at all (issue 30, item 5) ----
# what gnuplot leaves on a full disk: a PNG cut short, status 0. Refused; the old file stays
printf 'OLD CONTENT\n' >"$TMP/t.png"
fake trunc -c "set terminal png; set output $TMP/t.png; plot pof"
check truncated_refused fails_with "plot pof: cannot write '.*/t.png': gnuplot wrote an incomplete PNG file (3008 bytes, no end marker); the file is unchanged$"
check truncated_old_intact cond '[ "$(cat "$TMP/t.png")" = "OLD CONTENT" ] && ! ls "$TMP" | grep -q "t.png.tmp"'
fake trunc -c "set terminal pdfcairo; set output $TMP/t.pdf; plot pof"
check wrong_format_refused fails_with "plot pof: cannot write '.*/t.pdf': gnuplot wrote 3008 bytes that do not start as a PDF file; the file is unchanged$"
check wrong_format_no_file cond '[ ! -e "$TMP/t.pdf" ] && ! ls "$TMP" | grep -q "t.pdf.tmp"'

# a symbolic link: the file it names is replaced, the link stays a link
printf 'OLD CONTENT\n' >"$TMP/real.png"
ln -s real.png "$TMP/link.png"
fake capture -c "set terminal png; set output $TMP/link.png; plot pof"
check symlink_followed cond '[ "$RC" -eq 0 ] && [ -L "$TMP/link.png" ] && png_magic "$TMP/real.png" &&
  ! ls "$TMP" | grep -q "real.png.tmp"'

# what is not a regular file is refused before gnuplot starts: nothing reaches standard output
# (a binary terminal used to write 8 bytes of its PNG there and report the wrong reason)
mkfifo "$TMP/fifo.png"
for n in stdout:/dev/stdout fd1:/dev/fd/1 procfd1:/proc/self/fd/1 null:/dev/null \
         fifo:"$TMP/fifo.png" dir:"$TMP"; do
  o=${n#*:}; n=${n%%:*}
  rm -f "$TMP/args"
  fake capture -c "set terminal png; set output $o; plot pof"
  check "refused_$n" cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && [ ! -s "$TMP/out" ] &&
    has "$TMP/err" "plot pof: cannot write .$o.: it \(names an open descriptor\|is a FIFO\|is a character device\|is a directory\); accepted: a regular file, replaced whole when complete" &&
    [ ! -e "$TMP/args" ]'
done
check refused_fifo_kept [ -p "$TMP/fifo.png" ]
if command -v gnuplot >/dev/null 2>&1; then
  "$U" -c "set terminal png; set output /dev/stdout; plot pof" >"$TMP/out" 2>"$TMP/err"; RC=$?
  check real_stdout_refused cond '[ "$RC" -eq 1 ] && [ ! -s "$TMP/out" ] &&
    has "$TMP/err" "cannot write ./dev/stdout.: it names an open descriptor"'
fi

# a signal that ends the program while gnuplot writes the temporary file (here one that hangs):
# gnuplot is killed, the temporary file removed, the old file kept, and the program dies of the
# signal (issue 30, item 8). Each signal is given back its default first where env can (a suite
# run under nohup ignores SIGHUP, and an ignored signal stays ignored: test_atomic.sh)
dflt=""
env --default-signal true 2>/dev/null && dflt="--default-signal"
for sig in TERM HUP USR1 ALRM PIPE; do
  rm -f "$TMP/gp.pid"
  printf 'OLD CONTENT\n' >"$TMP/s.png"
  env $dflt PATH="$TMP/bin:/usr/bin:/bin" FAKE_DIR="$TMP" FAKE_GP=hang DISPLAY= WAYLAND_DISPLAY= \
    "$U" -c "set terminal png; set output $TMP/s.png; plot pof" >"$TMP/out" 2>"$TMP/err" & PID=$!
  n=0
  while [ ! -s "$TMP/gp.pid" ] && [ "$n" -lt 500 ]; do sleep 0.01; n=$((n + 1)); done
  check "plot_sig_${sig}_temp_made" cond 'ls "$TMP" | grep -q "s.png.tmp"'
  kill -s "$sig" $PID; { wait $PID; } 2>/dev/null; RC=$?
  check "plot_sig_${sig}_status" cond '[ "$RC" -gt 128 ] && [ "$(kill -l "$RC")" = "$sig" ]'
  check "plot_sig_${sig}_cleaned" cond '! ls "$TMP" | grep -q "s.png.tmp" &&
    [ "$(cat "$TMP/s.png")" = "OLD CONTENT" ] && ! kill -0 "$(cat "$TMP/gp.pid")" 2>/dev/null'
done

finish
