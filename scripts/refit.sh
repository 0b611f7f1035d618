#!/bin/sh
# refit.sh: the mechanical step between the refit's two stages (uasimpact-model(5), CALIBRATION,
# "The refit on materials"). Stage 1 (src/models/refit-drone.spec) fits the drone on cases B
# and C; this script writes stage 2's spec from stage 1's result, as declared before either ran:
# the drone's values held (set), the bag's plan bounded by shares 1-1.375 of the fitted frame.
#   sh scripts/refit.sh bag RESULT    > src/models/refit-bag.spec
#   sh scripts/refit.sh total RESULT1 RESULT2 > SPEC  (the three cases at the final point: the
#                                       injury choice with the lowest total L_A + L_B + L_C)
# RESULT is a result.txt of make calibrate: its 'set NAME VALUE' lines are read, nothing else.
set -eu
what=${1:-}
[ "$what" = bag ] || [ "$what" = total ] || {
  echo "usage: refit.sh bag RESULT | refit.sh total RESULT1 RESULT2" >&2
  exit 2
}
shift
for f in "$@"; do [ -r "$f" ] || { echo "refit.sh: $f: cannot read" >&2; exit 1; }; done
# the held values: only lines 'set NAME NUMBER' with a plain name and a number are taken
sets=$(awk '$1 == "set" && NF == 3 && $2 ~ /^[A-Za-z0-9_]+$/ &&
  $3 ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ { print "set " $2 " " $3 }' "$@")
val() { printf '%s\n' "$sets" | awk -v n="$1" '$2 == n { v = $3 } END { if (v == "") exit 1; print v }'; }
fa=$(val frame_a) || { echo "refit.sh: no 'set frame_a' in $*" >&2; exit 1; }
fb=$(val frame_b) || { echo "refit.sh: no 'set frame_b' in $*" >&2; exit 1; }

cat <<EOT
# refit-$what.spec: written by scripts/refit.sh $what from $* (uasimpact-model(5),
# CALIBRATION, "The refit on materials"). Do not edit: regenerate.
load src/models/candidate/ra3.urm
$sets
set bag_membrane 1
set bag_mesh 14
set tmax 0.4
set window 0.12
loss integral
EOT
if [ "$what" = bag ]; then
  # stage 2: case A, the bag's plan as shares 1-1.375 of the fitted frame, and its depth
  awk -v a="$fa" -v b="$fb" 'BEGIN {
    printf "case A 7.5 sessions/paper/grids/table04_caseA_wind0.csv\n"
    printf "free bag_a %.9g %.9g %.9g   # m: 1 .. 1.375 frame_a (start 1.322)\n", a, 1.375 * a, 1.322 * a
    printf "free bag_b %.9g %.9g %.9g   # m: 1 .. 1.375 frame_b (start 1.304)\n", b, 1.375 * b, 1.304 * b
    printf "free bag_depth 0.05 0.30 0.2956   # m: the membrane bag depth below its mount\n"
    printf "corner 1e-4 1e-3 3   # amended: ends at a corner of the bounds (man page)\n" }'
else
  # the final point: all three cases, nothing free but a no-op the tool needs (frame_a at its value)
  awk -v a="$fa" 'BEGIN {
    printf "case C 40.6 sessions/paper/grids/table06_caseC_wind0.csv\n"
    printf "case B 7.5 sessions/paper/grids/table05_caseB_wind0.csv\n"
    printf "case A 7.5 sessions/paper/grids/table04_caseA_wind0.csv\n"
    printf "free frame_a %.9g %.9g %.9g   # held: evaluated once (-e) at its value\n", 0.5 * a, 2 * a, a }'
fi
cat <<'EOT'
choice nij rescale nij_rescale=1
choice nij plain nij_rescale=0
choice ais upper pof_ais2=0.02,pof_ais3=0.10,pof_ais4=0.50
choice ais mid pof_ais2=0.015,pof_ais3=0.09,pof_ais4=0.275
choice order raise nij_order=1
choice order lower nij_order=2
simplex 1
tol 1e-3
maxeval 600
restarts 3
gain 0.005
EOT
