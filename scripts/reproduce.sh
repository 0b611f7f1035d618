#!/bin/sh
# reproduce.sh: 'make reproduce': run sessions/paper.ses (every reproduction of the paper) with CSV
# output, then write a side-by-side report of our numbers, the paper's and their ratio.
#
#   scripts/reproduce.sh [-o DIR] [-s STEP] [-n]
#     -o DIR   output folder (default build/reproduce)
#     -s STEP  a quick look, not a reproduction: every grid at pitch STEP m instead of the paper's
#              0.05 m (copies of the sessions with 'set step STEP' after each 'case'); the
#              cell-by-cell comparison with the paper's grids is then skipped
#     -n       no run: write the report again from DIR/raw.csv and DIR/run.txt
#
# DIR receives raw.csv (everything uasrisk printed), raw.err, run.txt (date, commit, machine, wall
# time of the run), report.md, and the CSV files the report describes. The paper's numbers come
# from sessions/paper-values.csv and its P{F|Delta} grids from $PAPER_GRIDS; the comparison is
# made by scripts/reproduce.awk. Environment: UASRISK (default ./uasrisk), PAPER_GRIDS (default
# ../shared/paper/grids). Run from the source directory.
set -u
out=build/reproduce step="" norun=0
UASRISK=${UASRISK:-./uasrisk}
PAPER_GRIDS=${PAPER_GRIDS:-../shared/paper/grids}
while getopts o:s:n opt; do
  case $opt in
    o) out=$OPTARG ;;
    s) step=$OPTARG ;;
    n) norun=1 ;;
    *) echo "usage: scripts/reproduce.sh [-o DIR] [-s STEP] [-n]" >&2; exit 2 ;;
  esac
done
if [ ! -x "$UASRISK" ]; then
  echo "reproduce: $UASRISK is not built (run make)" >&2
  exit 1
fi
mkdir -p "$out" || exit 1

# the number of grids a session runs: grid and compare one each, sweep one per value
grids_of() {
  awk '$1 == "source" { while ((getline l < $2) > 0) { split(l, w, " ")
         if (w[1] == "grid" && w[2] == "") n++; else if (w[1] == "compare") n++
         else if (w[1] == "sweep") n += split(w[3], v, ",") } close($2) }
       END { print n + 0 }' "$1"
}

# grids finished so far: data rows under the headers of grid, sweep and compare
grids_done() {
  awk '/^#/ { next } /^(case|dpar),/ { h = $0; next }
       h ~ /,q,seconds$/ || h == "case,wind,face,speed,angle,q" || h ~ /^case,wind,p_centre,/ { n++ }
       END { print n + 0 }' "$1"
}

if [ "$norun" -eq 0 ]; then
  ses=sessions/paper.ses
  if [ -n "$step" ]; then
    mkdir -p "$out/sessions" || exit 1
    for f in sessions/*.ses; do
      sed -e "s/^case \([A-Z0-9]*\)\$/case \1; set step $step/" \
          -e "s|^source sessions/|source $out/sessions/|" "$f" >"$out/$f" || exit 1
    done
    ses=$out/sessions/paper.ses
  fi
  total=$(grids_of "$ses")
  commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  if [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ]; then
    commit="$commit (with uncommitted changes)"
  fi
  cpu=$(sed -n 's/^model name[^:]*: *//p' /proc/cpuinfo 2>/dev/null | head -1)
  load=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)
  echo "reproduce: running $ses ($total grids) into $out/raw.csv; progress every minute"

  started=$(date -u '+%Y-%m-%d %H:%M:%S UTC')
  start=$(date +%s)
  "$UASRISK" -c 'set format csv' "$ses" >"$out/raw.csv" 2>"$out/raw.err" &
  pid=$!
  t=0
  while kill -0 "$pid" 2>/dev/null; do
    sleep 2
    t=$((t + 2))
    if [ $((t % 60)) -eq 0 ]; then
      echo "reproduce: $((t / 60)) min, $(grids_done "$out/raw.csv") of $total grids"
    fi
  done
  wait "$pid"
  rc=$?
  wall=$(($(date +%s) - start))
  {
    echo "started=$started"
    echo "date=$(date -u '+%Y-%m-%d %H:%M:%S UTC')"
    echo "commit=$commit"
    echo "machine=$(uname -srm)${cpu:+, $cpu}"
    echo "nproc=$(nproc 2>/dev/null || echo '?')"
    echo "load=$load"
    echo "sessions=$ses"
    if [ -n "$step" ]; then echo "step=$step m (a quick look on coarse grids)"
    else echo "step=0.05 m (the paper's)"; fi
    echo "grids=$total"
    echo "wall=$wall"
    echo "status=$rc"
  } >"$out/run.txt"
  if [ "$rc" -ne 0 ]; then
    echo "reproduce: uasrisk failed (status $rc) after ${wall} s:" >&2
    cat "$out/raw.err" >&2
    exit 1
  fi
  echo "reproduce: $total grids in ${wall} s"
fi
for f in "$out/raw.csv" "$out/run.txt"; do
  if [ ! -r "$f" ]; then
    echo "reproduce: $f is missing (run without -n first)" >&2
    exit 1
  fi
done

# the paper's grids as uasrisk's 'grid load' reads them: the full-plane Q it computes
: >"$out/paper-load.txt"
for f in "$PAPER_GRIDS"/table*.csv; do
  [ -r "$f" ] || continue
  q=$(NO_COLOR=1 "$UASRISK" -c "grid load $f; grid show" |
      sed -n 's/.*: Q = \([0-9.]*\) m^2 over the full plane.*/\1/p')
  echo "$f ${q:-nan}" >>"$out/paper-load.txt"
done

# the comparison and the report
# grids recalled: a note names one grid ('the grid is ...') or a sweep's ('the grids of wind 0, 4
# are ...')
recalled=$(awk '/^# recalled: the grid is / { n++ }
                /^# recalled: the grids of / { s = $0; sub(/^# recalled: the grids of [a-z]+ /, "", s)
                                               sub(/ are identical.*/, "", s); n += split(s, x, ",") }
                END { print n + 0 }' "$out/raw.csv")
awk -f scripts/reproduce.awk -v out="$out" -v values=sessions/paper-values.csv \
    -v run="$out/run.txt" -v loads="$out/paper-load.txt" -v recalled="$recalled" \
    "$out/raw.csv" || exit 1
echo "reproduce: report in $out/report.md"
