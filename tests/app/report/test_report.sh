# test_report.sh: report FILE.html after the README's worked example (sessions/study.ses, on
# coarse 0.3 m grids and a 3-node surface to keep it short): every section in reading order,
# every kept result and its settings, every figure an SVG embedded as a data: image that decodes,
# no external reference (no src or href outside the file, no script, no stylesheet link or
# import), text escaped by the serializer (a model part whose comment holds markup), the answer
# quoting the sora result; refusals. Then a real browser: headless Chromium (scripts/setup.sh
# browser; skipped without it) renders the file with networking off to a screenshot and prints
# it to PDF.
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
SES=$(pwd)/sessions/study.ses
H="$TMP/study.html"
(cd "$TMP" && "$U" -c "set step 0.3; set surface_nodes 3; source $SES" >"$TMP/out" 2>"$TMP/err")
RC=$?
check status cond '[ "$RC" -eq 0 ] && [ -s "$H" ] && grep -q "^report: study.html written" "$TMP/err"'

# sections, in reading order
check sections awk 'BEGIN { n = split("question answer evidence warnings assumptions validity appendix", want, " ") }
  { line = $0; while (match(line, /id="[a-z]+"/)) { id = substr(line, RSTART + 4, RLENGTH - 5)
      if (k < n && id == want[k + 1]) k++; line = substr(line, RSTART + RLENGTH) } }
  END { exit k != n }' "$H"
check headings cond 'grep -q ">1. Question<" "$H" && grep -q ">2. Answer<" "$H" && grep -q ">3. Evidence<" "$H" &&
  grep -q ">4. Assumptions<" "$H" && grep -q ">5. Model validity<" "$H" && grep -q ">Appendices<" "$H"'
check validity_parts cond 'grep -q "5.1 The paper.s Table 17" "$H" && grep -q "5.2 Numerical convergence" "$H" &&
  grep -q "5.3 Physics the test suite proves" "$H" && grep -q "5.4 Known limits" "$H" &&
  grep -q "test_sora25.c" "$H"'
# every kept result (15 tables): grid, sweep, grid, design compare, risk (2), montecarlo, shares,
# sora (3 tables), sora mc (3 tables), converge
check results cond '[ "$(grep -o "id=\"result-[0-9]*\"" "$H" | wc -l)" -eq 15 ]'
check commands cond 'for c in "grid" "sweep wind 0,2,4,6,8,10" "design compare unmitigated with_devices" \
  "risk" "montecarlo 200" "montecarlo shares" "sora" "sora mc" "converge"; do
  grep -q "<code>$c</code>" "$H" || exit 1; done'
check settings cond 'grep -q "id=\"settings-1\"" "$H" && grep -q "href=\"#settings-1\"" "$H"'
check model_texts cond 'grep -q "FNV-1a 64 [0-9a-f]\{16\}" "$H" && grep -q "^param dt" "$H"'
check answer cond 'grep -q "Intrinsic ground-risk class for the submission (SORA 2.5 Table 2" "$H" &&
  grep -q "M2 evidence: Q is reduced by a factor" "$H" && grep -q "Risk per flight hour, eq. (1.1)" "$H" &&
  grep -q "Convergence (changes as fractions of the finer result): halving the grid step" "$H"'

# figures: grids of A, C and the difference, the sweeps, the montecarlo histogram and shares
NFIG=$(grep -o "<figure" "$H" | wc -l)
NIMG=$(grep -o "<img src=\"data:image/svg+xml;base64,[A-Za-z0-9+/=]*\"" "$H" | wc -l)
check figures cond '[ "$NFIG" -eq 6 ] && [ "$NIMG" -eq 6 ] && ! grep -q "figure not drawn" "$H"'
grep -o "data:image/svg+xml;base64,[A-Za-z0-9+/=]*" "$H" | sed 's/^data:image\/svg+xml;base64,//' >"$TMP/b64"
check svg_decode cond 'n=0; while read -r b; do printf "%s" "$b" | base64 -d >"$TMP/f.svg" 2>/dev/null &&
  grep -q "<svg" "$TMP/f.svg" && grep -q "</svg>" "$TMP/f.svg" && ! grep -qi "<script\|xlink:href=\"http" "$TMP/f.svg" ||
  exit 1; n=$((n + 1)); done <"$TMP/b64"; [ "$n" -eq 6 ]'
check cell_tables cond '[ "$(grep -c "class=\"cells\"" "$H")" -ge 1 ]'

# nothing outside the file
check no_external cond '! grep -Eo "(src|href)=\"[^\"]*\"" "$H" | grep -Ev "^(src=\"data:image/svg\+xml;base64,|href=\"#)"'
check no_script cond '! grep -qi "<script\|<link\|<iframe\|<object\|@import\|url(" "$H"'

# text escaped by the serializer: markup in a model part's comment stays text
printf '# a part with <script>alert(1)</script> & "quotes" in a comment\nparam extra_x 1 m\n' >"$TMP/x.urm"
run -c "model load $TMP/x.urm; set step 0.3; grid; report $TMP/x.html"
check escaped cond '[ "$RC" -eq 0 ] && grep -q "&lt;script&gt;alert(1)&lt;/script&gt; &amp;" "$TMP/x.html" &&
  ! grep -qi "<script" "$TMP/x.html"'
# text that is not UTF-8 (a model file in Latin-1, a control byte): each bad byte becomes U+FFFD,
# nothing from libxml2 reaches the terminal, the rest of the text stays
printf '# caf\351 au lait \001 in Latin-1\nparam extra_y 1 m\n' >"$TMP/l1.urm"
run -c "model load $TMP/l1.urm; report $TMP/l1.html"
check latin1 cond '[ "$RC" -eq 0 ] && grep -q "caf&#65533; au lait &#65533; in Latin-1" "$TMP/l1.html" &&
  ! grep -qi "error" "$TMP/err"'
# warnings gathered: a grid on set extents
run -c "set step 0.3; set along_min -0.3; grid; report $TMP/w.html"
check warnings cond '[ "$RC" -eq 0 ] && grep -q "<li>grid: extents set: Q covers only" "$TMP/w.html" &&
  grep -q "class=\"warnbox\"" "$TMP/w.html"'
# Table 17 stands beside the paper's values only grids at its conditions (any step and descent):
# not B at pitch 20, not a sweep of bag_p0, not A with bag_p0 set (each was quoted before)
run -c "case B; set step 0.3; set wind 10; set p_chute 0.9; grid; set pitch 20; grid; set pitch 0;
  case A; set wind 0; set descent paper; grid; sweep bag_p0 1.5 atm; sweep wind 4; set bag_p0 1.2 atm;
  sweep wind 10; report $TMP/t17.html"
t17() { tr -d '\n' <"$TMP/t17.html" | grep -o "<tr><td>$1</td><td>$2</td><td>[^<]*</td><td>[^<]*</td>" |
  sed 's/.*<td>//; s/<.td>$//'; }
q() { awk -v c="$1" -v s="$2" -v k="$3" 'NF == 11 && $1 == c && $6 == s && ++n == k { print $9 }' "$TMP/out"; }
check table17_paper_only cond '[ "$RC" -eq 0 ] && [ -n "$(q B 0.3 1)" ] && [ "$(q B 0.3 1)" != "$(q B 0.3 2)" ] &&
  [ "$(t17 B 10)" = "$(q B 0.3 1)" ] && [ "$(t17 A 0)" = "$(q A 0.3 1)" ] && [ "$(t17 A 4)" != none ] &&
  [ "$(t17 A 10)" = none ]'
# its step column: a grid's own, and a sweep's (whose rows have no step: the settings it ran
# under; it was empty before)
t17step() { tr -d '\n' <"$TMP/t17.html" | grep -o "<tr><td>$1</td><td>$2</td>\(<td>[^<]*</td>\)\{5\}" |
  sed 's/.*<td>//; s/<.td>$//'; }
check table17_step cond '[ "$(t17step B 10)" = 0.3 ] && [ "$(t17step A 0)" = 0.3 ] && [ "$(t17step A 4)" = 0.3 ]'
# nothing computed: a report that says so
run -c "report $TMP/empty.html"
check empty cond '[ "$RC" -eq 0 ] && grep -q "The session computed no result" "$TMP/empty.html" &&
  grep -q "No SORA answer: the session ran no sora" "$TMP/empty.html"'
run -c 'report'
check no_file cond '[ "$RC" -eq 1 ] && has "$TMP/err" "report: wrong number of arguments"'
run -c "report $TMP"
check dir cond '[ "$RC" -eq 1 ] && has "$TMP/err" "report: cannot write"'

# a real browser, without network
if command -v chromium >/dev/null 2>&1; then
  CH="chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --proxy-server=127.0.0.1:9
    --proxy-bypass-list=<-loopback> --user-data-dir=$TMP/chrome"
  $CH --window-size=1100,3000 --screenshot="$TMP/shot.png" "file://$H" >/dev/null 2>&1
  check screenshot cond '[ "$(head -c 8 "$TMP/shot.png" | od -An -tx1 | tr -d " \n")" = "89504e470d0a1a0a" ] &&
    [ "$(wc -c <"$TMP/shot.png")" -gt 100000 ]'
  $CH --dump-dom "file://$H" >"$TMP/dom.html" 2>/dev/null
  check dom cond '[ "$(grep -o "<figure" "$TMP/dom.html" | wc -l)" -eq 6 ] && grep -q "id=\"appendix\"" "$TMP/dom.html"'
  $CH --no-pdf-header-footer --print-to-pdf="$TMP/study.pdf" "file://$H" >/dev/null 2>&1
  check pdf cond '[ "$(head -c 4 "$TMP/study.pdf")" = "%PDF" ] && [ "$(wc -c <"$TMP/study.pdf")" -gt 50000 ]'
  [ -n "$KEEP_SHOT" ] && cp "$TMP/shot.png" "$KEEP_SHOT"
else
  skip browser "chromium missing: scripts/setup.sh browser"
fi

# the model texts name a loaded file as it is found from the report's folder (as save session
# does): relative to it when the model is in it or below, else absolute
mkdir -p "$TMP/w/m" "$TMP/w/out" "$TMP/w/far"
cp sessions/quad/quad.urm "$TMP/w/m/quad.urm"
(cd "$TMP/w" && "$U" -c 'model drop airbags; model drop ra3; model load m/quad.urm; report out/r.html; report r.html; report far/../r2.html' >"$TMP/out" 2>"$TMP/err")
RC=$?
check model_path_below cond '[ "$RC" -eq 0 ] && grep -q "<h4>quad (m/quad.urm, FNV" "$TMP/w/r.html" &&
  grep -q "<h4>quad (m/quad.urm, FNV" "$TMP/w/r2.html"'
check model_path_elsewhere cond 'grep -q "<h4>quad ($TMP/w/m/quad.urm, FNV" "$TMP/w/out/r.html" ||
  grep -q "<h4>quad ($(cd "$TMP/w/m" && pwd -P)/quad.urm, FNV" "$TMP/w/out/r.html"'
[ "$RC" -eq 0 ] || cat "$TMP/err"

finish
