# test_calibrate.sh: 'make calibrate' (src/tools/calibrate.c): one evaluation's log row (every
# free parameter at its start, each case's loss and HIC share, the discrete choices, the total =
# the parts plus the HIC-share shortfalls), a setting that changes the loss, a malformed spec
# named by file and line, and the man page declaring every free parameter of the spec; make
# check-san builds and uses a sanitized calibrate of its own
. tests/lib.sh
CAL=${CALIBRATE:-build/calibrate}
SPEC=src/models/calibrate.spec

"$CAL" -e -o "$TMP/a" >"$TMP/out" 2>"$TMP/err"; RC=$?
L=$TMP/a/log.csv
check "one evaluation" cond '[ "$RC" -eq 0 ] && [ "$(lines "$L")" -eq 2 ]'
nfree=$(grep -c '^free ' "$SPEC")
check "log header" awk -F, -v n="$nfree" 'NR == 1 { exit !($1 == "eval" && NF == 1 + n + 2 * 3 + 2 &&
  $(n + 2) == "loss_C" && $NF == "loss") }' "$L"
check "start values logged" awk -F, 'NR == 1 { for (i = 2; i <= NF; i++) name[i] = $i }
  NR == 2 { for (i = 2; i <= NF; i++) v[name[i]] = $i }
  END { while ((getline l < "'"$SPEC"'") > 0) { split(l, w, " ")
          if (w[1] == "free" && v[w[2]] + 0 != w[5] + 0) exit 1 } }' "$L"
# the total: the parts plus the shortfall of HIC's share below the spec's bound where held
share=$(awk '$1 == "hic_share" { print $2 }' "$SPEC")
check "total = parts + shortfalls" awk -F, -v n="$nfree" -v s="$share" 'NR == 2 {
  t = 0; for (k = 0; k < 3; k++) { p = $(n + 2 + 2 * k); h = $(n + 3 + 2 * k); t += p
    if (k > 0 && h < s) t += s - h }
  d = t - $NF; exit !(d < 1e-5 && d > -1e-5) }' "$L"
check "result lines" cond '[ "$(grep -c "^set " "$TMP/a/result.txt")" -eq "$nfree" ] &&
  grep -q "^# injury choices: [a-z]*+[a-z]*+[a-z]*$" "$TMP/a/result.txt"'

# a setting on top moves the loss
"$CAL" -e -o "$TMP/b" foam_t=0.02 >/dev/null 2>&1
check "a setting changes the loss" cond '[ "$(tail -1 "$TMP/b/log.csv" | cut -d, -f1)" = 1 ] &&
  [ "$(tail -1 "$L" | awk -F, "{print \$NF}")" != "$(tail -1 "$TMP/b/log.csv" | awk -F, "{print \$NF}")" ]'

# a malformed spec: FILE:LINE: message, status 1
printf 'case C 40.6 x.csv\nfree arm_k 2000 1000 6000\n' >"$TMP/bad.spec"
"$CAL" -e -s "$TMP/bad.spec" -o "$TMP/c" >"$TMP/out" 2>"$TMP/err"; RC=$?
check "malformed spec" cond '[ "$RC" -eq 1 ] && has "$TMP/err" "bad.spec:2: expected free NAME LO HI START"'

# the man page's CALIBRATION section declares each free parameter of the spec
sed -n '/^\.SS Free parameters/,/^\.SS Discrete/p' man/uasimpact-model.5 >"$TMP/decl"
ok=1
for name in $(awk '$1 == "free" { print $2 }' "$SPEC"); do
  grep -q "^\.BR\{0,1\} .*\b$name\b" "$TMP/decl" || { echo "not declared: $name"; ok=0; }
done
check "every free parameter declared in uasimpact-model(5)" [ "$ok" -eq 1 ]

# issue 30: 'make check-san' on a fresh clone (no build/calibrate: only 'make check' makes it)
# builds the sanitized tool and hands it to this test as CALIBRATE (make -n: nothing is built)
if command -v make >/dev/null 2>&1; then
  env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -nB check-san >"$TMP/san" 2>&1
  check "check-san builds its calibrate" grep -q -- " -o build-san/calibrate src/tools/calibrate.c " "$TMP/san"
  check "check-san runs the tests on it" grep -q '^UASIMPACT=$b/uasimpact CALIBRATE=$b/calibrate TEST_TIMES=$b/test-times sh scripts/runtests.sh' scripts/check-san.sh
else
  skip "check-san builds its calibrate" "make is not installed"
fi
finish
