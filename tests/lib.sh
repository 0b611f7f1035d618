# lib.sh: tiny assertion helpers for shell tests; the closing lines match cmocka's, so the
# test runner counts them the same way.  Use: . tests/lib.sh; check NAME CONDITION...; finish
T_PASS=0; T_FAIL=0; T_FAILED=""
NL='
'
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
UASRISK=${UASRISK:-./uasrisk}

check() {
  name=$1; shift
  if "$@"; then T_PASS=$((T_PASS + 1)); echo "[       OK ] $name"
  else T_FAIL=$((T_FAIL + 1)); T_FAILED="$T_FAILED$NL$name"; echo "[  FAILED  ] $name"; fi
}

# run uasrisk, keeping stdout, stderr and status in $TMP/out, $TMP/err, $RC
run() { "$UASRISK" "$@" >"$TMP/out" 2>"$TMP/err"; RC=$?; }
run_in() { f=$1; shift; "$UASRISK" "$@" <"$f" >"$TMP/out" 2>"$TMP/err"; RC=$?; }

# a compound condition, evaluated in the caller's variables: check NAME cond '[ a ] && [ b ]'
cond() { eval "$1"; }
lines() { wc -l <"$1" | tr -d ' '; }
has() { grep -q -- "$2" "$1"; }

finish() {
  echo "[==========] $((T_PASS + T_FAIL)) test(s) run."
  echo "[  PASSED  ] $T_PASS test(s)."
  if [ "$T_FAIL" -gt 0 ]; then
    echo "[  FAILED  ] $T_FAIL test(s), listed below:"
    echo "$T_FAILED" | sed -n 's/^\(..*\)/[  FAILED  ] \1/p'
    exit 1
  fi
  exit 0
}
