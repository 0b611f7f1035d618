# test_report_fig.sh: the heat map of a grid, in the report and from plot grid to an SVG, draws
# each cell as its own filled rectangle, not as one bitmap that a browser or PDF reader scales
# smoothly (which blended neighbouring cells into colours of no band, so that a dossier showed a
# blurred footprint); the report's colour bar is ticked at the band edges (5, 30, 90 %) as plot
# grid's is; the line saying what was written counts in words. Case C on a coarse 0.2 m grid:
# a second or two.
. tests/lib.sh

if ! command -v gnuplot >/dev/null 2>&1; then
  skip report_fig "gnuplot is not installed"
  finish
fi
U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
(cd "$TMP" && "$U" -c "case C; set step 0.2; grid; report r.html; set output g.svg; plot grid" \
  >"$TMP/out" 2>"$TMP/err")
RC=$?
check status cond '[ "$RC" -eq 0 ] && [ -s "$TMP/r.html" ] && [ -s "$TMP/g.svg" ]'
# what was written, in words (it said "1 figures' grids")
check written_line grep -q "^report: r.html written (1 result, 1 grid drawn, 1 warning)$" "$TMP/err"

# the report's first figure is the grid's heat map: decode it
grep -o 'data:image/svg+xml;base64,[A-Za-z0-9+/=]*' "$TMP/r.html" | head -1 |
  sed 's|^data:image/svg+xml;base64,||' | base64 -d >"$TMP/fig.svg" 2>/dev/null
check report_figure cond 'grep -q "<svg" "$TMP/fig.svg" && grep -q "Q = 0.[0-9]* m^2" "$TMP/fig.svg"'
# no bitmap: every cell a filled shape of its own
check report_cells_not_bitmap cond '! grep -q "<image" "$TMP/fig.svg"'
check plot_svg_cells_not_bitmap cond '! grep -q "<image" "$TMP/g.svg"'
# the colour bar's ticks are the band edges, as in plot grid
for t in 5 30 90; do
  check "report_cbtic_$t" grep -q "> $t</tspan>" "$TMP/fig.svg"
done
check report_xlabel grep -q "cross offset dperp (m), + left of the course" "$TMP/fig.svg"
finish
