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
# DIR receives raw.csv (everything uasimpact printed), raw.err, run.txt (date, commit, machine, wall
# time of the run), report.md, report.html (the run as uasimpact's 'report' writes it), and the
# CSV files the report describes. The paper's numbers come from $PAPER_VALUES and its
# P{F|Delta} grids from $PAPER_GRIDS (sessions/paper/README.md); the comparison is made by
# scripts/reproduce.awk, with the labels and the scoring of Table 17 of scripts/table17.awk
# (which 'make sensitivity' shares). Without any of them nothing is run: one line names the
# missing file and the status is 1. Environment: UASIMPACT (default ./uasimpact),
# PAPER_VALUES (default sessions/paper/values.csv), PAPER_GRIDS (default sessions/paper/grids).
# Run from the source directory.
set -u
out=build/reproduce step="" norun=0
UASIMPACT=${UASIMPACT:-./uasimpact}
PAPER_VALUES=${PAPER_VALUES:-sessions/paper/values.csv}
PAPER_GRIDS=${PAPER_GRIDS:-sessions/paper/grids}
# the paper's printed grids the report compares with (sessions/paper/grids/README.md)
GRID_FILES="table04_caseA_wind0.csv table05_caseB_wind0.csv table06_caseC_wind0.csv
  table08_caseA_wind10.csv table09_caseB_wind10.csv table10_caseC_wind10.csv
  table15_caseA1_wind10.csv table16_caseA2_wind10.csv"
while getopts o:s:n opt; do
  case $opt in
    o) out=$OPTARG ;;
    s) step=$OPTARG ;;
    n) norun=1 ;;
    *) echo "usage: scripts/reproduce.sh [-o DIR] [-s STEP] [-n]" >&2; exit 2 ;;
  esac
done
if [ ! -x "$UASIMPACT" ]; then
  echo "reproduce: $UASIMPACT is not built (run make)" >&2
  exit 1
fi
# the paper's data first: a report without it would be empty tables
if [ ! -r "$PAPER_VALUES" ] || [ ! -s "$PAPER_VALUES" ]; then
  echo "reproduce: the paper's values $PAPER_VALUES are missing or empty (see sessions/paper/README.md; PAPER_VALUES names another file)" >&2
  exit 1
fi
for g in $GRID_FILES; do
  if [ ! -r "$PAPER_GRIDS/$g" ] || [ ! -s "$PAPER_GRIDS/$g" ]; then
    echo "reproduce: the paper's grid $PAPER_GRIDS/$g is missing or empty (see sessions/paper/README.md; PAPER_GRIDS names another folder)" >&2
    exit 1
  fi
done
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
       h ~ /,q,seconds(,complete)?$/ || h == "case,wind,face,speed,angle,q" || h ~ /^case,wind,p_centre,/ { n++ }
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
  # the sessions, then the study report of the same run (report.html, the machinery of 'report')
  printf 'source "%s"\nreport "%s/report.html"\n' "$ses" "$out" >"$out/run.ses" || exit 1
  "$UASIMPACT" -c 'set format csv' "$out/run.ses" >"$out/raw.csv" 2>"$out/raw.err" &
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
    echo "reproduce: uasimpact failed (status $rc) after ${wall} s:" >&2
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

# the paper's grids as uasimpact's 'grid load' reads them: the full-plane Q it computes
: >"$out/paper-load.txt"
for g in $GRID_FILES; do
  f=$PAPER_GRIDS/$g
  q=$(NO_COLOR=1 "$UASIMPACT" -c "grid load $f; grid show" |
      sed -n 's/.*: Q = \([0-9.]*\) m^2 over the full plane.*/\1/p')
  if [ -z "$q" ]; then
    echo "reproduce: uasimpact could not load the paper's grid $f ('grid load' gave no Q)" >&2
    exit 1
  fi
  echo "$f $q" >>"$out/paper-load.txt"
done

# the comparison and the report
# grids recalled: a note names one grid ('the grid is ...') or a sweep's ('the grids of wind 0, 4
# are ...')
recalled=$(awk '/^# recalled: the grid is / { n++ }
                /^# recalled: the grids of / { s = $0; sub(/^# recalled: the grids of [a-z]+ /, "", s)
                                               sub(/ are identical.*/, "", s); n += split(s, x, ",") }
                END { print n + 0 }' "$out/raw.csv")
awk -f scripts/table17.awk -f scripts/reproduce.awk -v out="$out" -v values="$PAPER_VALUES" \
    -v run="$out/run.txt" -v loads="$out/paper-load.txt" -v recalled="$recalled" \
    "$out/raw.csv" || exit 1
echo "reproduce: report in $out/report.md"
if [ -s "$out/report.html" ]; then echo "reproduce: the run's study report in $out/report.html"; fi
