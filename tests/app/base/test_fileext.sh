# test_fileext.sh: a writer of one format refuses a file name whose extension names another
# (src/app/base/fileext.c, case/output.c's ura_name_fits, ui/plot_file.c's ura_plot_name_check):
# report writes HTML, export CSV, save session and model save their own texts, plot the format of
# its terminal. Each refusal is one line naming the name, what its extension says, what the
# writer writes and what it accepts, and writes nothing; the accepted names, a name without an
# extension and one whose extension names no format are written as before.
. tests/lib.sh

# report x.txt: refused, nothing written; report x.html and x.HTML (case ignored) written
run -c "report $TMP/r.txt"
check report_txt cond '[ "$RC" -eq 1 ] && [ ! -e "$TMP/r.txt" ] &&
  has "$TMP/err" "report: the extension of .*r.txt. says text, but report writes HTML; accepted: a name ending in .html, .htm or .xhtml, or one whose extension names no other format$"'
[ "$RC" -eq 1 ] || cat "$TMP/err"
run -c "report $TMP/r.html; report $TMP/R.HTML; report $TMP/r; report $TMP/r.out"
check report_html cond '[ "$RC" -eq 0 ] && grep -q "<html" "$TMP/r.html" && grep -q "<html" "$TMP/R.HTML" &&
  grep -q "<html" "$TMP/r" && grep -q "<html" "$TMP/r.out"'
[ "$RC" -eq 0 ] || cat "$TMP/err"

# export writes CSV: .json and .html refused, .csv and .txt taken
run -c "case B; set step 0.4; sweep wind 0; export sweep $TMP/e.json"
check export_json cond '[ "$RC" -eq 1 ] && [ ! -e "$TMP/e.json" ] &&
  has "$TMP/err" "export: the extension of .*e.json. says JSON, but export writes CSV; accepted: a name ending in .csv or .txt"'
run -c "case B; set step 0.4; sweep wind 0; export sweep $TMP/e.txt; export sweep $TMP/e.csv"
check export_csv cond '[ "$RC" -eq 0 ] && head -n 1 "$TMP/e.txt" | grep -q "^case,sweep,wind," && cmp -s "$TMP/e.txt" "$TMP/e.csv"'
[ "$RC" -eq 0 ] || cat "$TMP/err"

# save session and model save: each its own text, not the other's
run -c "save session $TMP/s.urm"
check session_urm cond '[ "$RC" -eq 1 ] && [ ! -e "$TMP/s.urm" ] &&
  has "$TMP/err" "save session: the extension of .*s.urm. says model, but save session writes a script of commands; accepted: a name ending in .ses or .txt"'
run -c "model save $TMP/m.ses"
check model_ses cond '[ "$RC" -eq 1 ] && [ ! -e "$TMP/m.ses" ] &&
  has "$TMP/err" "model save: the extension of .*m.ses. says session, but model save writes model-language text; accepted: a name ending in .urm or .txt"'
run -c "save session $TMP/s.ses; save session $TMP/s.txt; model save $TMP/m.urm; model save $TMP/m.txt"
check own_texts cond '[ "$RC" -eq 0 ] && grep -q "^reset$" "$TMP/s.ses" && cmp -s "$TMP/s.ses" "$TMP/s.txt" &&
  grep -q "^part human" "$TMP/m.urm" && cmp -s "$TMP/m.urm" "$TMP/m.txt"'

# plot: the output's extension against the terminal's format, checked when plot writes (either
# may be set first); refused before gnuplot runs, so no gnuplot is needed for the refusals
run -c "set terminal png; set output $TMP/p.svg; plot pof"
check plot_svg_png cond '[ "$RC" -eq 1 ] && [ ! -e "$TMP/p.svg" ] &&
  has "$TMP/err" "plot pof: the extension of output .*p.svg. says SVG, but terminal .png. writes PNG; accepted: a name ending in .png, or set terminal svg$"'
run -c "set output $TMP/p.png; set terminal dumb; plot pof"
check plot_png_dumb cond '[ "$RC" -eq 1 ] &&
  has "$TMP/err" "says PNG, but terminal .dumb. writes text; accepted: a name ending in .txt, or set terminal png$"'
if command -v gnuplot >/dev/null 2>&1; then
  run -c "set terminal pngcairo; set output $TMP/p.PNG; plot pof; set terminal dumb; set output $TMP/p.txt; plot pof"
  check plot_fits cond '[ "$RC" -eq 0 ] && [ -s "$TMP/p.PNG" ] && [ -s "$TMP/p.txt" ]'
  [ "$RC" -eq 0 ] || cat "$TMP/err"
else
  skip plot_fits "gnuplot is not installed"
fi
finish
