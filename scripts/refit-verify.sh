#!/bin/sh
# refit-verify.sh: 'make refit-verify': the refit's logged optimum reproduces on this build
# (issue 33; uasimpact-model(5), CALIBRATION, "The refit on materials"). Minutes, not make
# check: stage 2's evaluations run case A's 0.05 m grid with the membrane bag at mesh 14.
#   1. stage 2's best row (src/models/refit-bag-log.csv), evaluated once at its point through
#      its own spec, gives that row's losses to the last digit;
#   2. the final point (src/models/refit-total.spec, the two results held) evaluated once gives
#      the row of src/models/refit-total-log.csv to the last digit.
# Stage 1's start and best row are tests/test_refit.sh's (make check). Both run with the
# defaults the fits ran under (src/models/replay.pins, set on top of each spec). Each line says
# PASS or FAIL; the status is the number of failures.
#   scripts/refit-verify.sh [OUTDIR]        (default build/refit-verify)
set -u
CAL=${CALIBRATE:-build/calibrate}
out=${1:-build/refit-verify}
mkdir -p "$out" || exit 1
pins=$(sh scripts/replay-pins.sh) || exit 1
fails=0
verdict() { # NAME OK
  if [ "$2" = 1 ]; then echo "PASS $1"; else echo "FAIL $1"; fails=$((fails + 1)); fi
}
rows() { grep '^[0-9]' "$1" | cut -d, -f2-; }

# 1. stage 2's best row: the spec's start moved to that row's point
spec=src/models/refit-bag.spec log=src/models/refit-bag-log.csv
ncol=$(grep '^eval,' "$log" | tr ',' '\n' | wc -l)
best=$(grep '^[0-9]' "$log" | sort -t, -k"$ncol" -g | head -1)
awk -F, -v hdr="$(grep '^eval,' "$log")" -v row="$best" '
  BEGIN { n = split(hdr, h, ","); split(row, r, ",")
          for (i = 2; i <= n; i++) { split(h[i], p, "/"); v[p[1]] = r[i] } }
  $1 == "free" && ($2 in v) { $5 = v[$2] } { print }' FS=' ' "$spec" >"$out/bag-best.spec"
"$CAL" -e -s "$out/bag-best.spec" -o "$out/bag-best" $pins >"$out/bag-best.out" 2>&1
got=$(rows "$out/bag-best/log.csv" 2>/dev/null)
want=$(printf '%s' "$best" | cut -d, -f2-)
echo "stage 2's best row (evaluation ${best%%,*}): logged $want"
echo "                                  evaluated $got"
verdict "stage 2's best row reproduces its losses, bit for bit" \
  "$([ -n "$got" ] && [ "$got" = "$want" ] && echo 1)"

# 2. the final point
"$CAL" -e -s src/models/refit-total.spec -o "$out/total" $pins >"$out/total.out" 2>&1
got=$(rows "$out/total/log.csv" 2>/dev/null)
want=$(rows src/models/refit-total-log.csv)
echo "the final point: logged $want"
echo "              evaluated $got"
verdict "the final point reproduces its logged losses, bit for bit" \
  "$([ -n "$got" ] && [ "$got" = "$want" ] && echo 1)"
exit "$fails"
