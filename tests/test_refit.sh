# test_refit.sh: the refit on materials (uasimpact-model(5), CALIBRATION, "The refit on
# materials") reproduces from a fresh clone. Stage 1's committed log
# (src/models/refit-drone-log.csv) is what `make refit-drone` writes: its first evaluation comes
# out again (values and losses round-trip at %.17g, so equal text is equal bits; the simplex's
# determinism is test_calibrate.sh's resume), and its best row, evaluated once at that row's
# point, gives that row's losses to the last digit. Stage 1's evaluations run cases B and C on
# their 0.05 m grids (a few seconds each); stage 2's (the membrane bag on case A) take minutes
# and are checked by its resume.
. tests/lib.sh
CAL=${CALIBRATE:-build/calibrate}
# the defaults the fit ran under, set on top of the spec (src/models/replay.pins)
pins=$(sh scripts/replay-pins.sh)
SPEC=src/models/refit-drone.spec
LOG=src/models/refit-drone-log.csv

check "stage 1's log has rows" cond '[ "$(grep -c "^[0-9]" "$LOG")" -gt 1 ]'

# the first evaluation again: the declared spec at its start
"$CAL" -e -s "$SPEC" -o "$TMP/first" $pins >"$TMP/out" 2>"$TMP/err"
check "the fit's start evaluates" cond '[ -s "$TMP/first/log.csv" ]'
# the losses to the last digit; the point as the spec's start (the fit's own row went through
# the logistic coordinates and back: within an ulp or two)
nfree=$(grep -c '^free ' "$SPEC")
losses() { grep "^1," "$1" | cut -d, -f$((nfree + 2))-; }
check "the start's losses as logged, bit for bit" \
  cond '[ -n "$(losses "$LOG")" ] && [ "$(losses "$LOG")" = "$(losses "$TMP/first/log.csv")" ]'
check "the start's point as logged" awk -F, -v n="$nfree" '$1 == 1 { k++
  for (i = 2; i <= n + 1; i++) if (k == 1) v[i] = $i; else { d = $i - v[i]
    if (d < 0) d = -d; if (d > 1e-12 * (v[i] < 0 ? -v[i] : v[i])) exit 1 } }
  END { exit k != 2 }' "$LOG" "$TMP/first/log.csv"
check "the same columns" cond '[ "$(grep "^eval," "$LOG")" = "$(grep "^eval," "$TMP/first/log.csv")" ]'

# the best row: the spec's start moved to that row's point (a share's column is its share)
best=$(grep '^[0-9]' "$LOG" | sort -t, -k"$(grep '^eval,' "$LOG" | tr ',' '\n' | wc -l)" -g | head -1)
awk -F, -v hdr="$(grep '^eval,' "$LOG")" -v row="$best" '
  BEGIN { n = split(hdr, h, ","); split(row, r, ",")
          for (i = 2; i <= n; i++) { split(h[i], p, "/"); v[p[1]] = r[i] } }
  $1 == "free" && ($2 in v) { $5 = v[$2] } { print }' FS=' ' "$SPEC" >"$TMP/best.spec"
"$CAL" -e -s "$TMP/best.spec" -o "$TMP/best" $pins >"$TMP/out" 2>"$TMP/err"
got=$(grep '^[0-9]' "$TMP/best/log.csv" | cut -d, -f2-)
check "the best row reproduces its losses, bit for bit" \
  cond '[ -n "$got" ] && [ "$got" = "$(printf "%s" "$best" | cut -d, -f2-)" ]'
check "the best row is the result's loss" \
  grep -q "best loss $(printf '%.5f' "$(printf '%s' "$best" | awk -F, '{ print $NF }')")" \
  src/models/refit-drone-result.txt
finish
