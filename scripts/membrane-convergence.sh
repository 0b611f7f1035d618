#!/bin/sh
# membrane-convergence.sh: 'make membrane-convergence': the membrane airbag's mesh and time-step
# convergence on case A (issue 32):
#   the peak head acceleration and P{F|Delta} at case A's centre, zero wind, at the default mesh
#   (the model's bag_mesh N), a mesh twice finer (2N) and the default time step halved;
#   Q of case A's zero-wind grid at meshes N and 2N and at mesh N with the time step halved (with
#   STEP, default 0.05; about a minute of grids on 2 threads since the bag's mass scaling: make
#   check runs both parts, tests/test_membrane_convergence.sh with --centre and
#   tests/test_membrane_convergence_grid.sh with --grid, side by side).
# Targets: <= 5 % from mesh N to 2N, <= 2 % for dt halved; each line says PASS or FAIL. The
# window is 0.12 s (uasimpact-model(5), BAGS: the 60 ms window ends a membrane impact early).
#   scripts/membrane-convergence.sh [--centre | --grid] [STEP]
set -u
UASIMPACT=${UASIMPACT:-./uasimpact}
only_centre=0
only_grid=0
if [ "${1:-}" = --centre ]; then
  only_centre=1
  shift
elif [ "${1:-}" = --grid ]; then
  only_grid=1
  shift
fi
step=${1:-0.05}
if ! awk -v s="$step" 'BEGIN { exit !(s ~ /^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/ && s + 0 > 0) }'; then
  echo "membrane-convergence: '$step' is not a grid step; accepted: [--centre | --grid] [STEP in m > 0]" >&2
  exit 2
fi
base='set format csv; case A; set descent paper; set wind 0; set bag_model membrane; set window 0.12'

# one centre impact: prints "peak_head_acc p"
centre() {
  "$UASIMPACT" -c "$base; $1; impact 0 0; history" 2>/dev/null | awk -F, '
    /^0,0,/ || /^0\.0*,0\.0*,/ { p = $NF }
    $1 == "head_acc" { a = $2 }
    END { print a, p }'
}

# Q of the zero-wind grid
gridq() {
  "$UASIMPACT" -c "$base; set threads 2; set step $step; $1; grid" 2>/dev/null |
    awk -F, '$1 == "A" { print $9 }'
}

rel() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.4f", (b - a) / a }'; }
verdict() { awk -v r="$1" -v t="$2" 'BEGIN { r = r < 0 ? -r : r; print (r <= t ? "PASS" : "FAIL") }'; }

n=$("$UASIMPACT" -c 'case A; show bag_mesh' 2>/dev/null | awk '$1 == "bag_mesh" { print $2 }')
n2=$((n * 2))
dt=$("$UASIMPACT" -c 'model params dt' 2>/dev/null | awk '{print $2}')
dt2=$(awk -v d="$dt" 'BEGIN { print d / 2 }')
if [ "$only_grid" -eq 0 ]; then
  set -- $(centre "set bag_mesh $n"); a1=$1 p1=$2
  set -- $(centre "set bag_mesh $n2"); a2=$1 p2=$2
  set -- $(centre "set bag_mesh $n; set dt $dt2"); ah=$1 ph=$2
  echo "centre peak head acceleration: mesh $n $a1, mesh $n2 $a2 m/s^2: change $(rel "$a1" "$a2") $(verdict "$(rel "$a1" "$a2")" 0.05)"
  echo "centre P{F|Delta}: mesh $n $p1, mesh $n2 $p2: change $(rel "$p1" "$p2") $(verdict "$(rel "$p1" "$p2")" 0.05)"
  echo "centre peak head acceleration: dt $dt s $a1, dt $dt2 s $ah: change $(rel "$a1" "$ah") $(verdict "$(rel "$a1" "$ah")" 0.02)"
  echo "centre P{F|Delta}: dt $dt s $p1, dt $dt2 s $ph: change $(rel "$p1" "$ph") $(verdict "$(rel "$p1" "$ph")" 0.02)"
fi
[ "$only_centre" -eq 1 ] && exit 0
q1=$(gridq "set bag_mesh $n")
q2=$(gridq "set bag_mesh $n2")
echo "Q of the zero-wind grid (step $step): mesh $n $q1, mesh $n2 $q2: change $(rel "$q1" "$q2") $(verdict "$(rel "$q1" "$q2")" 0.05)"
qh=$(gridq "set bag_mesh $n; set dt $dt2")
echo "Q of the zero-wind grid (step $step): dt $dt s $q1, dt $dt2 s $qh: change $(rel "$q1" "$qh") $(verdict "$(rel "$q1" "$qh")" 0.02)"
