#!/bin/sh
# test_membrane_convergence.sh: issue 32's convergence of the membrane airbag on the cheap
# quantities: at case A's centre (zero wind), the peak head acceleration and P{F|Delta} change by
# at most 5 % from the default mesh to a twice finer one and by at most 2 % when the time step
# is halved (scripts/membrane-convergence.sh --centre; the grid's Q is
# tests/test_membrane_convergence_grid.sh's).
. tests/lib.sh

sh scripts/membrane-convergence.sh --centre >"$TMP/conv" 2>&1
cat "$TMP/conv"
check four_lines cond '[ $(grep -c "PASS\|FAIL" "$TMP/conv") -eq 4 ]'
check mesh_head_acc grep -q "^centre peak head acceleration: mesh.*PASS" "$TMP/conv"
check mesh_p grep -q "^centre P{F|Delta}: mesh.*PASS" "$TMP/conv"
check dt_head_acc grep -q "^centre peak head acceleration: dt.*PASS" "$TMP/conv"
check dt_p grep -q "^centre P{F|Delta}: dt.*PASS" "$TMP/conv"
finish
