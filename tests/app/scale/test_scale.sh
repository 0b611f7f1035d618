# test_scale.sh: a script's grids split over processes (src/app/scale/scale*.c): run serially, as 2 and
# as 3 shards merged (uasimpact --shard I/N --part OUT; uasimpact merge), and under mpirun -n 2
# (./uasimpact-mpi, make mpi), the outputs and the exported file must be the serial run's apart
# from the wall-clock fields (the grid row's seconds, montecarlo's time note). The script has a
# grid, its cells, an impact, a wind sweep, a model-parameter sweep, risk, sora, compare, a small
# montecarlo on a response surface with its check grids, and an export. Then every refusal of merge (status 2, one line) and of --shard, and Ctrl-C or
# SIGTERM on MPI rank 0 stopping every rank.
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
MPI=$(cd "$(dirname "$UASIMPACT")" && pwd)/uasimpact-mpi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

# the wall-clock fields masked: the last column of rows under a header ending in ',seconds',
# and montecarlo's '# time:' note
mask() {
  awk -F, -v OFS=, '/,seconds$/ { n = NF; print; next }
    n && NF == n && !/^#/ { $NF = "S"; print; next }
    { n = 0; sub(/^# time: .*/, "# time: T"); print }' "$1"
}

# one directory per way of running, each with the same script and include
for d in serial s2 s3 mpi bad; do
  mkdir -p "$TMP/$d"
  printf 'set step 0.2\n' >"$TMP/$d/inc.ses"
  cat >"$TMP/$d/t.ses" <<'SES'
set format csv
source inc.ses
case A
grid
grid cells
impact 0.2 0.1
sweep wind 0,4
sweep neck_k_flex 120,200
set p_chute 0.9
risk
sora
compare
set surface_nodes 2
set surface_check 2
dist wind discrete 0,4 0.5,0.5
dist face uniform -180 180
montecarlo 20
export montecarlo mc.csv
SES
done

cd "$TMP/serial" && "$U" t.ses >out 2>err; RC=$?
check serial_runs cond '[ $RC -eq 0 ] && [ -s mc.csv ] && grep -q "^mixed," out && grep -q "^# surface check: samples 0..1" out'
mask out >masked

# two shards, then three given out of order
cd "$TMP/s2" && "$U" --shard 0/2 --part p0 t.ses >sh.out 2>&1 && "$U" t.ses --part p1 --shard 1/2 >>sh.out 2>&1
RC=$?
check shards2_run cond '[ $RC -eq 0 ] && [ ! -s sh.out ] && [ ! -e mc.csv ] && [ -s p0 ] && [ -s p1 ]'
"$U" merge p0 p1 >out 2>err; RC=$?
check merge2_status cond '[ $RC -eq 0 ] && [ ! -s err ]'
mask out >masked
check merge2_equals_serial cmp -s masked "$TMP/serial/masked"
check merge2_export_equal cmp -s mc.csv "$TMP/serial/mc.csv"
# the shards shared out the cells: every simulated cell is in exactly one part
n0=$(grep -c '^c ' p0); n1=$(grep -c '^c ' p1)
check shards2_split cond '[ "$n0" -gt 10 ] && [ "$n1" -gt 10 ] && [ $((n0 - n1)) -le 40 ] && [ $((n1 - n0)) -le 40 ]'

cd "$TMP/s3" && for i in 0 1 2; do "$U" --shard $i/3 --part p$i t.ses || echo fail; done >sh.out 2>&1
"$U" merge p2 p0 p1 >out 2>err; RC=$?
mask out >masked
check merge3_equals_serial cond '[ $RC -eq 0 ] && [ ! -s sh.out ] && cmp -s masked "$TMP/serial/masked"'
check merge3_export_equal cmp -s mc.csv "$TMP/serial/mc.csv"
# every cell bitwise the same whoever computed it: the three parts' cells are one shard's
"$U" --shard 0/1 --part p01 t.ses
cells() { awk '/^grid /{ g = $2 } /^c /{ $1 = ""; print g, $0 }' "$@" | sort; }
cells p01 >one; cells p0 p1 p2 >three
check cells_bitwise_equal cond '[ "$(lines one)" -gt 300 ] && cmp -s one three'

# MPI: 2 ranks
if command -v mpirun >/dev/null 2>&1 && [ -x "$MPI" ]; then
  cd "$TMP/mpi" && mpirun -n 2 "$MPI" t.ses >out 2>err; RC=$?
  mask out >masked
  check mpi2_equals_serial cond '[ $RC -eq 0 ] && cmp -s masked "$TMP/serial/masked"'
  check mpi2_export_equal cmp -s mc.csv "$TMP/serial/mc.csv"

  # scripts only; a failing script fails every rank with the serial status and message
  mpirun -n 2 "$MPI" -i t.ses </dev/null >o 2>e; RC=$?
  check mpi_no_session cond '[ $RC -eq 2 ] && grep -q "runs scripts, not sessions" e'
  printf 'set format csv\ncase A\nset step 0.2\ngrid\nnosuch\n' >f.ses
  mpirun -n 2 "$MPI" f.ses >o 2>e; RC=$?
  check mpi_failure cond '[ $RC -eq 1 ] && [ "$(grep -c "f.ses:5: unknown command" e)" -eq 1 ] && grep -q "^A,0," o'

  # Ctrl-C on rank 0 stops every rank: status 130; SIGTERM on rank 0 ends the run too, and so
  # does Ctrl-C on mpirun
  printf 'set threads 1\nset step 0.02\ncase C\ngrid\ngrid\ngrid\n' >long.ses
  for sig in INT TERM RUN; do
    mpirun -n 2 "$MPI" long.ses >l.out 2>l.err &
    mp=$!
    r0=""; k=0
    while [ -z "$r0" ] && [ $k -lt 100 ]; do
      sleep 0.1; k=$((k + 1))
      for p in $(pgrep -P $mp); do
        tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx OMPI_COMM_WORLD_RANK=0 && r0=$p
      done
    done
    sleep 1
    if [ $sig = RUN ]; then kill -INT $mp; else [ -n "$r0" ] && kill -$sig "$r0"; fi
    wait $mp; RC=$?
    sleep 0.3
    left=$(pgrep -f "$MPI long.ses" | wc -l)
    if [ $sig = INT ]; then
      check mpi_ctrl_c_130 cond '[ -n "$r0" ] && [ $RC -eq 130 ] && [ "$left" -eq 0 ] && grep -q "interrupted (Ctrl-C) on rank 0; every rank stopped" l.err'
    elif [ $sig = TERM ]; then
      check mpi_sigterm_stops cond '[ -n "$r0" ] && [ $RC -ne 0 ] && [ "$left" -eq 0 ]'
    else   # Ctrl-C at a terminal reaches mpirun, which ends every rank itself
      check mpirun_ctrl_c_stops cond '[ $RC -ne 0 ] && [ "$left" -eq 0 ]'
    fi
  done
else
  skip mpi "mpirun or ./uasimpact-mpi missing: scripts/setup.sh mpi; make mpi"
fi

# ---- refusals: status 2, one line naming what is wrong ----
cd "$TMP/s2"
refused() {   # NAME PATTERN MERGE-ARGS...
  name=$1; pat=$2; shift 2
  "$U" merge "$@" >o 2>e; rc=$?
  check "$name" cond '[ $rc -eq 2 ] && [ ! -s o ] && [ "$(lines e)" -eq 1 ] && grep -q -- "$pat" e'
}
refused merge_missing "missing shards 1 of 2" p0
refused merge_duplicate "are the same shard" p0 p0 p1
refused merge_counts "different numbers of shards" p0 p1 "$TMP/s3/p2"
refused merge_not_part "is not a part file" p0 t.ses
refused merge_none "no part files"
refused merge_unreadable "cannot read" p0 nosuch
head -c 2000 p1 >trunc
refused merge_truncated "is truncated" p0 trunc
sed '8s/^c \([0-9]*\) 2 1 /c \1 2 0 /' p1 >damaged
check damaged_differs cond '! cmp -s damaged p1'
refused merge_damaged "is damaged" p0 damaged
sed '1s/ 1$/ 9/' p1 >version
refused merge_version "format version 9; accepted: version 1" p0 version
"$U" --shard 1/2 --part pc -c 'set step 0.2; case A; grid' >/dev/null 2>&1
refused merge_other_script "different scripts or command lines" p0 pc
# the script changed since the shards ran; a file it reads changed (the grid's key)
cp t.ses t.keep && echo '# changed' >>t.ses
refused merge_script_changed "script file of the parts' command line changed" p0 p1
cp t.keep t.ses && printf 'set step 0.3\n' >inc.ses
"$U" merge p0 p1 >o 2>e; rc=$?
check merge_grid_changed cond '[ $rc -ne 0 ] && grep -q "grid 0 is not the one the shards ran" e && [ "$(lines e)" -eq 1 ]'
printf 'set step 0.2\n' >inc.ses

# --shard and --part: strict, together, no -i
for a in 2/2 1/0 -1/2 a/2 1/2x 0.5/2 ''; do
  "$U" --shard "$a" --part px t.ses >o 2>e; rc=$?
  check "shard_arg_${a:-empty}" cond '[ $rc -eq 2 ] && [ "$(lines e)" -eq 1 ] && grep -q "accepted: I/N" e && [ ! -e px ]'
done
"$U" --shard 0/2 t.ses >o 2>e; rc=$?
check shard_needs_part cond '[ $rc -eq 2 ] && grep -q "go together" e'
"$U" --shard 0/2 --part px -i t.ses >o 2>e </dev/null; rc=$?
check shard_no_i cond '[ $rc -eq 2 ] && grep -q "not accepted" e && [ ! -e px ]'
"$U" --shard 0/2 --part px <t.ses >o 2>e; rc=$?
check shard_no_stdin cond '[ $rc -eq 2 ] && grep -q "standard input is not accepted" e && [ ! -e px ]'

# Ctrl-C stops a shard with status 130 and no part (nor a temporary file of one)
printf 'set threads 1\nset step 0.02\ncase C\ngrid\ngrid\n' >long.ses
"$U" --shard 0/2 --part pl long.ses >o 2>e &
sp=$!
sleep 1
kill -INT $sp
wait $sp; rc=$?
check shard_ctrl_c cond '[ $rc -eq 130 ] && [ ! -e pl ] && [ -z "$(ls | grep "^pl")" ] && grep -q "interrupted" e'

# a shard whose script fails keeps the status, and its part says so
printf 'set step 0.2\ncase A\ngrid\nnosuch\n' >fail.ses
"$U" --shard 0/2 --part pf fail.ses >o 2>e; rc=$?
check shard_failure_status cond '[ $rc -eq 1 ] && grep -q "^end 1 1$" pf && grep -q "unknown command" e'
finish
