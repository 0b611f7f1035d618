#!/bin/sh
# fuzz.sh RUNS SECONDS BIN...: run each libFuzzer target BIN (.../fuzz_NAME) until RUNS
# executions or SECONDS, whichever comes first (RUNS 0: only the corpus), on its committed
# corpus tests/fuzz/corpus_NAME, with the dictionary tests/fuzz/NAME.dict when there is one
# (the targets: fuzz_model, fuzz_script, fuzz_run, fuzz_part).
# New inputs go to new_NAME beside BIN (the committed corpus is only read); with
# FUZZ_MINIMISE=1 the corpus is afterwards replaced by the minimal set (libFuzzer -merge=1)
# covering it and the new inputs. Prints the executions each target reached; a crash, a timeout,
# a leak or a sanitizer report fails, its input kept beside BIN. Paths are given to libFuzzer
# absolute: a target may work in a folder of its own (fuzz_run works in a scratch folder).
# FUZZ_TIMEOUT (s, default 20): an input running longer counts as a hang; on a machine shared
# with other jobs a slow input can pass 20 s without hanging (fuzz_run's grid and report scripts).
set -u
runs=$1; secs=$2; shift 2
status=0
root=$(pwd)
for bin in "$@"; do
  case "$bin" in /*) ;; *) bin=$root/$bin ;; esac
  t=$(basename "$bin"); dir=$(dirname "$bin"); name=${t#fuzz_}
  corpus=$root/tests/fuzz/corpus_$name
  new=$dir/new_$name
  log=$dir/$t.log
  mkdir -p "$new" "$corpus"
  dict=""; [ -r "tests/fuzz/$name.dict" ] && dict="-dict=$root/tests/fuzz/$name.dict"
  start=$(date +%s)
  "$bin" -runs="$runs" -max_total_time="$secs" -timeout=${FUZZ_TIMEOUT:-20} -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$dir/$t-" $dict "$new" "$corpus" >"$log" 2>&1
  rc=$?
  took=$(( $(date +%s) - start ))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ "$rc" -ne 0 ]; then
    echo "fuzz: $t FAILED (status $rc) after ${execs:-?} executions, $took s; log $log:"
    grep -E 'ERROR|SUMMARY|runtime error|Test unit written' "$log" | head -20
    status=1
    continue
  fi
  echo "fuzz: $t: ${execs:-?} executions in $took s, no crash ($(ls "$corpus" | wc -l) corpus inputs, $(ls "$new" | wc -l) new)"
  if [ "${FUZZ_MINIMISE:-0}" = 1 ]; then
    min=$dir/min_$name
    rm -rf "$min"; mkdir -p "$min"
    if "$bin" -merge=1 $dict "$min" "$corpus" "$new" >>"$log" 2>&1; then
      rm -f "$corpus"/*; cp "$min"/* "$corpus"/
      echo "fuzz: $t: corpus minimised to $(ls "$corpus" | wc -l) inputs"
    else
      echo "fuzz: $t: minimising failed; log $log"; status=1
    fi
  fi
done
exit $status
