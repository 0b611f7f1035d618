# test_runtests.sh: the test runner (scripts/runtests.sh) counts what cmocka programs and shell
# tests (tests/lib.sh) report: passed, failed and skipped, the skipped ones listed by name in
# the closing lines "skipped (not run on this machine):" and "N passed, N failed, N skipped"; a
# skip alone does not fail the suite unless NOSKIP=1; a failure or a crash does. It runs on a
# made-up tests/ folder of its own (the runner picks up every tests/test_*.sh of the folder it
# runs in). Tests run TEST_JOBS at a time: two tests that each wait for the other pass together
# with 2 and not with 1, and the report keeps the tests' order; TEST_TIMES keeps each test's
# time.
. tests/lib.sh

W=$TMP/w
mkdir -p "$W/tests" "$W/scripts"
cp tests/lib.sh "$W/tests/"
cp scripts/runtests.sh "$W/scripts/"

# a cmocka-like program: 3 passed, 2 skipped (cmocka's own closing lines)
cat >"$W/prog_skip" <<'EOF'
#!/bin/sh
echo '[==========] 5 test(s) run.'
echo '[  PASSED  ] 3 test(s).'
echo '[  SKIPPED ] 2 test(s), listed below:'
echo '[  SKIPPED ] gnuplot_png'
echo '[  SKIPPED ] gnuplot_svg'
echo ''
echo ' 2 SKIPPED TEST(S)'
EOF
# a shell test through lib.sh: one check passes, one is skipped with its reason
cat >"$W/tests/test_a.sh" <<'EOF'
. tests/lib.sh
check one true
skip terminal_checks "tmux is not installed"
finish
EOF
chmod +x "$W/prog_skip"

(cd "$W" && sh scripts/runtests.sh ./prog_skip) >"$TMP/out" 2>&1; RC=$?
check skips_pass [ "$RC" -eq 0 ]
check closing_line [ "$(tail -1 "$TMP/out")" = "4 passed, 0 failed, 3 skipped" ]
check skips_listed cond 'has "$TMP/out" "^skipped (not run on this machine):$" &&
  has "$TMP/out" "^  ./prog_skip: gnuplot_png$" && has "$TMP/out" "^  ./prog_skip: gnuplot_svg$" &&
  has "$TMP/out" "^  tests/test_a.sh: terminal_checks (tmux is not installed)$"'
check lib_skip_lines cond 'has "$TMP/out" "^\[  SKIPPED \] 1 test(s), listed below:$" &&
  has "$TMP/out" "^\[  SKIPPED \] terminal_checks (tmux is not installed)$"'

# NOSKIP=1: the same run fails, saying why
(cd "$W" && NOSKIP=1 sh scripts/runtests.sh ./prog_skip) >"$TMP/out" 2>&1; RC=$?
check noskip_fails cond '[ "$RC" -eq 1 ] && has "$TMP/out" "^runtests: NOSKIP=1: 3 test(s) skipped$"'

# a failure and a crash fail the suite, and nothing skipped says 0 skipped
rm "$W/tests/test_a.sh"
cat >"$W/tests/test_b.sh" <<'EOF'
. tests/lib.sh
check good true
check bad false
finish
EOF
printf '#!/bin/sh\necho "[  PASSED  ] 1 test(s)."\nexit 3\n' >"$W/prog_crash"
chmod +x "$W/prog_crash"
(cd "$W" && sh scripts/runtests.sh ./prog_crash) >"$TMP/out" 2>&1; RC=$?
check failures_fail cond '[ "$RC" -eq 1 ] && [ "$(tail -1 "$TMP/out")" = "2 passed, 2 failed, 0 skipped" ] &&
  has "$TMP/out" "^runtests: ./prog_crash exited with status 3$" && ! has "$TMP/out" "^skipped"'

# shell tests in the folders that mirror the sources (tests/app/base/...) are found too
rm "$W/tests/test_b.sh"
mkdir -p "$W/tests/app/base"
printf '. tests/lib.sh\ncheck deep true\nfinish\n' >"$W/tests/app/base/test_c.sh"
(cd "$W" && sh scripts/runtests.sh) >"$TMP/out" 2>&1; RC=$?
check subfolders_found cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^== tests/app/base/test_c.sh$" &&
  [ "$(tail -1 "$TMP/out")" = "1 passed, 0 failed, 0 skipped" ]'

# two at a time: each of two tests waits (up to 10 s) for the other to have started
rm "$W/tests/app/base/test_c.sh"
for me in x y; do
  other=$([ $me = x ] && echo y || echo x)
  cat >"$W/tests/test_$me.sh" <<EOF
. tests/lib.sh
touch "$TMP/started_$me"
n=0; while [ ! -e "$TMP/started_$other" ] && [ \$n -lt 100 ]; do sleep 0.1; n=\$((n + 1)); done
check together [ -e "$TMP/started_$other" ]
finish
EOF
done
(cd "$W" && TEST_JOBS=2 TEST_TIMES="$TMP/times" sh scripts/runtests.sh) >"$TMP/out" 2>&1; RC=$?
check two_at_a_time cond '[ "$RC" -eq 0 ] && [ "$(tail -1 "$TMP/out")" = "2 passed, 0 failed, 0 skipped" ]'
check report_order cond '[ "$(grep "^== " "$TMP/out" | tr "\n" " ")" = "== tests/test_x.sh == tests/test_y.sh " ]'
check times_kept cond '[ "$(wc -l <"$TMP/times")" -eq 2 ] && grep -q "^[0-9.]* tests/test_y.sh$" "$TMP/times"'
rm -f "$TMP"/started_*
(cd "$W" && TEST_JOBS=1 TEST_TIMES="$TMP/times" sh scripts/runtests.sh) >"$TMP/out" 2>&1; RC=$?
check one_at_a_time cond '[ "$RC" -eq 1 ] && [ "$(tail -1 "$TMP/out")" = "1 passed, 1 failed, 0 skipped" ]'
finish
