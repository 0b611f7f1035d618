# test_cli.sh: the scripting contract of uasimpact(1): -c, script files, stdin, exit status,
# FILE:LINE messages, CSV headers, and the man page covering every command
. tests/lib.sh

# -c runs commands and exits 0; CSV has one header and one row per wind
run -c 'set format csv; case B; descent'
check c_descent_status [ "$RC" -eq 0 ]
check c_descent_header [ "$(head -1 "$TMP/out")" = "case,wind,speed,angle" ]
check c_descent_rows [ "$(grep -c '^B,' "$TMP/out")" -eq 6 ]
check c_descent_stderr_empty [ ! -s "$TMP/err" ]

# case B zero-wind row of Table 2 (7.5 m/s, 90 deg) and 10 m/s row (12.5 m/s, 37.0 deg)
b0=$(grep '^B,0,' "$TMP/out"); b10=$(grep '^B,10,' "$TMP/out")
check table2_b0 awk -F, -v l="$b0" 'BEGIN{split(l,a,","); exit !((a[3]-7.5)^2<0.0225 && (a[4]-90)^2<0.36)}'
check table2_b10 awk -F, -v l="$b10" 'BEGIN{split(l,a,","); exit !((a[3]-12.5)^2<0.0225 && (a[4]-37)^2<0.36)}'

# parametric: Table 3 numbers for case B
run -c 'set format csv; case B; parametric'
check parametric_header has "$TMP/out" '^case,wind,speed,angle,planform,mtow,gliding,pof_rcc,pof_bc,pof_awke$'
check parametric_b0 has "$TMP/out" '^B,0,7.480,90.00,1.430,3.000,2.550,1.0000,1.0000,'
check parametric_one_header [ "$(grep -vc '^#' "$TMP/out")" -eq 7 ]

# pof: curves as x,p, monotone, 0 at 0 and reaching p ~ 1 (vc_thorax is bounded by P{F|AIS4}=0.5)
for k in hic nij vc vc_abdomen; do
  run -c "set format csv; pof $k"
  check "pof_$k" cond '[ "$RC" -eq 0 ] && [ "$(grep -v "^#" "$TMP/out" | head -1)" = "x,p" ] &&
    grep -v "^#" "$TMP/out" | awk -F, "NR==2&&\$2!=0{bad=1} NR>1{if(\$2+0<p)bad=1; p=\$2+0; n++} END{exit bad || !(n>=50 && p>0.99)}"'
done
run -c 'set hic_window 0.036; show hic_window'
check injury_setting has "$TMP/out" '^hic_window  *0.036 s$'
run -c 'set nij_order 1.5'
check injury_setting_range cond '[ "$RC" -eq 1 ] && has "$TMP/err" "accepted: an integer in \[0, 2\]"'

# errors: one clear line, non-zero status
run -c 'bogus'
check bogus_status [ "$RC" -ne 0 ]
check bogus_one_line [ "$(lines "$TMP/err")" -eq 1 ]
check bogus_message has "$TMP/err" "^-c:1: unknown command 'bogus'"
run -c 'set wind abc'
check setwind_status [ "$RC" -ne 0 ]
check setwind_one_line [ "$(lines "$TMP/err")" -eq 1 ]
check setwind_message has "$TMP/err" "set wind: 'abc' is not a number; accepted: a number in \[0, 60\] m/s"
for bad in 'set wind nan' 'set wind 1e400' 'set wind inf' 'set wind 0x' 'set wind -2' 'set winds 1,a' \
           'set dt_nonexistent 1' 'show nosuch' 'case Q' 'help nosuch' 'set wind 1 2' 'descent x'; do
  run -c "$bad"
  check "refused: $bad" cond '[ "$RC" -ne 0 ] && [ "$(lines "$TMP/err")" -eq 1 ]'
done

# a script stops at the first failing command with FILE:LINE and a non-zero status
printf 'case C\n# a comment\nset wind 3 ; set face 10\nset wind zz\nset wind 9\n' >"$TMP/s.ses"
run "$TMP/s.ses"
check script_status [ "$RC" -ne 0 ]
check script_file_line has "$TMP/err" "^$TMP/s.ses:4: set wind: 'zz'"
run_in "$TMP/s.ses"
check stdin_file_line has "$TMP/err" "^<stdin>:4: set wind"
check stdin_status [ "$RC" -ne 0 ]

# nested source: the innermost file and line are named
printf 'set wind 1\nsource %s/inner.ses\n' "$TMP" >"$TMP/outer.ses"
printf 'set wind 2\nset face north\n' >"$TMP/inner.ses"
run "$TMP/outer.ses"
check nested_status [ "$RC" -ne 0 ]
check nested_inner_line has "$TMP/err" "^$TMP/inner.ses:2: set face"

# scripts and -c run in order; state carries over
printf 'case C\nset wind 4\n' >"$TMP/state.ses"
run "$TMP/state.ses" -c 'show case; show wind'
check order_case has "$TMP/out" '^case  *C$'
check order_wind has "$TMP/out" '^wind  *4 m/s$'

# missing file, NUL bytes, random bytes: one message, non-zero, no crash
run /nonexistent/x.ses
check missing_file cond '[ "$RC" -eq 1 ] && has "$TMP/err" "cannot open ./nonexistent/x.ses."'
printf 'show wind\n\000\000binary\n' >"$TMP/nul.ses"
run "$TMP/nul.ses"
check nul_bytes cond '[ "$RC" -eq 1 ] && has "$TMP/err" "NUL byte"'
head -c 4096 /dev/urandom >"$TMP/rand.ses"
run "$TMP/rand.ses"
check random_bytes cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ]'

# issue 30: a UTF-8 byte-order mark as a script's first bytes (an editor's 'UTF-8 with BOM')
# is skipped, in a file, a sourced file and standard input; anywhere else it is refused by name
printf '\357\273\277set wind 3\nshow wind\n' >"$TMP/bom.ses"
run "$TMP/bom.ses"
check bom_first_skipped cond '[ "$RC" -eq 0 ] && [ ! -s "$TMP/err" ] && has "$TMP/out" "^wind  *3 m/s$"'
run -c "source $TMP/bom.ses"
check bom_sourced cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^wind  *3 m/s$"'
run_in "$TMP/bom.ses"
check bom_stdin cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^wind  *3 m/s$"'
printf 'set wind 3\n\357\273\277show wind\n' >"$TMP/bom2.ses"
run "$TMP/bom2.ses"
check bom_later_refused cond '[ "$RC" -eq 1 ] && [ ! -s "$TMP/out" ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "bom2.ses:2: a byte-order mark (U+FEFF, bytes EF BB BF) at byte 1 of the line; accepted only as the first bytes of a script or session file"'
run -c "$(printf 'set wind 3; show \357\273\277wind')"
check bom_in_c_refused cond '[ "$RC" -eq 1 ] && has "$TMP/err" "^-c:1: a byte-order mark (U+FEFF, bytes EF BB BF) at byte 18 of the line"'
printf 'show wind # a comment may hold one \357\273\277\n' >"$TMP/bom3.ses"
run "$TMP/bom3.ses"
check bom_in_comment cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^wind  *0 m/s$"'

# quit ends a script successfully; replaying stdin without errors exits 0
printf 'set wind 1\nquit\nbogus\n' >"$TMP/q.ses"
run "$TMP/q.ses"
check quit_status [ "$RC" -eq 0 ]
printf 'case B\nset format csv\ndescent\n' >"$TMP/ok.ses"
run_in "$TMP/ok.ses"
check stdin_ok cond '[ "$RC" -eq 0 ] && [ "$(grep -c "^B," "$TMP/out")" -eq 6 ]'
run -h
check help_option cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^usage: uasimpact"'
run -x
check bad_option [ "$RC" -eq 2 ]

# impacts: case C p >= 0.99, B within a factor 1.3 of the paper's centre cell (Table 5: 63.7 %),
# A above 0 and below B (the airbag protects); far: none
run -c 'set format csv; case C; impact 0 0; case B; impact 0 0; case A; impact 0 0; impact 0 1.5'
check impact_status [ "$RC" -eq 0 ]
check impact_header has "$TMP/out" '^dpar,dperp,contact,hic15,nij,nij_tf,nij_te,nij_cf,nij_ce,vc_thorax,vc_abdomen,p_hic,p_nij,p_vc,p$'
grep '^0,' "$TMP/out" | cut -d, -f15 >"$TMP/p"
check impact_values awk 'NR==1&&$1<0.99{bad=1} NR==2{b=$1; if($1<0.637/1.3||$1>0.637*1.3)bad=1} NR==3&&($1<=0||$1>=b){bad=1} NR==4&&$1!=0{bad=1} END{exit bad || NR!=4}' "$TMP/p"
run -c 'impact 0.1 zz'
check impact_bad_number cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && has "$TMP/err" "DPERP .zz. is not a number"'
run -c 'set dt 0'
check dt_zero_refused cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && has "$TMP/err" "set dt: refused"'

# the model set: save, load back, and a malformed file is refused at its line, nothing changed
run -c "model save $TMP/m.urm"
check model_save cond '[ "$RC" -eq 0 ] && [ "$(grep -c "^part " "$TMP/m.urm")" -eq 4 ]'
run -c "model load $TMP/m.urm; model parts"
check model_load_roundtrip cond '[ "$RC" -eq 0 ] && [ "$(grep -c "$TMP/m.urm" "$TMP/out")" -eq 4 ]'
printf 'part extra\nparam a 1\n\nbody b parent=world joint=free pos=0,0,0 mass=-2 inertia=1,1,1\n' >"$TMP/bad.urm"
run -c "model load $TMP/bad.urm"
check model_bad_line cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] && has "$TMP/err" "bad.urm:4: .*mass"'
printf 'part ra3\nparam x 1\nbdy q\n' >"$TMP/bad2.urm"
run -c "model load $TMP/bad2.urm; model parts"
check model_bad_keyword cond '[ "$RC" -eq 1 ] && has "$TMP/err" "bad2.urm:3: unknown keyword"'
printf 'model load %s\nmodel parts\n' "$TMP/bad2.urm" >"$TMP/in.txt"
run_in "$TMP/in.txt" -i
check model_unchanged cond 'has "$TMP/out" "^ra3  *built-in\$" && has "$TMP/err" "bad2.urm:3"'

# grid extents under wind reach upstream (the paper's 10 m/s grids go to dpar = -1.6 m)
run -c 'set format csv; case B; set wind 10; set step 0.2; grid; grid cells'
check grid_wind_status [ "$RC" -eq 0 ]
check grid_wind_upstream awk -F, '/^-?[0-9]/ && NF==8 {if ($1 < m) m = $1; if ($3 == 1) n++} END {exit !(m <= -1.6 && n > 0)}' "$TMP/out"

# case keeps the grid step (a numerical setting, like threads)
run -c 'set step 0.2; case C; show step'
check case_keeps_step has "$TMP/out" '^step  *0.2 m$'

# sweep and compare (coarse grids): one row per value, the live wind restored
run -c 'set format csv; case C; set step 0.2; sweep wind 0,4; show wind; compare'
check sweep_rows cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^case,wind,face,speed,angle,q$" && [ "$(grep -c "^C,[04],0," "$TMP/out")" -eq 2 ]'
check sweep_restores has "$TMP/out" '^wind  *0 m/s$'
check compare_row cond 'has "$TMP/out" "^case,wind,p_centre,gliding,q_parametric,q,factor$" && grep -q "^C,0,1.0000,2.550,2.5500," "$TMP/out"'
run -c 'sweep wind 0,-3'
check sweep_bad cond '[ "$RC" -eq 1 ] && has "$TMP/err" "accepted: comma-separated numbers in \[0, 60\] m/s"'

# export: CSV files that grid load reads back with the same Q
run -c "set format table; case C; set step 0.2; grid; export grid $TMP/g.csv; impact 0 0; export history $TMP/h.csv; grid load $TMP/g.csv; grid cells"
check export_status [ "$RC" -eq 0 ]
check export_grid_header grep -q '^dpar,dperp,contact,hic15,nij,vc_thorax,vc_abdomen,p$' "$TMP/g.csv"
check export_history cond '[ "$(grep -vc "^#" "$TMP/h.csv")" -gt 100 ] && grep -q "^t,head_acc_x" "$TMP/h.csv"'
# contacts: the last impact's pairs in order of first touch; none before an impact, none for a miss
run -c "contacts"
check contacts_not_yet cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "contacts: no impact yet; run .impact DPAR DPERP."'
run -c "set format csv; case C; impact 0.25 0.25; contacts; impact 0 1.5; contacts"
check contacts_rows cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^drone,person,first,last,peak_force,peak_time$" &&
  has "$TMP/out" "^# impact at (0.25, 0.25) m: [1-9][0-9]* pairs touched" &&
  has "$TMP/out" "^arm5_tube,head_cranium,0\.0[0-9]*,0\.0[0-9]*,[0-9.]*,0\.0[0-9]*$" &&
  has "$TMP/out" "^# impact at (0, 1.5) m: 0 pairs touched"'
awk -F, '/^# impact at \(0.25/ { on = 1; next } /^#/ { on = 0 } on && $1 != "drone" { print $3 }' \
  "$TMP/out" >"$TMP/firsts"
check contacts_ordered cond '[ "$(lines "$TMP/firsts")" -ge 2 ] && sort -c -n "$TMP/firsts"'
run -c "case A; impact 0 0; contacts"
check contacts_airbag has "$TMP/out" "bag_bottom  *head_cranium"
run -c "case A; impact 0 0; set format table; export contacts $TMP/c.csv"
check export_contacts cond '[ "$RC" -eq 0 ] && [ "$(sed -n 1p "$TMP/c.csv")" = "drone,person,first,last,peak_force,peak_time" ] &&
  grep -q "^bag_bottom,head_cranium,0\.0[0-9]*," "$TMP/c.csv"'

run -c "export grid /nonexistent/dir/g.csv"
check export_unwritable cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ]'

# save session recreates the state exactly (the source of speed and angle and tau included)
run -c "case A1; set wind 6; set face 45; set speed 9.5; set bag_kappa 4; set hic_window 0.036; set winds 0,5; set descent paper; set tau top; set format csv; save session $TMP/x.ses; show"
cp "$TMP/out" "$TMP/show1"
run "$TMP/x.ses" -c show
check save_session_status [ "$RC" -eq 0 ]
check save_session_same cmp -s "$TMP/show1" "$TMP/out"
check save_session_descent_tau cond 'grep -q "^set descent paper$" "$TMP/x.ses" && grep -q "^set tau top$" "$TMP/x.ses" &&
  grep -q "^angle  *51.5 deg  (derived: the paper.s Table 2, case B.s column" "$TMP/out" && grep -q "^tau  *top$" "$TMP/out"'
run "$TMP/x.ses" -c "set descent model; show angle"
check save_session_model_again has "$TMP/out" '^angle  *[0-9.]* deg  (derived: descent model at the live wind)$'

# every command listed by help is documented in the man page
run -c help
cmds=$(sed -n 's/^  \([a-z][a-z]*\).*/\1/p' "$TMP/out" | sort -u)
check help_lists_commands [ -n "$cmds" ]
for k in $cmds; do
  check "man documents $k" grep -q "^\.BI* $k\( \|\$\)" man/uasimpact.1
done


# quotes: single or double group a word (gnuplot's set output 'f.png'); the other kind inside;
# ';' and '#' inside quotes are text; an unterminated quote is one clear error
run -c "set output '/tmp/a b;#.png'; show output"
check quote_single cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^output  *\/tmp\/a b;#\.png$"'
run -c 'set output "/tmp/it'"'"'s.png"; show output'
check quote_double_holds_single cond '[ "$RC" -eq 0 ] && has "$TMP/out" "it.s\.png$"'
run -c "set output '/tmp/x.png"
check quote_unterminated cond '[ "$RC" -eq 1 ] && has "$TMP/err" "unterminated quote"'

# ---- standard output that cannot be written: one message, a non-zero exit (issue 24, item 6) ----
"$UASIMPACT" -c 'case C; impact 0 0; history' >/dev/full 2>"$TMP/err"; RC=$?
check stdout_full cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^-c:1: impact: cannot write the output: No space left on device$"'
"$UASIMPACT" -c 'help' >/dev/full 2>"$TMP/err"; RC=$?
check stdout_full_help cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "help: cannot write the output: No space left on device$"'
printf 'show wind\n' | "$UASIMPACT" >/dev/full 2>"$TMP/err"; RC=$?
check stdout_full_stdin cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "^<stdin>:1: show: cannot write the output: No space left on device$"'
"$UASIMPACT" -h >/dev/full 2>"$TMP/err"; RC=$?
check stdout_full_usage cond '[ "$RC" -eq 1 ] &&
  has "$TMP/err" "^uasimpact: cannot write standard output: No space left on device$"'

finish
