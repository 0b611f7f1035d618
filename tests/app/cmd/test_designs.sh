# test_designs.sh: designs side by side (src/app/cmd/designs.c): design save keeps the full state,
# design compare prints both Q (each the Q of that design's own grid) and their ratio, and leaves
# the difference grid P_b - P_a (its Q is q_b - q_a, a cell's p the difference of the cells);
# the live state stays; a saved session replays the designs; refusals name what is accepted.
# Case A with the analytic bag throughout (set bag_model analytic, a change 'design list' shows):
# designs are the subject, whatever the bag; the membrane bag, A's default at the switch, costs
# ~10 s CPU per coarse grid of A.
. tests/lib.sh

S='set format csv; set step 0.3'
run -c "$S; case B; design save plain; case A; set bag_model analytic; set bag_p0 1.2 atm; design save bag; case C; design compare plain bag; show case; grid cells; design list"
check compare_runs cond '[ $RC -eq 0 ]'
check compare_header has "$TMP/out" '^design_a,case_a,q_a,design_b,case_b,q_b,ratio$'
row=$(grep '^plain,B,[0-9.]*,bag,' "$TMP/out")
qa=$(echo "$row" | cut -d, -f3); qb=$(echo "$row" | cut -d, -f6); ratio=$(echo "$row" | cut -d, -f7)
check ratio_is_qb_over_qa awk -v a="$qa" -v b="$qb" -v r="$ratio" 'BEGIN{exit !(a > 0 && (b/a - r)^2 < 1e-8)}'
check live_case_kept has "$TMP/out" '^case  *C$'
check diff_has_negative_p awk -F, 'NF==8 && $1 ~ /^[-0-9]/ && $8 < 0 {n++} END{exit !(n > 0)}' "$TMP/out"
check list_changes has "$TMP/out" '^bag,A,0,0,bag_p0=121590 bag_membrane=0$'

# each Q is the design's own grid; the difference cell by cell
run -c "$S; case B; grid; grid cells"
qB=$(awk -F, '$1=="B" && NF==11 {print $9; exit}' "$TMP/out")
awk -F, 'NF==8 && $1 ~ /^[-0-9]/ {print $1","$2","$8}' "$TMP/out" | sort >"$TMP/pa"
check q_a_is_grid cond '[ -n "$qa" ] && [ "$qB" = "$qa" ]'
run -c "$S; case A; set bag_model analytic; set bag_p0 1.2 atm; grid; grid cells"
awk -F, 'NF==8 && $1 ~ /^[-0-9]/ {print $1","$2","$8}' "$TMP/out" | sort >"$TMP/pb"
run -c "$S; case B; design save plain; case A; set bag_model analytic; set bag_p0 1.2 atm; design save bag; design compare plain bag; grid cells"
awk -F, 'NF==8 && $1 ~ /^[-0-9]/ {print $1","$2","$8}' "$TMP/out" | sort >"$TMP/pd"
check diff_cellwise awk -F, '
  FILENAME == ARGV[1] {a[$1","$2] = $3; next}
  FILENAME == ARGV[2] {b[$1","$2] = $3; next}
  {k = $1","$2; d = b[k] - a[k]; if ((d - $3)^2 > 1e-6) bad++; n++}
  END {exit !(n > 0 && bad == 0)}' "$TMP/pa" "$TMP/pb" "$TMP/pd"

# a session keeps the designs
run -c "$S; case B; design save plain; case A; set bag_model analytic; set bag_p0 1.2 atm; design save bag; case C; save session $TMP/d.ses"
run -c "source $TMP/d.ses; set format csv; design list; show case"
check session_designs cond '[ $RC -eq 0 ] && grep -q "^plain,B," "$TMP/out" && grep -q "^bag,A,0,0,bag_p0=121590 bag_membrane=0$" "$TMP/out" && grep -q "^case  *C$" "$TMP/out"'

# the difference grid in grid show: its title and the diverging legend
run -c "set step 0.3; case B; design save plain; case A; set bag_model analytic; design save bag; design compare plain bag; grid show"
check show_diff_title has "$TMP/out" '^\(d\|Δ\)P = P_b - P_a in %: '
check show_diff_legend has "$TMP/out" '^legend: none 0 / no contact; safer <=-30 %; safer -30-0 %; riskier 0-30 %; riskier >=30 %$'

# issue 30: an exported difference grid loads back as a difference grid (grid show the same,
# Q = q_b - q_a, its note keeps the mark so that it exports and loads again unchanged)
run -c "set step 0.3; case B; design save plain; case A; set bag_model analytic; design save bag; design compare plain bag; grid show; export grid $TMP/d.csv"
sed -n '/P = P_b - P_a in %/,/^legend/p' "$TMP/out" >"$TMP/show0"
q0=$(sed -n 's/.*Q = Q_b - Q_a = \(-*[0-9.]*\) m^2 over.*/\1/p' "$TMP/out")
run -c "grid load $TMP/d.csv; grid show; export grid $TMP/d2.csv; grid load $TMP/d2.csv; grid show"
check diff_loads cond '[ "$RC" -eq 0 ] && [ ! -s "$TMP/err" ]'
sed -n '/P = P_b - P_a in %/,/^legend/p' "$TMP/out" | head -n "$(lines "$TMP/show0")" >"$TMP/show1"
check diff_load_same_show cond '[ -s "$TMP/show0" ] && cmp -s "$TMP/show0" "$TMP/show1"'
check diff_load_q cond '[ -n "$q0" ] && [ "$(grep -c "Q = Q_b - Q_a = $q0 m^2 over .*source difference P_b - P_a loaded from" "$TMP/out")" -eq 2 ]'
check diff_load_negative_q cond 'echo "$q0" | grep -q "^-0\.[0-9]"'
check diff_round_trip cond 'cmp -s "$TMP/d.csv" "$TMP/d2.csv" &&
  grep -q "\"grid of case A, .*(difference P_b - P_a loaded from .*d.csv)" "$TMP/d2.csv.meta.json"'
# without the mark a negative p is refused, saying what makes a difference grid
grep -v "^#" "$TMP/d.csv" >"$TMP/nomark.csv"
run -c "grid load $TMP/nomark.csv"
check diff_unmarked cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "nomark.csv:[0-9]*: p is -[0-9.e-]*, outside \[0, 1\]; a difference grid (p = P_b - P_a in \[-1, 1\], .design compare.) is marked by a note .... difference P_b - P_a .... in FILE.meta.json beside it, as .export grid. writes it (or a comment .# .... before the header)$"'
# a marked grid still refuses p outside [-1, 1]
sed 's/^\(0\.000,0\.000,1,.*,\)[^,]*$/\1-1.5/' "$TMP/d.csv" >"$TMP/big.csv"
cp "$TMP/d.csv.meta.json" "$TMP/big.csv.meta.json"
run -c "grid load $TMP/big.csv"
check diff_range has "$TMP/err" "big.csv:[0-9]*: p is -1.5, outside \[-1, 1\] (a difference P_b - P_a)$"

# refusals
run -c "design compare x y"
check unknown_design has "$TMP/err" "design compare: no design 'x'"
run -c "design save 1x"
check bad_name has "$TMP/err" "design save: '1x' is not a name; accepted: letters"
run -c "set step 0.3; design save a; set step 0.2; design save b; design compare a b"
check steps_differ has "$TMP/err" "design compare: the designs' grid steps differ (0.3 and 0.2 m)"
run -c "design frob"
check usage has "$TMP/err" "design: usage: design save NAME"

# the viewer shows the difference on a diverging scale (blue: B safer)
if ! command -v tmux >/dev/null 2>&1; then
  skip diff_viewer "tmux is not installed"
  finish
fi
. tests/lib_tmux.sh
start d1 120 40
check d_prompt wait_for d1 'uasimpact\[A\]>'
line d1 "set step 0.3; case B; design save plain; case A; set bag_model analytic; design save bag; design compare plain bag"
check d_compare wait_for d1 'plain +B +0\.[0-9]+ +bag' 20
line d1 "view"
check d_caption wait_for d1 'P = P_b - P_a in % \(blue: b safer, red: b riskier\)'
check d_legend wait_for d1 'P = P_b - P_a: .*<=-30 %.*-30-0 %.*0-30 %.*>=30 %'
# the cursor line holds the differences the grid keeps, and no Nij mode (it has no difference)
check d_cursor_diff wait_for d1 '^dpar 0\.00 m  dperp 0\.00 m  dP -?[0-9.]+ %  dHIC15 -?[0-9.]+  dNij -?[0-9.]+ *$'
grab d1 -e
# a grid row (its dpar label, then cells) holds a blue cell: the legend alone does not count
check d_blue grep -Eq "(^|m) *0\.00 .*$ESC\[([0-9;]*;)?(44|48;5;(25|153))(;[0-9;]*)?m" "$TMP/screen"
keys d1 Enter
check d_inspect_refused wait_for d1 'a difference grid has no impact of its own'
keys d1 q
finish
