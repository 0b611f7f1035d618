#!/bin/sh
# runtests.sh: run every test binary given and every shell test (tests/test_*.sh and
# tests/*/.../test_*.sh, the folders mirroring the sources), then list the skipped tests
# and print one closing line "N passed, N failed, N skipped". Exit status is non-zero when any
# test failed or a test program crashed, and, with NOSKIP=1 in the environment ('make check
# NOSKIP=1'), when any test was skipped.
# Tests run TEST_JOBS at a time (default: the number of processors), each into a log of its own;
# the logs are printed in the tests' order as they finish, each with its time. With TEST_TIMES=FILE the
# times are kept there and the next run starts the slowest tests first (the order of the report
# does not change). Every test is written to run beside others: its own temporary directory, its
# own tmux server.
# cmocka binaries print "[  PASSED  ] N test(s).", "[  SKIPPED ] N test(s), listed below:" and
# "[  FAILED  ] N test(s), listed below:", each list followed by one line per test; shell tests
# print the same lines through tests/lib.sh (its skip NAME REASON). A test skips only what this
# machine cannot run (a tool that is not installed); the repository's own data is never a reason.
passed=0; failed=0; skipped=0
jobs=${TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
skips=$dir/skips

# the tests in report order, numbered; then the run order: slowest first by the last run's times
n=0
for t in "$@" $(find tests -name 'test_*.sh' -type f | LC_ALL=C sort); do
  [ -e "$t" ] || continue
  n=$((n + 1))
  printf '%d %s\n' "$n" "$t"
done >"$dir/list"
if [ -n "${TEST_TIMES:-}" ] && [ -s "$TEST_TIMES" ]; then
  awk 'NR == FNR { s[$2] = $1; next } { print (($2 in s) ? s[$2] : 1e9), $1, $2 }' \
    "$TEST_TIMES" "$dir/list" | sort -k1,1gr | cut -d' ' -f2- >"$dir/order"
else
  cp "$dir/list" "$dir/order"
fi

# report in order, each test as soon as it has finished (in the background: the tests run in
# the foreground, where a background job's ignored SIGINT cannot reach them)
report() {
  : >"$dir/times"
  while read -r k t; do
    log=$dir/$k.log
    while [ ! -e "$dir/$k.time" ] && [ ! -e "$dir/done" ]; do sleep 0.2; done
    echo "== $t"
    cat "$log" 2>/dev/null
    rc=$(cat "$dir/$k.rc" 2>/dev/null || echo 1)
    secs=$(cat "$dir/$k.time" 2>/dev/null || echo 0)
    echo "   ($secs s)"
    echo "$secs $t" >>"$dir/times"
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" 2>/dev/null | tail -1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test(s), listed below.*/\1/p' "$log" 2>/dev/null | tail -1)
    s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test(s), listed below.*/\1/p' "$log" 2>/dev/null | tail -1)
    p=${p:-0}; f=${f:-0}; s=${s:-0}
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
      echo "runtests: $t exited with status $rc"; f=1
    fi
    if [ "$s" -gt 0 ]; then
      # the names after the count line (cmocka prints each skipped test once there)
      sed -n '/^\[  SKIPPED \] [0-9]* test(s), listed below/,$s/^\[  SKIPPED \] \(.*\)/\1/p' \
        "$log" | sed 1d | head -n "$s" | sed "s|^|  $t: |" >>"$skips"
    fi
    passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + s))
  done <"$dir/list"
  echo "$passed $failed $skipped" >"$dir/totals"
}
: >"$skips"
report &
reporter=$!

# run: each test into DIR/K.log, its status into DIR/K.rc, its seconds into DIR/K.time (written
# last, whole)
export dir
xargs -P "$jobs" -L 1 sh -c '
  s=$(date +%s.%N)
  case "$1" in *.sh) sh "$1" ;; *) "$1" ;; esac >"$dir/$0.log" 2>&1
  echo $? >"$dir/$0.rc"
  e=$(date +%s.%N)
  echo "$s $e" | awk "{ printf \"%.1f\n\", \$2 - \$1 }" >"$dir/$0.t"
  mv "$dir/$0.t" "$dir/$0.time"
' <"$dir/order"
touch "$dir/done"
wait "$reporter"
read -r passed failed skipped <"$dir/totals" || { passed=0; failed=1; skipped=0; }
if [ -n "${TEST_TIMES:-}" ]; then
  cp "$dir/times" "$TEST_TIMES" 2>/dev/null || true
fi
echo "slowest tests (s, $jobs at a time):"
sort -k1,1gr "$dir/times" | head -5 | sed 's/^/  /'
if [ "$skipped" -gt 0 ]; then
  echo "skipped (not run on this machine):"
  cat "$skips"
fi
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ] || exit 1
if [ "$skipped" -gt 0 ] && [ "${NOSKIP:-0}" = 1 ]; then
  echo "runtests: NOSKIP=1: $skipped test(s) skipped"
  exit 1
fi
exit 0
