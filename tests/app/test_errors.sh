# test_errors.sh: every error path of the reliability list (issue 8), one check each: one line
# naming what was wrong and what is accepted, a non-zero exit in a script, no crash, and the
# state unchanged (interactively, where errors do not stop the session)
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")

# refused NAME COMMANDS REGEX: -c fails with status 1 and one line of error matching REGEX
refused() {
  run -c "$2"
  check "$1" cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && has "$TMP/err" "$3"'
}
# kept NAME BAD: interactively, after 'set wind 3; set mass 7', the refused command BAD reports
# an error and leaves the state as it was (show prints the same before and after)
kept() {
  printf 'set wind 3\nset mass 7\nshow\n%s\nshow\n' "$2" >"$TMP/in"
  run_in "$TMP/in" -i
  # the two show listings (each from 'case' to the last model parameter) must be the same
  awk '/^uasimpact\[/{next} /^case /{n++} n==1{print >f1} n==2{print >f2}' f1="$TMP/show1" \
    f2="$TMP/show2" "$TMP/out"
  check "$1" cond '[ "$RC" -eq 0 ] && has "$TMP/err" "^error: " && [ -s "$TMP/show1" ] &&
    cmp -s "$TMP/show1" "$TMP/show2" && has "$TMP/show2" "^wind  *3 m/s"'
}

# ---- unknown command, wrong number of arguments ----
refused unknown_command 'set wind 3; bogus 1 2' "^-c:1: unknown command 'bogus'; type 'help' for the list"
kept unknown_command_kept 'bogus 1 2'
refused too_few_args 'impact 1' \
  "^-c:1: impact: wrong number of arguments (1); usage: impact DPAR DPERP$"
refused too_many_args 'set wind 1 2 3' "set: wrong number of arguments (4); usage: set NAME VALUE"
kept wrong_args_kept 'set wind'

# ---- malformed numbers: each names the value and the accepted range ----
for v in 1e400 -1e400 1e-400 nan NaN inf -inf 0x 0x10 '""' 3abc '3 m' 1..2 1e 1e+ . - +; do
  refused "malformed number $v" "set wind $v" \
    "set wind: '.*' is not a number; accepted: a number in \[0, 60\] m/s$"
done
kept malformed_kept 'set wind nan'
refused malformed_impact 'impact 0.1 zz' \
  "impact: DPERP 'zz' is not a number; accepted: the cross offset in m$"
refused malformed_list 'set winds 0,,4' "set winds: '0,,4' is not a list of numbers; accepted: comma"
refused malformed_model_param 'set bag_p0 1.1x atm' "set bag_p0: '1.1x' is not a number; accepted: a number"
kept malformed_model_param_kept 'set bag_p0 1e999 atm'

# ---- out of range ----
refused negative_mass 'set mass -2' "set mass: -2 is out of range; accepted: a number in \[0.01, 1000\] kg$"
kept negative_mass_kept 'set mass -2'
refused negative_wind 'set wind -0.5' "set wind: -0.5 is out of range; accepted: a number in \[0, 60\] m/s$"
refused dt_zero 'set dt 0' "set dt: refused, the model does not accept it: model: sim:.*: option dt must be > 0 (got 0)"
refused dt_negative 'set dt -1 ms' "set dt: refused, the model does not accept it: .*dt must be > 0"
kept dt_zero_kept 'set dt 0'
refused adapt_fraction 'set adapt 2.5' \
  "set adapt: refused, the model does not accept it: model: sim:.*: option adapt must be an integer from 1 (off) to 16 (got 2.5)"
refused adapt_zero 'set adapt 0' "set adapt: 0 is out of range; accepted: 1 to 16 (no unit)"
refused step_zero 'set step 0' "set step: 0 is out of range; accepted: a number in \[0.005, 1\] m$"
refused step_negative 'set step -0.1' "set step: -0.1 is out of range; accepted: a number in \[0.005, 1\] m$"
refused threads_fraction 'set threads 1.5' "set threads: 1.5 is out of range; accepted: a whole number in \[1, 64\]$"
refused impact_far 'impact 20 0' "impact: offset out of range; accepted: |DPAR|, |DPERP| <= 10 m$"

# a grid too large for memory is refused with its size, before anything is allocated, and the
# last grid stays as it was
printf 'along,0.00,0.05\n0.05,10,100\n0.00,50,0\n' >"$TMP/tiny.csv"
run -c "grid load $TMP/tiny.csv; set angle 1; set step 0.005; grid"
check grid_too_large cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "grid: [0-9]* cells of 0.005 m to scan for the extents ([0-9]* MB; [0-9]* MB of memory available) is too large; accepted: at most 4000000 cells"'
printf 'grid load %s\nset angle 1\nset step 0.005\ngrid\ngrid cells\n' "$TMP/tiny.csv" >"$TMP/in"
run_in "$TMP/in" -i
check grid_too_large_kept cond 'has "$TMP/err" "^error: grid: .* is too large" &&
  has "$TMP/out" "tiny.csv); status: complete" && grep -q "^ *0.050  *0.050 " "$TMP/out"'

# ---- missing and unreadable files (as root chmod does not hide a file: directories, devices
# and /proc files that fail to read instead) ----
refused source_missing 'source /nonexistent/x.ses' "cannot open '/nonexistent/x.ses': No such file or directory$"
refused source_directory "source $TMP" "cannot run '$TMP': it is a directory; accepted: a script file$"
refused source_eio 'source /proc/self/mem' "^/proc/self/mem:1: cannot read: Input/output error$"
refused source_zero 'source /dev/zero' "^/dev/zero:1: line contains a NUL byte; scripts are text files$"
refused model_missing 'model load /nonexistent.urm' "model load: cannot open '/nonexistent.urm': No such file"
refused model_directory "model load $TMP" "model load: cannot use '$TMP': Is a directory; accepted: a model text file"
refused model_eio 'model load /proc/self/mem' "model load: cannot use '/proc/self/mem': Input/output error"
refused model_zero 'model load /dev/zero' "model load: cannot use '/dev/zero': it contains NUL bytes"
refused grid_missing 'grid load /nonexistent.csv' "grid load: cannot open '/nonexistent.csv': No such file"
refused grid_directory "grid load $TMP" "^$TMP:1: read error: Is a directory$"
refused grid_zero 'grid load /dev/zero' "^/dev/zero:1: NUL byte: not a text file$"
kept model_directory_kept "model load $TMP"
awk 'BEGIN { while (n++ < 1100000) printf "a" }' >"$TMP/long.ses"
refused source_long_line "source $TMP/long.ses" "long.ses:1: line longer than 1048576 bytes; scripts are text files$"
# a script named on the command line
run "$TMP"
check script_arg_directory cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "it is a directory"'

# ---- NUL bytes and binary garbage (a fixed pseudo-random sequence, so that a failure repeats) ----
printf 'set wind 3\nshow wind\000\nset wind 5\n' >"$TMP/nul.ses"
run "$TMP/nul.ses"
check script_nul cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "nul.ses:2: line contains a NUL byte; scripts are text files$"'
for seed in 1 2 3 4 5 6 7 8; do
  awk -v s="$seed" 'BEGIN { srand(s); for (i = 0; i < 3000; i++) printf "%c", int(rand() * 255) + 1 }' \
    >"$TMP/garbage.ses"
  run "$TMP/garbage.ses"
  check "script_garbage_$seed" cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
    has "$TMP/err" "garbage.ses:[0-9]*: "'
done
printf 'part extra\nparam a 1\000\001\n' >"$TMP/nul.urm"
refused model_nul "model load $TMP/nul.urm" "model load: cannot use '.*nul.urm': it contains NUL bytes"
awk 'BEGIN { srand(9); for (i = 0; i < 3000; i++) printf "%c", int(rand() * 255) + 1 }' >"$TMP/garbage.urm"
refused model_garbage "model load $TMP/garbage.urm" "garbage.urm:[0-9]*: "
awk 'BEGIN { srand(10); for (i = 0; i < 3000; i++) printf "%c", int(rand() * 255) + 1 }' >"$TMP/garbage.csv"
refused grid_garbage "grid load $TMP/garbage.csv" "garbage.csv:[0-9]*: "

# ---- gnuplot absent, or dying in the middle of a plot (SIGPIPE): one message, the session goes on ----
awk 'BEGIN { print "dpar,dperp,p"; for (i = 0; i < 200; i++) for (j = -100; j <= 100; j++)
       printf "%.2f,%.2f,%.3f\n", i * 0.05, j * 0.05, (i + j + 300) % 100 / 100 }' >"$TMP/big.csv"
mkdir -p "$TMP/bin"
printf '#!/bin/sh\nexit 3\n' >"$TMP/bin/gnuplot"
chmod +x "$TMP/bin/gnuplot"
printf 'set wind 3\ngrid load %s\nset terminal png\nset output %s/p.png\nplot grid\nshow wind\n' \
  "$TMP/big.csv" "$TMP" >"$TMP/in"
env PATH="$TMP/bin:/usr/bin:/bin" "$U" -i <"$TMP/in" >"$TMP/out" 2>"$TMP/err"; RC=$?
check gnuplot_dies cond '[ "$RC" -eq 0 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^error: plot grid: gnuplot failed (it stopped reading)" &&
  has "$TMP/out" "^wind  *3 m/s"'
env PATH=/nonexistent "$U" -i <"$TMP/in" >"$TMP/out" 2>"$TMP/err"; RC=$?
check gnuplot_absent cond '[ "$RC" -eq 0 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^error: plot grid: gnuplot not found; install it (Debian: gnuplot-nox) or use export" &&
  has "$TMP/out" "^wind  *3 m/s"'

# ---- echoed input is made printable: no control byte of a name reaches the terminal ----
ESC=$(printf '\033')
run -c "set ${ESC}[2J${ESC}[31mred$(printf '\007')x 1"
check echo_sanitised cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  ! grep -q "$ESC" "$TMP/err" && ! grep -q "$(printf "\007")" "$TMP/err" &&
  has "$TMP/err" "unknown parameter .\\\\x1b\[2J\\\\x1b\[31mred\\\\x07x."'
run -c "$(printf 'show \302\2330m\303\251t\303\251')"
check echo_c1_sanitised cond '[ "$RC" -eq 1 ] && has "$TMP/err" "\\\\xc2\\\\x9b0m" &&
  has "$TMP/err" "été"'
run -c "grid load $TMP/x${ESC}[2Jy.csv"
check echo_path_sanitised cond '[ "$RC" -eq 1 ] && ! grep -q "$ESC" "$TMP/err"'
cp "$TMP/tiny.csv" "$TMP/x${ESC}[2Jy.csv"
run -c "grid load $TMP/x${ESC}[2Jy.csv; grid show; grid cells"
check source_sanitised cond '[ "$RC" -eq 0 ] && ! grep -q "$ESC" "$TMP/out" &&
  has "$TMP/out" "x\\\\x1b\[2Jy.csv"'

# ---- a grid file's error names the script line that loaded it as well ----
printf 'along,0.00\n0.10,zz\n' >"$TMP/badgrid.csv"
printf 'show wind\ngrid load %s\n' "$TMP/badgrid.csv" >"$TMP/g.ses"
run "$TMP/g.ses"
check gridload_script_line cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^.*g.ses:2: .*badgrid.csv:2: value at cross offset 0.00: .zz. is not a number"'

# ---- no terminal: the viewer says what to use (a too small terminal: tests/test_view.sh) ----
refused view_no_tty "grid load $TMP/tiny.csv; view" "view: needs a terminal; use 'grid show'$"

finish
