# test_scale.sh: a script's grids split over processes (src/app/scale/scale*.c): run serially, as 2 and
# as 3 shards merged (uasimpact --shard I/N --part OUT; uasimpact merge), and under mpirun -n 2
# (./uasimpact-mpi, make mpi), the outputs and the exported file must be the serial run's apart
# from the wall-clock fields (the grid row's seconds, montecarlo's time note). The script has a
# grid, its cells, an impact, a wind sweep, a model-parameter sweep, risk, sora, compare, a small
# montecarlo on a response surface with its check grids, and an export. Then every refusal of
# merge (status 2, one line) and of --shard, Ctrl-C or SIGTERM on MPI rank 0 stopping every rank
# and ranks out of step (status 3). A part file is data: merge takes the script on its own
# command line and runs nothing a part says; parts forged with the checksum recomputed (a
# command line of their own, -i, none; p = 5, 1e300, inf, nan, -1; an escape sequence as a
# failure reason; more grids than the run) are refused, and so are /dev/zero and a directory;
# --part never replaces an input of the run or a file that is not a part.
. tests/lib.sh

U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
MPI=$(cd "$(dirname "$UASIMPACT")" && pwd)/uasimpact-mpi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

# the wall-clock fields masked: the seconds column of rows under a header ending in ',seconds'
# (or ',seconds,complete'), and montecarlo's '# time:' note
mask() {
  awk -F, -v OFS=, '/,seconds(,complete)?$/ { n = NF; s = $NF == "complete" ? NF - 1 : NF
      print; next }
    n && NF == n && !/^#/ { $s = "S"; print; next }
    { n = 0; sub(/^# time: .*/, "# time: T"); print }' "$1"
}

# resum FILE: the checksum line of a part recomputed (FNV-1a, 64 bits, of every byte before it;
# awk in 16-bit limbs), as a forger would: the checksum finds damage, it is no signature
resum() {
  sed '$d' "$1" >"$1.body"
  h=$(od -An -v -tu1 "$1.body" | awk '
    function xor8(a, b,   r, i, p) { r = 0; p = 1
      for (i = 0; i < 8; i++) { if ((int(a / p) % 2) != (int(b / p) % 2)) r += p; p *= 2 }
      return r }
    BEGIN { l[0] = 8997; l[1] = 33826; l[2] = 40164; l[3] = 52210 }   # 0xcbf29ce484222325
    { for (f = 1; f <= NF; f++) {   # h = (h ^ byte) * (2^40 + 435) mod 2^64
        lo = l[0] % 256; l[0] = l[0] - lo + xor8(lo, $f)
        c = 0; for (i = 0; i < 4; i++) { v = l[i] * 435 + c; m[i] = v % 65536; c = int(v / 65536) }
        s[0] = 0; s[1] = 0; s[2] = (l[0] * 256) % 65536; s[3] = (l[1] * 256 + int(l[0] / 256)) % 65536
        c = 0; for (i = 0; i < 4; i++) { v = m[i] + s[i] + c; l[i] = v % 65536; c = int(v / 65536) }
      } }
    END { printf "%04x%04x%04x%04x", l[3], l[2], l[1], l[0] }')
  { cat "$1.body"; echo "sum $h"; } >"$1"
  rm -f "$1.body"
}

# one directory per way of running, each with the same script and include (case A with the
# analytic bag here and below: the shards are the subject, whatever the bag; the membrane bag,
# A's default at the switch, costs ~20 s CPU per grid of A at 0.2 m, and this script has ~15)
for d in serial s2 s3 mpi bad; do
  mkdir -p "$TMP/$d"
  printf 'set step 0.2\n' >"$TMP/$d/inc.ses"
  cat >"$TMP/$d/t.ses" <<'SES'
set format csv
source inc.ses
case A
set bag_model analytic
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
"$U" merge --script t.ses p0 p1 >out 2>err; RC=$?
check merge2_status cond '[ $RC -eq 0 ] && [ ! -s err ]'
mask out >masked
check merge2_equals_serial cmp -s masked "$TMP/serial/masked"
check merge2_export_equal cmp -s mc.csv "$TMP/serial/mc.csv"
# the shards shared out the cells: every simulated cell is in exactly one part
n0=$(grep -c '^c ' p0); n1=$(grep -c '^c ' p1)
check shards2_split cond '[ "$n0" -gt 10 ] && [ "$n1" -gt 10 ] && [ $((n0 - n1)) -le 40 ] && [ $((n1 - n0)) -le 40 ]'

cd "$TMP/s3" && for i in 0 1 2; do "$U" --shard $i/3 --part p$i t.ses || echo fail; done >sh.out 2>&1
"$U" merge --script t.ses p2 p0 p1 >out 2>err; RC=$?
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
  printf 'set format csv\ncase A\nset bag_model analytic\nset step 0.2\ngrid\nnosuch\n' >f.ses
  mpirun -n 2 "$MPI" f.ses >o 2>e; RC=$?
  check mpi_failure cond '[ $RC -eq 1 ] && [ "$(grep -c "f.ses:6: unknown command" e)" -eq 1 ] && grep -q "^A,0," o'

  # ranks that run other grids (nodes that see other files; here other -c commands per rank)
  # stop with a status of their own, not Ctrl-C's 130
  mpirun -n 1 "$MPI" -c 'set format csv; case A; set bag_model analytic; set step 0.2; grid' : \
    -n 1 "$MPI" -c 'set format csv; case A; set bag_model analytic; set step 0.3; grid' >o 2>e; RC=$?
  check mpi_out_of_step_3 cond '[ $RC -eq 3 ] && grep -q "ranks out of step" e'

  # Ctrl-C on rank 0 stops every rank: status 130 (in a grid, or before one on a loaded machine:
  # while settling the stance); SIGTERM on rank 0 ends the run too, and so does Ctrl-C on mpirun
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
      check mpi_ctrl_c_130 cond '[ -n "$r0" ] && [ $RC -eq 130 ] && [ "$left" -eq 0 ] && grep -Eq "interrupted \(Ctrl-C\)( on rank 0)?; every rank stopped" l.err'
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
refused() {   # NAME PATTERN MERGE-ARGS... (after merge --script t.ses)
  name=$1; pat=$2; shift 2
  "$U" merge --script t.ses "$@" >o 2>e; rc=$?
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
"$U" --shard 1/2 --part pc -c 'set step 0.2; case A; set bag_model analytic; grid' >/dev/null 2>&1
refused merge_other_script "different scripts or command lines" p0 pc
# the script changed since the shards ran; a file it reads changed (the grid's key)
cp t.ses t.keep && echo '# changed' >>t.ses
refused merge_script_changed "a script file of the command line changed" p0 p1
cp t.keep t.ses && printf 'set step 0.3\n' >inc.ses
"$U" merge --script t.ses p0 p1 >o 2>e; rc=$?
check merge_grid_changed cond '[ $rc -ne 0 ] && grep -q "grid 0 is not the one the shards ran" e && [ "$(lines e)" -eq 1 ]'
printf 'set step 0.2\n' >inc.ses

# the merge's own command line: the script and -c commands given, compared with the parts'
refused merge_other_line "are not the ones the shards ran (t.ses, recorded in 'p0')" -c 'set threads 1' p0 p1
refused merge_unknown_option "unknown option '-x'" -x p0 p1
refused merge_dash_script "a name that starts with '-' reads as an option; accepted: ./-i" --script -i p0 p1
"$U" merge p0 p1 >o 2>e; rc=$?
check merge_old_form cond '[ $rc -eq 2 ] && [ ! -s o ] && [ "$(lines e)" -eq 1 ] && grep -q "no script given: a part file is data, its command line is not run; accepted: uasimpact merge \[-c COMMANDS\] \[--script FILE\]... PART..." e && grep -q "(the parts record: --script t.ses)" e'
"$U" merge --script >o 2>e; rc=$?
check merge_script_needs_file cond '[ $rc -eq 2 ] && [ "$(lines e)" -eq 1 ] && grep -q -- "--script needs the script file" e'

# ---- a part file is data (nothing it says is run) ----
cd "$TMP/bad"
printf 'keep\n' >VICTIM
cp t.ses t.keep
"$U" --shard 0/1 --part evil -c 'save session VICTIM' >o 2>e; rc=$?
check evil_part_written cond '[ $rc -eq 0 ] && grep -qx "arg save session VICTIM" evil && grep -qx keep VICTIM'
cp evil evil.re && resum evil.re
check resum_reproduces cmp -s evil evil.re
"$U" merge evil >o 2>e </dev/null; rc=$?
check evil_old_form cond '[ $rc -eq 2 ] && [ ! -s o ] && [ "$(lines e)" -eq 1 ] && grep -q "no script given" e && grep -qx keep VICTIM && [ "$(ls | grep -c VICTIM)" -eq 1 ]'
check evil_old_form_shown cond "grep -q \"(the parts record: -c 'save session VICTIM')\" e"
"$U" merge --script t.ses evil >o 2>e </dev/null; rc=$?
check evil_other_script cond '[ $rc -eq 2 ] && [ ! -s o ] && [ "$(lines e)" -eq 1 ] && grep -q "are not the ones the shards ran" e && grep -qx keep VICTIM'
# a part whose command line is -i (a prompt) or empty (standard input), checksum recomputed
sed -e 's/^argc 2$/argc 1/' -e '/^arg -c$/d' -e 's/^arg save session VICTIM$/arg -i/' evil >evil_i
sed -e 's/^argc 2$/argc 0/' -e '/^arg /d' evil >evil_0
resum evil_i; resum evil_0
for f in evil_i evil_0; do
  for how in old new; do
    if [ $how = old ]; then "$U" merge $f >o 2>e <t.ses; rc=$?
    else "$U" merge --script t.ses $f >o 2>e <t.ses; rc=$?; fi
    check "${f}_$how" cond '[ $rc -eq 2 ] && [ ! -s o ] && [ "$(lines e)" -eq 1 ] && grep -qx keep VICTIM && ! grep -q "uasimpact>" e'
  done
  check "${f}_why" grep -q "records a command line that no shard runs" e
done

# a small run of one grid, its part forged cell by cell (the first simulated cell with contact)
cmds='set format csv; case A; set step 0.5; grid'
"$U" --shard 0/1 --part small -c "$cmds" && "$U" -c "$cmds" >o && mask o >serial.out
"$U" merge -c "$cmds" small >o 2>e; rc=$?
check small_merges cond '[ $rc -eq 0 ] && [ ! -s e ] && mask o | cmp -s - serial.out && grep -q "^c [0-9]* 2 1 " small'
forge() {   # OUT AWK-STATEMENTS: small with the first contact cell changed, checksum recomputed
  awk "/^c [0-9]+ 2 1 / && !done { $2; done = 1 } { print }" small >"$1"
  resum "$1"
}
forge same 'x = 0'
"$U" merge -c "$cmds" same >o 2>e; rc=$?
check forge_control cond '[ $rc -eq 0 ] && mask o | cmp -s - serial.out'
for v in 5 1e300 inf nan -1 0x1.0000000000001p+0; do
  forge "p_$v" "\$(NF - 2) = \"$v\""
  "$U" merge -c "$cmds" "p_$v" >o 2>e; rc=$?
  check "cell_p_$v" cond '[ $rc -eq 2 ] && [ ! -s o ] && [ "$(lines e)" -eq 1 ] && grep -q "is damaged (bad cell line)" e'
  forge "pof_$v" "\$(NF - 3) = \"$v\""
  "$U" merge -c "$cmds" "pof_$v" >o 2>e; rc=$?
  check "cell_pof_$v" cond '[ $rc -eq 2 ] && [ ! -s o ] && grep -q "is damaged (bad cell line)" e'
done
# a failure reason that would set the terminal's title and clear the screen (a plain one merges)
forge failed '$3 = 3; $NF = "|simulation failed"'
"$U" merge -c "$cmds" failed >o 2>e; rc=$?
check cell_reason_plain cond '[ $rc -eq 1 ] && grep -q "failed: simulation failed" e'
forge esc '$3 = 3; $NF = "|\033]0;pwned\007\033[2J"'
check esc_forged grep -q "$(printf '\033')" esc
"$U" merge -c "$cmds" esc >o 2>e; rc=$?
check cell_reason_escape cond '[ $rc -eq 2 ] && [ ! -s o ] && grep -q "is damaged (bad cell line)" e && ! grep -q "$(printf "\033")" e'
# more grids than the run has: grid 0 again as grid 1
awk '/^grid 0 /{ g = 1 } /^end / { for (i = 1; i <= n; i++) { l = b[i]; if (i == 1) sub(/^grid 0 /, "grid 1 ", l); print l }
  print "end 0 2"; next } g { b[++n] = $0 } { print }' small >more
resum more
"$U" merge -c "$cmds" more >o 2>e; rc=$?
check more_grids cond '[ $rc -eq 2 ] && [ "$(lines e)" -eq 1 ] && grep -q "part .more. holds 2 grids, the merged run ran 1" e'
# files that are not parts: refused by their first line, at once
"$U" merge -c "$cmds" small /dev/zero >o 2>e; rc=$?
check merge_dev_zero cond '[ $rc -eq 2 ] && [ ! -s o ] && [ "$(lines e)" -eq 1 ] && grep -q "./dev/zero. is not a part file" e'
mkdir -p sub
"$U" merge -c "$cmds" small sub >o 2>e; rc=$?
check merge_directory cond '[ $rc -eq 2 ] && [ "$(lines e)" -eq 1 ] && grep -q "is a directory" e'

# --part never replaces an input of the run, nor a file that is not a part
"$U" --shard 0/2 --part t.ses t.ses >o 2>e; rc=$?
check part_is_script cond '[ $rc -eq 2 ] && [ "$(lines e)" -eq 1 ] && grep -q "is a file the run reads" e && cmp -s t.ses t.keep'
: >empty.ses
printf 'source empty.ses\n%s\n' "$cmds" | tr ';' '\n' >src.ses
"$U" --shard 0/2 --part empty.ses src.ses >o 2>e; rc=$?
check part_is_sourced cond '[ $rc -eq 2 ] && grep -q "is a file the run reads (.empty.ses.)" e && [ ! -s empty.ses ]'
printf 'precious\n' >notes.txt
"$U" --shard 0/2 --part notes.txt -c "$cmds" >o 2>e; rc=$?
check part_not_a_part cond '[ $rc -eq 2 ] && grep -q "exists and is not a part file" e && grep -qx precious notes.txt'
"$U" --shard 0/2 --part sub -c "$cmds" >o 2>e; rc=$?
check part_directory cond '[ $rc -eq 2 ] && grep -q "is a directory" e'
: >fresh
"$U" --shard 0/1 --part fresh -c "$cmds" && "$U" --shard 0/1 --part small -c "$cmds"; rc=$?
check part_replaces_part_or_empty cond '[ $rc -eq 0 ] && cmp -s fresh small'
cd "$TMP/s2"

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
# -n changes nothing in a script run (only a session reads the start-up file): a shard given it
# writes the part it writes without it, which merges (it recorded -n, which no merge took)
cmds='set format csv; case B; set step 0.3; grid'
"$U" -n --shard 0/1 --part pn -c "$cmds" >o 2>e; rc=$?
"$U" --shard 0/1 --part pn0 -c "$cmds" && "$U" -c "$cmds" >on0 && mask on0 >on
"$U" merge -c "$cmds" pn >o 2>e; rc2=$?
check shard_n_merges cond '[ $rc -eq 0 ] && [ $rc2 -eq 0 ] && [ ! -s e ] && mask o | cmp -s - on'
check shard_n_same_part cmp -s pn pn0

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
