#!/bin/sh
# runtests.sh: run every test binary given and every shell test (tests/test_*.sh and
# tests/*/.../test_*.sh, the folders mirroring the sources), then list the skipped tests
# and print one closing line "N passed, N failed, N skipped". Exit status is non-zero when any
# test failed or a test program crashed, and, with NOSKIP=1 in the environment ('make check
# NOSKIP=1'), when any test was skipped.
# cmocka binaries print "[  PASSED  ] N test(s).", "[  SKIPPED ] N test(s), listed below:" and
# "[  FAILED  ] N test(s), listed below:", each list followed by one line per test; shell tests
# print the same lines through tests/lib.sh (its skip NAME REASON). A test skips only what this
# machine cannot run (a tool that is not installed); the repository's own data is never a reason.
passed=0; failed=0; skipped=0
log=$(mktemp); skips=$(mktemp); trap 'rm -f "$log" "$skips"' EXIT
for t in "$@" $(find tests -name 'test_*.sh' -type f | LC_ALL=C sort); do
  [ -e "$t" ] || continue
  echo "== $t"
  case "$t" in *.sh) sh "$t" >"$log" 2>&1 ;; *) "$t" >"$log" 2>&1 ;; esac
  rc=$?
  cat "$log"
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test(s), listed below.*/\1/p' "$log" | tail -1)
  s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test(s), listed below.*/\1/p' "$log" | tail -1)
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
done
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
