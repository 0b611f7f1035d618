# lib.sh: tiny assertion helpers for shell tests; the closing lines match cmocka's, so the
# test runner counts them the same way.  Use: . tests/lib.sh; check NAME CONDITION...; finish
# A check that cannot run on this machine (a tool that is not installed) is declared with
# skip NAME REASON: it is counted and listed as skipped, never silently left out. Data of the
# repository (sessions/paper) is never a reason to skip: check that it is there instead.
T_PASS=0; T_FAIL=0; T_FAILED=""; T_SKIP=0; T_SKIPPED=""
NL='
'
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
UASIMPACT=${UASIMPACT:-./uasimpact}

check() {
  name=$1; shift
  if "$@"; then T_PASS=$((T_PASS + 1)); echo "[       OK ] $name"
  else T_FAIL=$((T_FAIL + 1)); T_FAILED="$T_FAILED$NL$name"; echo "[  FAILED  ] $name"; fi
}

# skip NAME REASON: the checks under NAME cannot run here (counted as one skipped test)
skip() {
  T_SKIP=$((T_SKIP + 1)); T_SKIPPED="$T_SKIPPED$NL$1 ($2)"; echo "[  SKIPPED ] $1 ($2)"
}

# run uasimpact, keeping stdout, stderr and status in $TMP/out, $TMP/err, $RC
run() { "$UASIMPACT" "$@" >"$TMP/out" 2>"$TMP/err"; RC=$?; }
run_in() { f=$1; shift; "$UASIMPACT" "$@" <"$f" >"$TMP/out" 2>"$TMP/err"; RC=$?; }

# waiting_in PID RE: wait (up to 60 s) until process PID sleeps in a kernel function matching
# the extended regular expression RE (/proc/PID/wchan: wait_for_partner opening a FIFO,
# anon_pipe_read or pipe_read reading one), so that a signal meets it there and not while it
# starts up; where /proc does not say, 0.5 s
waiting_in() { _n=0
  while [ "$_n" -lt 600 ]; do
    _w=$(cat "/proc/$1/wchan" 2>/dev/null) || { sleep 0.5; return 0; }
    echo "$_w" | grep -Eqx "$2" && return 0
    sleep 0.1; _n=$((_n + 1))
  done
}

# a compound condition, evaluated in the caller's variables: check NAME cond '[ a ] && [ b ]'
cond() { eval "$1"; }
lines() { wc -l <"$1" | tr -d ' '; }
has() { grep -q -- "$2" "$1"; }

finish() {
  echo "[==========] $((T_PASS + T_FAIL)) test(s) run."
  echo "[  PASSED  ] $T_PASS test(s)."
  if [ "$T_SKIP" -gt 0 ]; then
    echo "[  SKIPPED ] $T_SKIP test(s), listed below:"
    echo "$T_SKIPPED" | sed -n 's/^\(..*\)/[  SKIPPED ] \1/p'
  fi
  if [ "$T_FAIL" -gt 0 ]; then
    echo "[  FAILED  ] $T_FAIL test(s), listed below:"
    echo "$T_FAILED" | sed -n 's/^\(..*\)/[  FAILED  ] \1/p'
    exit 1
  fi
  exit 0
}
