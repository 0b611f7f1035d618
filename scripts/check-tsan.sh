#!/bin/sh
# check-tsan.sh BIN: ThreadSanitizer on the grid's threads and the Ctrl-C flag. BIN is uasimpact
# built with -fsanitize=thread (make check-tsan builds build-tsan/uasimpact). Two runs, each on 2
# worker threads: a short grid that completes (case C, 0.2 m step), and a finer grid that gets
# SIGINT while its workers run (the handler sets the flag that the workers and the running
# impacts read): it must stop with status 130 and keep its finished cells. Any ThreadSanitizer
# report fails. Prints the times.
set -u
bin=$1
status=0
d=$(mktemp -d); trap 'rm -rf "$d"' EXIT
TSAN_OPTIONS="halt_on_error=1 exitcode=66 second_deadlock_stack=1"
export TSAN_OPTIONS
report() { grep -q 'ThreadSanitizer' "$1"; }

# a grid that completes
t0=$(date +%s)
"$bin" -c 'case C; set threads 2; set step 0.2; grid' >"$d/out1" 2>"$d/err1"; rc=$?
t1=$(date +%s)
if [ "$rc" -ne 0 ] || report "$d/err1"; then
  echo "check-tsan: the complete grid FAILED (status $rc):"; head -60 "$d/err1"; status=1
else
  echo "check-tsan: a complete grid on 2 threads: clean ($((t1 - t0)) s)"
fi

# a grid interrupted by SIGINT while its workers run
printf 'case C\nset threads 2\nset step 0.02\nimpact 0 0\nsave session %s/ready.ses\ngrid\n' "$d" \
  >"$d/g.ses"
"$bin" "$d/g.ses" >"$d/out2" 2>"$d/err2" & pid=$!
n=0
while [ ! -e "$d/ready.ses" ] && [ "$n" -lt 1200 ]; do sleep 0.1; n=$((n + 1)); done
while [ "$(ls "/proc/$pid/task" 2>/dev/null | wc -l)" -lt 3 ] && [ "$n" -lt 2400 ]; do
  sleep 0.05; n=$((n + 1))
done
sleep 1
kill -INT "$pid"
wait "$pid"; rc=$?
t2=$(date +%s)
if [ "$rc" -ne 130 ] || report "$d/err2" ||
   ! grep -q 'grid: interrupted (Ctrl-C); [1-9][0-9]* of [0-9]* cells finished' "$d/err2"; then
  echo "check-tsan: the interrupted grid FAILED (status $rc):"; head -60 "$d/err2"; status=1
else
  echo "check-tsan: a grid on 2 threads stopped by SIGINT: clean, $(sed -n \
    's/.*interrupted (Ctrl-C); \([0-9]* of [0-9]*\) cells.*/\1/p' "$d/err2") cells kept" \
    "($((t2 - t1)) s)"
fi
exit $status
