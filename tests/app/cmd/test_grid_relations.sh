#!/bin/sh
# test_grid_relations.sh: routes to the same numbers that must agree (metamorphic checks), on the
# built-in case B under 10 m/s wind at face 45, where no mirror image is taken and the grid is
# not symmetric. (1) Each cell with contact, and every fifth without, equals the single 'impact'
# at its offset (the criteria and P to the 6 digits both print: 2e-5 relative). (2) Face 45 and
# face -315 are one direction: the same grid, byte for byte. (3) The RA3 and the person are
# mirror-symmetric, so face -45 is face 45 seen in a mirror: its cell (dpar, -dperp) is face 45's
# (dpar, dperp), byte for byte, and Q is the same. A grid that swapped the sides, took the face
# with the wrong sign or not modulo 360 fails one of them.
. tests/lib.sh

G='set format csv; set recall off; case B; set wind 10; set step 0.25'
run -c "$G; set face 45; grid; export grid $TMP/f45.csv; set face -315; grid; export grid $TMP/f-315.csv;
  set face -45; grid; export grid $TMP/f-45.csv"
check grids_run cond '[ $RC -eq 0 ] && [ $(grep -c "^B,10,.*,1$" "$TMP/out") -eq 3 ]'
q() { grep "^B,10," "$TMP/out" | sed -n "$1p" | cut -d, -f9; }
contact=$(awk -F, 'NR > 1 && $3 == 1' "$TMP/f45.csv" | wc -l)
check grid_has_contacts cond '[ "$contact" -gt 30 ] && [ -n "$(q 1)" ] && awk "BEGIN { exit !($(q 1) > 0.3) }"'

# (1) the cells against their own impacts
awk -F, 'NR > 1 && ($3 == 1 || NR % 5 == 0) { printf "; impact %s %s", $1, $2 }' "$TMP/f45.csv" >"$TMP/imp"
run -c "set format csv; case B; set wind 10; set face 45$(cat "$TMP/imp")"
grep -v -e '^#' -e '^dpar' "$TMP/out" >"$TMP/rows"
check impacts_run cond '[ $RC -eq 0 ] && [ $(lines "$TMP/rows") -eq $(grep -o impact "$TMP/imp" | wc -l) ]'
check cells_equal_impacts awk -F, '
  function off(x, y, t) { d = x - y; if (d < 0) d = -d; m = (x < 0 ? -x : x); if ((y < 0 ? -y : y) > m) m = y < 0 ? -y : y
                          return d > t * m + 1e-12 }
  FNR == 1 { f++ }
  f == 1 && FNR > 1 { k = sprintf("%.3f %.3f", $1, $2); c[k] = $3; h[k] = $4; n[k] = $5; vt[k] = $6; va[k] = $7; p[k] = $8; next }
  f == 2 { k = sprintf("%.3f %.3f", $1, $2); seen++
           if (!(k in p) || c[k] != $3 || off(h[k], $4, 2e-5) || off(n[k], $5, 2e-5) || off(vt[k], $10, 2e-5) ||
               off(va[k], $11, 2e-5) || off(p[k], $NF, 2e-5)) { print "differs at", k; bad = 1 } }
  END { exit !(seen > 30 && !bad) }' "$TMP/f45.csv" "$TMP/rows"

# (2) face -315 is face 45
check face_modulo_360 cond 'cmp -s "$TMP/f45.csv" "$TMP/f-315.csv" && [ "$(q 1)" = "$(q 2)" ]'

# (3) face -45 is face 45 mirrored: dperp -> -dperp, cell by cell
flip() { awk -F, -v OFS=, 'NR > 1 { $2 = sprintf("%.3f", -$2); if ($2 == "-0.000") $2 = "0.000"; print }' "$1" | LC_ALL=C sort; }
body() { awk 'NR > 1' "$1" | LC_ALL=C sort; }
flip "$TMP/f-45.csv" >"$TMP/m"
body "$TMP/f45.csv" >"$TMP/b"
check face_mirrored cond 'cmp -s "$TMP/m" "$TMP/b" && [ "$(q 1)" = "$(q 3)" ] && ! cmp -s "$TMP/f45.csv" "$TMP/f-45.csv"'
finish
