#!/bin/sh
# runtests.sh: run every test binary given and every tests/test_*.sh, then print one closing line
# "N passed, N failed". Exit status is non-zero when any test failed or a test program crashed.
# cmocka binaries print "[  PASSED  ] N test(s)." and "[  FAILED  ] N test(s), listed below:";
# shell tests print the same two lines through tests/lib.sh.
passed=0; failed=0
log=$(mktemp); trap 'rm -f "$log"' EXIT
for t in "$@" tests/test_*.sh; do
  [ -e "$t" ] || continue
  echo "== $t"
  case "$t" in *.sh) sh "$t" >"$log" 2>&1 ;; *) "$t" >"$log" 2>&1 ;; esac
  rc=$?
  cat "$log"
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test(s), listed below.*/\1/p' "$log" | tail -1)
  p=${p:-0}; f=${f:-0}
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    echo "runtests: $t exited with status $rc"; f=1
  fi
  passed=$((passed + p)); failed=$((failed + f))
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
