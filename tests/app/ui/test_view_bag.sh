#!/bin/sh
# test_view_bag.sh: the viewer's cell inspection shows the cell's airbags (issue 32), in tmux:
# on the paper's Table 4 (case A, zero wind) with the membrane bag, Enter at the centre cell
# runs its impact and the panel lists the bag (peak gauge pressure, volume lost, peak strain,
# force on the person, bottoming) with the values 'history' then prints for that impact; b in
# the panel and b on the grid draw 'plot bag' for the cell through gnuplot (a PNG, checked
# complete), and the key help says so; with the analytic bag the panel says analytic, and
# without airbags (case C) the panel has no bag lines and b says why in one line.
. tests/lib.sh

T4=sessions/paper/grids/table04_caseA_wind0.csv
check paper_grid_present [ -r "$T4" ]
if ! command -v tmux >/dev/null 2>&1; then
  skip viewer_bag_checks "tmux is not installed"
  finish
fi
. tests/lib_tmux.sh

start b1 160 50
check prompt wait_for b1 'uasimpact\[A\]>'
line b1 "case A; set bag_model membrane; grid load $T4; set terminal png; set output $TMP/bag.png; view"
# the membrane bag inflates once before the viewer opens: seconds, a minute under the sanitizers
check keys_help wait_for b1 'Enter inspect  p plot  b bag  q back' 300
check centre wait_for b1 'dpar 0.00 m  dperp 0.00 m'
keys b1 Enter
check panel_bag wait_for b1 'bag_bottom \(membrane\): peak [0-9.]+ kPa gauge at [0-9.]+ ms' 60
check panel_volume wait_for b1 'volume -[0-9.]+ L \(-[0-9.]+ %\), peak fabric strain [0-9.]+ %'
check panel_force wait_for b1 'peak force on the person [0-9.]+ kN at [0-9.]+ ms'
KPA=$(sed -n 's/.*bag_bottom (membrane): peak \([0-9.]*\) kPa gauge.*/\1/p' "$TMP/screen")
STR=$(sed -n 's/.*peak fabric strain \([0-9.]*\) %.*/\1/p' "$TMP/screen")
check panel_bottoming wait_for b1 '(not )?bottomed: '
check panel_keys wait_for b1 'p plot in gnuplot   b bag plot   any other key closes'
check panel_trace wait_for b1 'head acceleration vs time'
keys b1 Escape
keys b1 q
check left_panel wait_for b1 'uasimpact\[A[^]]*\]> *$'
# the inspected cell's impact is the last impact: 'history' prints the panel's values
line b1 "set format csv; history"
check history_shown wait_for b1 '^bag_bottom_p_strain,'
PP=$(sed -n 's/^bag_bottom_p_p,\([^,]*\),.*/\1/p' "$TMP/screen")
SP=$(sed -n 's/^bag_bottom_p_strain,\([^,]*\),.*/\1/p' "$TMP/screen")
echo "  (panel: $KPA kPa, strain $STR %; history: $PP Pa, strain $SP)"
check panel_is_history cond '[ -n "$KPA" ] && [ "$KPA" = "$(awk -v p="$PP" "BEGIN { printf \"%.1f\", (p - 101325) / 1e3 }")" ] &&
  [ "$STR" = "$(awk -v s="$SP" "BEGIN { printf \"%.1f\", 100 * s }")" ]'
line b1 "set format table"
line b1 "view"
check view_again wait_for b1 'Enter inspect  p plot  b bag  q back'
keys b1 Enter
check panel_again wait_for b1 'bag_bottom \(membrane\): peak [0-9.]+ kPa gauge' 60
keys b1 b
check panel_b_plot wait_for b1 "plot bag: wrote $TMP/bag.png" 60
png_magic() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; }
if command -v gnuplot >/dev/null 2>&1; then
  check bag_png cond 'png_magic "$TMP/bag.png" && [ "$(wc -c <"$TMP/bag.png")" -gt 10000 ]'
else
  skip bag_png "gnuplot is not installed"
fi
# b on the grid: another cell, its impact run first, then its bag plotted
rm -f "$TMP/bag.png"
keys b1 Right
check moved wait_for b1 'dpar 0.00 m  dperp 0.05 m'
keys b1 b
check grid_b_plot wait_for b1 "plot bag: wrote $TMP/bag.png" 60
keys b1 q
check left wait_for b1 'uasimpact\[A[^]]*\]> *$'

# the analytic bag: said so in the panel, and b says there is no membrane bag
line b1 "set bag_model analytic; view"
check analytic_view wait_for b1 'Enter inspect  p plot  b bag  q back'
keys b1 Enter
check panel_analytic wait_for b1 'bag_bottom \(analytic\): peak [0-9.]+ kPa gauge' 60
keys b1 b
check analytic_b wait_for b1 "plot bag: no membrane airbag touched the person in the last impact" 30
keys b1 q

# no airbag (case C): no bag lines in the panel
line b1 "case C; view"
check c_view wait_for b1 'Enter inspect  p plot  b bag  q back'
keys b1 Enter
check c_panel wait_for b1 'head acceleration vs time' 60
check c_no_bag cond '! grep -q "(membrane)\|(analytic)" "$TMP/screen"'
keys b1 Escape
keys b1 q
check alive_at_end alive b1
finish
