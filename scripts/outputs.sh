#!/bin/sh
# outputs.sh: the whole-program check of a change that must not change results (src/README,
# section 5): record what a build prints, before and after, and compare byte for byte.
#   sh scripts/outputs.sh record BIN DIR [quick]   run BIN (from the source directory) and keep
#       its outputs in DIR: show, impacts, their histories and contacts, a grid, its cells and
#       its export for cases A, B and C; the paper sessions that run in seconds; a script split
#       over 2 shards and merged (and under mpirun when BIN-mpi and mpirun exist); and the Table
#       17 session with 'set format csv' (minutes). 'quick': case C only, nothing else.
#   sh scripts/outputs.sh compare DIR1 DIR2        every file of DIR1 against DIR2's: "same" or
#       "DIFF" per file, status 1 on any difference or missing file.
# Compared with the wall-clock fields masked (a grid row's seconds, montecarlo's time note) and
# the paths of DIR1 and DIR2 taken out; the tool's former name reads as its present one. Part
# files name the built-in models by a hash of their text: compare them after a change of the
# models' comments by their cell lines.
set -u

# the wall-clock fields masked and the output directory's path taken out
mask() { # FILE DIR
  awk -F, -v OFS=, '/,seconds(,complete)?$/ { n = NF; s = $NF == "complete" ? NF - 1 : NF
      print; next }
    n && NF == n && !/^#/ { $s = "S"; print; next }
    { n = 0; sub(/^# time: .*/, "# time: T"); print }' "$1" |
    sed "s|$2|DIR|g; s/uasrisk/uasimpact/g"
}

record() { # BIN DIR QUICK
  b=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
  mkdir -p "$2" || exit 2
  o=$(cd "$2" && pwd)
  src=$(pwd)
  cases="A B C"
  [ "$3" = quick ] && cases=C
  export PAGER=cat NO_COLOR=1 HOME="$o/home"
  mkdir -p "$HOME"
  for c in $cases; do
    printf 'set format csv\ncase %s\nshow\nimpact 0 0\nhistory all\ncontacts\nimpact 0.2 0.1\n%s\n' \
      "$c" 'history head_acc' >"$o/case$c.ses"
    printf 'contacts\nset step 0.2\ngrid\ngrid cells\nexport grid %s/grid%s.csv\n' "$o" "$c" \
      >>"$o/case$c.ses"
    (cd "$o" && "$b" "case$c.ses" >"case$c.out" 2>"case$c.err"; echo "status $?" >>"case$c.out")
  done
  [ "$3" = quick ] && return 0
  for s in table2 table3 tables11-13 demo; do
    "$b" "sessions/$s.ses" >"$o/$s.out" 2>"$o/$s.err"
    echo "status $?" >>"$o/$s.out"
  done
  mkdir -p "$o/scale"
  printf 'set step 0.2\n' >"$o/scale/inc.ses"
  printf '%s\n' 'set format csv' 'source inc.ses' 'case A' 'grid' 'grid cells' 'impact 0.2 0.1' \
    'sweep wind 0,4' 'sweep neck_k_flex 120,200' 'set p_chute 0.9' 'risk' 'sora' 'compare' \
    'set surface_nodes 2' 'set surface_check 2' 'dist wind discrete 0,4 0.5,0.5' \
    'dist face uniform -180 180' 'montecarlo 20' 'export montecarlo mc.csv' >"$o/scale/t.ses"
  (
    cd "$o/scale" || exit 2
    "$b" t.ses >serial.out 2>serial.err && mv mc.csv mc-serial.csv
    "$b" --shard 0/2 --part p0 t.ses >shards.out 2>&1
    "$b" --shard 1/2 --part p1 t.ses >>shards.out 2>&1
    "$b" merge p0 p1 >merge.out 2>merge.err && mv mc.csv mc-merge.csv
    grep '^c ' p0 >p0.cells
    grep '^c ' p1 >p1.cells
    rm -f p0 p1
    if [ -x "$b-mpi" ] && command -v mpirun >/dev/null 2>&1; then
      OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        OMPI_MCA_rmaps_base_oversubscribe=1 mpirun -n 2 "$b-mpi" t.ses >mpi.out 2>mpi.err &&
        mv mc.csv mc-mpi.csv
    fi
  )
  { echo 'set format csv'; cat sessions/table17.ses; } >"$o/table17.ses"
  (cd "$src" && "$b" "$o/table17.ses" >"$o/table17.out" 2>"$o/table17.err"
    echo "status $?" >>"$o/table17.out")
}

compare() { # DIR1 DIR2
  a=$(cd "$1" && pwd) || exit 2
  b=$(cd "$2" && pwd) || exit 2
  t=$(mktemp -d) || exit 2
  rc=0
  for f in $(cd "$a" && find . -type f ! -path './home/*' | LC_ALL=C sort); do
    if [ ! -f "$b/$f" ]; then
      echo "missing: $f"
      rc=1
      continue
    fi
    mask "$a/$f" "$a" >"$t/a"
    mask "$b/$f" "$b" >"$t/b"
    if cmp -s "$t/a" "$t/b"; then
      echo "same: $f"
    else
      echo "DIFF: $f"
      rc=1
    fi
  done
  rm -rf "$t"
  return $rc
}

case "${1:-}" in
record) [ $# -ge 3 ] || { echo "usage: outputs.sh record BIN DIR [quick]" >&2; exit 2; }
  record "$2" "$3" "${4:-}" ;;
compare) [ $# -eq 3 ] || { echo "usage: outputs.sh compare DIR1 DIR2" >&2; exit 2; }
  compare "$2" "$3" ;;
*) echo "usage: outputs.sh record BIN DIR [quick] | compare DIR1 DIR2" >&2; exit 2 ;;
esac
