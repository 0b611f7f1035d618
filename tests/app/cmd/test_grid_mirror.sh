#!/bin/sh
# test_grid_mirror.sh: a grid takes its half dperp < 0 as the mirror image only when the model
# is mirror-symmetric (engine_mirror.c) and the scene is (face 0 or 180, no roll or yaw, set
# mirror on). 'show mirror' says which, and what breaks it. A drone with its centre of mass
# 8 cm to one side is not mirrored: its grid's cells are those of its own impacts on each side
# (before, the grid copied one side onto the other), and a Monte Carlo over the face computes
# face -60 instead of taking face 60's Q. The built-in B gives the same cells mirrored or not.
. tests/lib.sh
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }

# the built-in model: symmetric; what the scene can break
run -c 'case A; show mirror; set face 30; show mirror; set face 180; set yaw 5; show mirror; set yaw 0; set mirror off; show mirror'
check show_symmetric cond 'sed -n 1p "$TMP/out" | grep -q "mirror  *on  (derived: the next grid simulates dperp >= 0 and mirrors it)"'
check show_face cond 'sed -n 2p "$TMP/out" | grep -q "every cell: the face is neither 0 nor 180 deg"'
check show_yaw cond 'sed -n 3p "$TMP/out" | grep -q "every cell: roll or yaw breaks the symmetry"'
check show_off cond 'sed -n 4p "$TMP/out" | grep -q "^mirror  *off  (derived: the next grid simulates every cell: set mirror off)"'
run -c 'set mirror sideways'
check bad_value cond '[ $RC -ne 0 ] && [ $(lines "$TMP/err") -eq 1 ] && grep -q "mirror" "$TMP/err"'

# B mirrored and not: the same cells (the RA3 and the person are symmetric to the bit)
G='set format csv; set recall off; case B; set wind 0; set step 0.15; grid'
run -c "$G; export grid $TMP/on.csv; set mirror off; grid; export grid $TMP/off.csv"
check b_same_cells cond '[ $RC -eq 0 ] && [ $(lines "$TMP/on.csv") -gt 50 ] && cmp -s "$TMP/on.csv" "$TMP/off.csv"'
# the summary's note counts the mirror images apart from the simulated and geometric cells
n() { grep 'impacts simulated' "$TMP/out" | sed -n "$1p" | sed -n "s/.* \([0-9]*\) $2.*/\1/p"; }
check note_counts cond '[ -n "$(n 1 "their mirror")" ] && [ $(( $(n 1 "impacts simulated") + $(n 1 "their mirror") )) -eq $(n 2 "impacts simulated") ] &&
  [ "$(n 1 "cells decided")" = "$(n 2 "cells decided")" ] && ! grep "impacts simulated" "$TMP/out" | sed -n 2p | grep -q mirror'

# a drone with its centre of mass to one side (left, +y): not mirrored, its own impacts
run -c "model save $TMP/m.urm"
sed 's/^\(body main parent=world joint=free pos=0,0,0 mass=[0-9.]*\)/\1 com=0,0.08,0/' "$TMP/m.urm" >"$TMP/asym.urm"
check asym_edited cond '! cmp -s "$TMP/m.urm" "$TMP/asym.urm"'
L="set format csv; model load $TMP/asym.urm; case B; set wind 0; set step 0.15"
run -c "$L; show mirror"
check asym_said has "$TMP/out" 'every cell: body main has no mirror image'
run -c "$L; grid; grid cells; impact 0.3 0.15; impact 0.3 -0.15"
cell() { grep "^0.300,$1," "$TMP/out" | awk -F, '{ print $NF }'; }
imp() { grep "^0.3,$1," "$TMP/out" | awk -F, '{ print $NF }'; }
# (P at (0.3, 0.15) is 0.99 and at (0.3, -0.15) 0.08 today: the sides differ)
check asym_sides_differ awk -v a="$(cell 0.150)" -v b="$(cell -0.150)" 'BEGIN { exit !(a - b > 0.5 || b - a > 0.5) }'
check asym_left_own cond '[ -n "$(imp 0.15)" ] && [ "$(cell 0.150)" = "$(imp 0.15)" ]'
check asym_right_own cond '[ -n "$(imp -0.15)" ] && [ "$(cell -0.150)" = "$(imp -0.15)" ]'

# its Monte Carlo over the face: face -60 is its own, not face 60's
run -c "$L; dist face discrete -60,60 0.5,0.5; set mc_method exact; montecarlo 4; montecarlo samples; set face -60; grid; set face 60; grid"
qs() { grep "^[0-9],$1,1,chute," "$TMP/out" | sed -n 1p | cut -d, -f5; }
qg() { grep "^B,0,[0-9.]*,[0-9.]*,$1," "$TMP/out" | cut -d, -f9; }
check mc_own_face cond 'near "$(qs -60)" "$(qg -60)" 5e-5 && near "$(qs 60)" "$(qg 60)" 5e-5 && ! near "$(qs -60)" "$(qs 60)" 1e-3'
finish
