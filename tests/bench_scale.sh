# bench_scale.sh: the speed-up of 2 MPI ranks x 1 thread over 1 rank x 1 thread on a zero-wind
# grid (case B, step 0.05 m, the paper's pitch), the two runs back to back, repeated R times
# (min and median of each); and the figures of the cost model in uasimpact(1), SCALING OUT: the
# seconds per impact (one thread, in the grid and alone), the set-up per grid (a grid of one cell after a model change:
# compile and settled stance) and the bytes a simulated cell costs in a part or message.
#   sh tests/bench_scale.sh [R]        (make bench; needs ./uasimpact-mpi: make mpi)
# The machine may be shared: the load average is printed with the times.
U=${UASIMPACT:-./uasimpact}
MPI=$(dirname "$U")/uasimpact-mpi
R=${1:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
if ! command -v mpirun >/dev/null 2>&1 || [ ! -x "$MPI" ]; then
  echo "bench_scale: skipped (mpirun or $MPI missing: make mpi)"
  exit 0
fi
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
printf 'set format csv\nset threads 1\nset step 0.05\ncase B\ngrid\n' >"$T/g.ses"

now() { date +%s.%N; }
# run N ranks: prints "WALL GRIDSECONDS IMPACTS Q"
one() {
  t0=$(now)
  mpirun -n "$1" "$MPI" "$T/g.ses" >"$T/out" 2>"$T/err" || { cat "$T/err"; exit 1; }
  t1=$(now)
  awk -F, -v w="$(echo "$t1 - $t0" | bc)" '/impacts simulated/ { sub(/.*; /, ""); n = $1 + 0 }
    /,seconds$/ { getline; print w, $10, n, $9 }' "$T/out"
}
stats() {   # min and median of a column of numbers
  sort -g | awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "min %.2f s, median %.2f s", v[1], m }'
}

echo "bench_scale: zero-wind grid of case B, step 0.05 m; $R pairs of runs back to back;" \
  "$(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg) (a shared machine is noisy)"
: >"$T/r1"; : >"$T/r2"
for i in $(seq "$R"); do
  one 1 >>"$T/r1"
  one 2 >>"$T/r2"
done
q1=$(awk '{ print $4 }' "$T/r1" | sort -u | tr '\n' ' '); q2=$(awk '{ print $4 }' "$T/r2" | sort -u | tr '\n' ' ')
n=$(awk '{ print $3; exit }' "$T/r1")
echo "  impacts per grid: $n; Q: 1 rank $q1, 2 ranks $q2$([ "$q1" = "$q2" ] && echo '(identical)' || echo '(DIFFERENT)')"
g1=$(awk '{ print $2 }' "$T/r1" | stats); g2=$(awk '{ print $2 }' "$T/r2" | stats)
w1=$(awk '{ print $1 }' "$T/r1" | stats); w2=$(awk '{ print $1 }' "$T/r2" | stats)
echo "  grid (its seconds): 1 rank x 1 thread $g1; 2 ranks x 1 thread $g2"
echo "  whole run (mpirun): 1 rank x 1 thread $w1; 2 ranks x 1 thread $w2"
sp() { paste "$T/r1" "$T/r2" | awk -v c="$1" '{ print $c / $(c + 4) }' | sort -g |
  awk '{ v[NR] = $1 } END { printf "%.2f (median of the pairs; best %.2f)", v[int((NR + 1) / 2)], v[NR] }'; }
echo "  speed-up 2 ranks over 1: grid $(sp 2); whole run $(sp 1)"
gm=$(awk '{ print $2 }' "$T/r1" | sort -g | head -1)
echo "  seconds per impact (1 thread, best grid): $(echo "scale=5; $gm / $n" | bc) s"

# a single impact through the impact command (with its histories): 21 impacts against 1
imp() {
  { printf 'set threads 1\ncase B\n'; for k in $(seq 0 "$1"); do printf 'impact 0.%02d 0.1\n' "$k"; done; } >"$T/i.ses"
  t0=$(now); "$U" "$T/i.ses" >/dev/null 2>&1 || exit 1; t1=$(now)
  echo "$t1 - $t0" | bc
}
a=$(imp 0); b=$(imp 20)
echo "  a single impact (the impact command, 1 thread): $(echo "scale=4; ($b - $a) / 20" | bc) s"

# set-up per grid: 11 grids of one cell, each after a model change, against 1
setup() {
  printf 'set threads 1\ncase B\nset along_min 0\nset along_max 0\nset cross_max 0\nsweep neck_k_flex %s\n' "$1" >"$T/s.ses"
  t0=$(now); "$U" "$T/s.ses" >/dev/null 2>&1 || exit 1; t1=$(now)
  echo "$t1 - $t0" | bc
}
a=$(setup 160); b=$(setup 100,110,120,130,140,150,160,170,180,190,200)
echo "  set-up per grid (a model change: compile, settled stance; one cell): $(echo "scale=3; ($b - $a) / 10" | bc) s"

# bytes per simulated cell in a part
"$U" --shard 0/1 --part "$T/p" "$T/g.ses" >/dev/null 2>&1
echo "  a simulated cell in a part or an MPI message: $(awk '/^c / { n++; b += length($0) + 1 } END { printf "%.0f", b / n }' "$T/p") bytes"
