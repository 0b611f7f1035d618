#!/bin/sh
# check-san.sh BUILD [PLAIN]: the whole test suite again on the AddressSanitizer+UBSan build in
# BUILD (its test programs, and the shell tests run on BUILD/uasimpact and BUILD/calibrate), then a
# representative session (impacts, their histories, a coarse grid, grid show, a case switched
# back with its kept model and its grid recalled, save and export, a model saved and loaded
# back, refused commands) under valgrind on the plain build PLAIN (default ./uasimpact; valgrind
# does not run sanitized programs, and the Makefile gives it a build without the AVX2 clones,
# some of whose instructions valgrind 3.19 cannot decode): any memory error or definite leak
# fails. Prints the times.
set -u
b=$1
plain=${2:-./uasimpact}
status=0
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS UBSAN_OPTIONS

t0=$(date +%s)
tests=$(find "$b"/tests -name 'test_*' -type f ! -name '*.d' | LC_ALL=C sort)
# shellcheck disable=SC2086
UASIMPACT=$b/uasimpact CALIBRATE=$b/calibrate TEST_TIMES=$b/test-times sh scripts/runtests.sh $tests || status=1
t1=$(date +%s)
echo "check-san: sanitized test suite: $((t1 - t0)) s"

# valgrind: one session of the plain build
if ! command -v valgrind >/dev/null 2>&1; then
  echo "check-san: valgrind is not installed (sh scripts/setup.sh san)"; exit 1
fi
d=$(mktemp -d); trap 'rm -rf "$d"' EXIT
cat >"$d/session.ses" <<SES
case C
set threads 2
impact 0 0
impact 0.3 0.1
history
set step 0.2
grid
grid show
grid cells
case B
impact 0 0
case C
grid
set bag_p0 1.1 atm
save session $d/s.ses
export grid $d/g.csv
export history $d/h.csv
model save $d/m.urm
model load $d/m.urm
grid load $d/g.csv
pof nij
descent
parametric
set wind nan
impact 0.1 zz
source /nonexistent
show
SES
valgrind --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite \
  --show-leak-kinds=definite --track-origins=yes -q "$plain" -i <"$d/session.ses" \
  >"$d/out" 2>"$d/err"
rc=$?
t2=$(date +%s)
if [ "$rc" -ne 0 ] || grep -q '^==[0-9]*==' "$d/err"; then
  echo "check-san: valgrind session FAILED (status $rc):"; grep '^==' "$d/err" | head -40
  status=1
else
  echo "check-san: valgrind session clean ($(grep -c '^error: ' "$d/err") commands refused as" \
       "expected): $((t2 - t1)) s"
fi
exit $status
