#!/bin/sh
# test_membrane_grid.sh: the membrane airbags through the workbench: a coarse zero-wind grid of
# case A with membrane bags gives the same cells with 1 and 2 threads (byte for byte); mirror
# impacts about the course give P within 1 % (the mesh is mirror symmetric up to its
# triangulation); 'model params bag' says how the membrane is sub-stepped; 'set bag_model'
# refuses a wrong value with one line; 'plot bag' needs a membrane impact.
. tests/lib.sh

G='set format csv; case A; set descent paper; set wind 0; set bag_model membrane; set step 0.2'
run -c "$G; set threads 1; grid; grid cells"
sed '/seconds/,+1d' "$TMP/out" | grep -v '^#' >"$TMP/g1"
check grid_runs cond '[ $RC -eq 0 ] && [ $(lines "$TMP/g1") -gt 20 ]'
run -c "$G; set threads 2; grid; grid cells"
sed '/seconds/,+1d' "$TMP/out" | grep -v '^#' >"$TMP/g2"
check threads_bitwise cmp -s "$TMP/g1" "$TMP/g2"
check some_contact cond 'awk -F, "\$3 == 1" "$TMP/g1" | grep -q .'

# (at (0.3, +-0.1) m, P 0.067 with the switched bag; at (0.2, +-0.3) it is 0.0056 now)
run -c 'set format csv; case A; set descent paper; set wind 0; set bag_model membrane; impact 0.3 0.1; impact 0.3 -0.1'
p1=$(grep -v '^#' "$TMP/out" | grep '^0.3' | sed -n 1p | awk -F, '{print $NF}')
p2=$(grep -v '^#' "$TMP/out" | grep '^0.3' | sed -n 2p | awk -F, '{print $NF}')
check mirror_impacts awk -v a="$p1" -v b="$p2" 'BEGIN { exit !(a > 0.01 && (a - b) / a < 0.01 && (b - a) / a < 0.01) }'

# (mesh 5 named: its node count; the default mesh changes at the switch)
run -c 'case A; set bag_model membrane; set bag_mesh 5; model params bag'
check substeps_said has "$TMP/out" '# derived, membrane bag_bottom: 152 nodes, 300 triangles.*sub-step'
run -c 'set bag_model fem'
check bad_bag_model cond '[ $RC -ne 0 ] && [ $(lines "$TMP/err") -eq 1 ] && grep -q "expected analytic or membrane" "$TMP/err"'
run -c 'case A; set bag_model analytic; impact 0 0; plot bag'
check plot_bag_needs_membrane grep -q "no membrane airbag touched" "$TMP/err"
finish
