# test_plot_kinds.sh: every kind of plot rendered to PNG through the real gnuplot (plot.c and
# plot_cmd.c, plot_sweep.c, plot_history.c, plot_mc.c, plot_bag.c): a wrapper named gnuplot
# first in PATH keeps the script it is sent and runs the real gnuplot on it, so that each test
# checks both the PNG (its signature, not empty) and the labels the script gives it: the
# difference grid's diverging palette and its ΔP, ΔQ; one unit per sweep axis (kPa drawn in
# atm) and a panel for every kind of sweep kept; history's real units, plain legends and one
# channel per quantity; titles of montecarlo and tornado on two lines. Skipped without gnuplot.
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
REAL=$(command -v gnuplot)
if [ -z "$REAL" ]; then
  skip plot_kinds "gnuplot is not installed (Debian: gnuplot-nox)"
  finish
fi
mkdir -p "$TMP/bin" "$TMP/gp"
cat >"$TMP/bin/gnuplot" <<EOS
#!/bin/sh
n=\$(ls "$TMP/gp" | wc -l)
cat >"$TMP/gp/\$n.gp"
cp "$TMP/gp/\$n.gp" "$TMP/gp/last.gp.txt"
if [ "\$1" = -persist ]; then exec "$REAL" -persist "$TMP/gp/\$n.gp"; fi
exec "$REAL" "$TMP/gp/\$n.gp"
EOS
chmod +x "$TMP/bin/gnuplot"
png_ok() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] &&
  [ "$(wc -c <"$1")" -gt 3000 ]; }
# run the commands, then plot KIND into $TMP/NAME.png; the script sent is $TMP/NAME.gp
plot_png() {
  pn=$1; pre=$2; what=$3 # (not 'name': check sets it)
  rm -f "$TMP/gp/last.gp.txt"
  PATH="$TMP/bin:$PATH" "$U" -c "$pre; set terminal png; set output $TMP/$pn.png; plot $what" \
    >"$TMP/out" 2>"$TMP/err"
  RC=$?
  cp "$TMP/gp/last.gp.txt" "$TMP/$pn.gp" 2>/dev/null || : >"$TMP/$pn.gp"
  check "${pn}_png" cond '[ "$RC" -eq 0 ] && png_ok "$TMP/$pn.png"'
}
gp() { grep -q -- "$2" "$TMP/$1.gp"; }

T6=sessions/paper/grids/table06_caseC_wind0.csv
check paper_grid_present [ -r "$T6" ]

# pof: four panels with their titles
plot_png pof "set step 0.3" pof
check pof_panels cond 'gp pof "HIC15 -> P_HIC" && gp pof "Nij -> P_NI" && gp pof "VC -> P_VC"'

# grid: the band palette over 0..100 %, P{F|Delta} and Q in the title
plot_png grid "grid load $T6" grid
check grid_labels cond 'gp grid "P{F|Delta} in %; Q = 0.8469 m^2" && gp grid "set cbrange \[0:100\]" &&
  gp grid "set cblabel \"P{F|Delta} (%)\""'

# a difference grid: diverging palette symmetric about 0, ΔP = P_b − P_a and ΔQ in title and bar
# (the analytic bag here and in the sweeps and montecarlo below: the plots are checked, whatever
# the bag; the membrane bag, A's default at the switch, costs ~10 s CPU per coarse grid)
D="set step 0.3; case B; design save plain; case A; set bag_model analytic; design save bag; design compare plain bag"
plot_png diff "$D" grid
check diff_palette cond 'gp diff "set palette defined (-1 .#2166ac., .*0 .#f7f7f7., .*1 .#b2182b.)" &&
  gp diff "set cbrange \[-[0-9.]*:[0-9.]*\]" && ! gp diff "set cbrange \[0:100\]"'
cbr=$(sed -n 's/^set cbrange \[\(.*\)\]$/\1/p' "$TMP/diff.gp")
check diff_range_symmetric cond '[ "${cbr%%:*}" = "-${cbr#*:}" ]'
check diff_title cond 'gp diff "ΔP = P_b − P_a in %; ΔQ = Q_b − Q_a = -[0-9.]* m^2" &&
  gp diff "set cblabel \"ΔP = P_b − P_a (%)"'

# history: the six derived signals, units in the labels, legends noenhanced
plot_png history "impact 0 0" history
check history_units cond 'gp history "head_acc (g)" && gp history "neck_fz (N)" &&
  gp history "neck_my (N m)" && gp history "chest_defl (mm)"'
check history_plain_legends cond '[ "$(grep -c "^plot .* title .*noenhanced" "$TMP/history.gp")" -eq 6 ]'

# history all: every channel with its real unit (none "(SI)"), no quantity twice
plot_png history_all "impact 0 0" "history all"
check history_all_no_si cond '! gp history_all "(SI)" && gp history_all "head_acc_x (m/s^2)" &&
  gp history_all "bag_bottom_p_p (Pa)"'
check history_all_no_duplicate cond '! gp history_all "neck_load_fz" && ! gp history_all "neck_load_my" &&
  [ "$(grep -c "set ylabel .chest_defl " "$TMP/history_all.gp")" -eq 1 ]'
# a left margin of 14 characters: neck_load_mx's tic labels (-1.5x10^-5) and its y label fit in
# it (12 cut the label at the image's edge; looked at in the PNG)
check history_all_margin cond 'gp history_all "^set lmargin 14$"'
# many rows: small type and two tic intervals a panel, so that neighbouring panels' labels and
# tic marks do not run into each other (the six-signal plot keeps the normal type)
check history_all_small_type cond 'gp history_all "set tics font \",8\"" && ! gp history "set tics font"'
check history_all_plain_legends cond '! grep "^plot " "$TMP/history_all.gp" | grep -v -q "noenhanced"'

# sweep: wind, face and a parameter entered in atm and in kPa: a panel each, one axis in atm
S="set step 0.3; set bag_model analytic; sweep wind 0,4; sweep face 0,90; sweep bag_p0 1.0,1.1 atm; sweep bag_p0 105 kPa"
plot_png sweep_all "$S" sweep
check sweep_all_panels cond 'gp sweep_all "set multiplot layout 1,3" &&
  gp sweep_all "Q against horizontal wind" && gp sweep_all "Q against face direction" &&
  gp sweep_all "Q against bag_p0"'
plot_png sweep_param "$S" "sweep bag_p0"
check sweep_param_axis cond 'gp sweep_param "set xlabel .bag_p0 (atm)." && gp sweep_param "swept in kPa"'
# 105 kPa drawn at 1.036 atm on the atm axis (105000 / 101325)
check sweep_param_converted awk '$1 ~ /^1\.036/ { n++ } END { exit !(n == 1) }' "$TMP/sweep_param.gp"
plot_png sweep_wind "$S" "sweep wind"
check sweep_wind_alone cond '! gp sweep_wind multiplot && gp sweep_wind "horizontal wind speed (m/s)"'

# montecarlo and tornado: two-line titles
M="set step 0.3; set bag_model analytic; dist wind uniform 0 4; set surface_nodes 3; montecarlo 12"
plot_png montecarlo "$M" montecarlo
check montecarlo_title cond 'gp montecarlo "set title \"Q over 12 samples of case A (seed [0-9]*)\\\\nmean "'
plot_png tornado "$M" tornado
check tornado_title cond 'gp tornado "set title \"Variance shares of Q (first-order)\\\\ncase A, 12 samples"'

# bag: the membrane airbag at first contact and at peak pressure
plot_png bag "case A; set bag_model membrane; impact 0 0" bag
check bag_panels cond 'gp bag "at first contact" && gp bag "at peak pressure"'
# every label readable: the z label along its axis (set horizontally left of the tic labels, a
# narrow panel's margin cut it), two panels a row (A2's two bags made four in one row, 400 px
# each: titles ran into each other, z cut), and per panel tic steps that give at most 6 labels
# along x and y over the mesh and head drawn (5 cm steps over 0.8 m ran into each other)
tics_ok() { awk '/^\$M[0-9]+_[0-9]+ << EOD/ { b = substr($1, 2); inb = 1; next }
  /^EOD/ { inb = 0; next }
  inb && NF == 3 { if (!(b in lo)) { lo[b] = hi[b] = $1; ly[b] = hy[b] = $2 }
    if ($1 < lo[b]) lo[b] = $1; if ($1 > hi[b]) hi[b] = $1
    if ($2 < ly[b]) ly[b] = $2; if ($2 > hy[b]) hy[b] = $2; next }
  /^set xtics [0-9.e+-]+$/ { sx = $3 } /^set ytics [0-9.e+-]+$/ { sy = $3 }
  /^splot \$M/ { b = substr($2, 2); n++
    if (!(sx > 0 && sy > 0) || (hi[b] - lo[b]) / sx > 6 || (hy[b] - ly[b]) / sy > 6) bad = 1 }
  END { exit !(n > 0 && !bad) }' "$TMP/$1.gp"; }
check bag_labels cond 'gp bag "set multiplot layout 1,2" && gp bag "size 1600,760" &&
  gp bag "set zlabel .z (m). rotate parallel" && tics_ok bag'
plot_png bag2 "case A2; set bag_model membrane; impact -0.2 0" bag
check bag2_two_bags cond 'gp bag2 "bag_bottom at peak pressure" && gp bag2 "bag_front at first contact" &&
  gp bag2 "set multiplot layout 2,2" && gp bag2 "size 1600,1400" && tics_ok bag2'

ls "$TMP"/*.png | sed 's|.*/|  (rendered: |; s|$|)|'
# KEEP_PNG=DIR keeps the PNGs for a person to look at
[ -n "$KEEP_PNG" ] && mkdir -p "$KEEP_PNG" && cp "$TMP"/*.png "$KEEP_PNG"/
finish
