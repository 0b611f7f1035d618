# test_candidate.sh: the RA3 rebuilt on its materials (src/models/candidate/ra3.urm, issue 33),
# the model under calibration: it loads in place of the built-in RA3; its arm hinges are those
# beam theory gives for its carbon tube (k = 3EI/L, M_p = sigma_y Z_p, closed forms computed here
# from the file's own D, t, L, E and yield); it declares no law of the person's head (the scalp
# laws come from the person's layer, the foam's backing too); arm_t moves the hinge as the
# formulas say; the built-in RA3 is it with the refit's values.
. tests/lib.sh
F=src/models/candidate/ra3.urm

run -c "model load $F; model notes"
check loads cond '[ $RC -eq 0 ] && [ ! -s "$TMP/err" ]'
# closed forms for the tube D = 0.06 m, t = arm_t, L = 0.41 m, E 54.8 GPa, yield 59.3 MPa
hinge() { # t -> "k Mp"
  awk -v t="$1" 'BEGIN { D = 0.06; d = D - 2 * t; pi = atan2(0, -1)
    I = pi * (D^4 - d^4) / 64; Zp = (D^3 - d^3) / 6
    printf "%.6g %.6g\n", 3 * 5.48e10 * I / 0.41, 5.93e7 * Zp }'
}
read -r K MP <<EOT
$(hinge 0.00078)
EOT
got_k=$(awk -F'= ' '/restraint .arm1. dof 0 .*hinge k = 3 E I/ { split($3, a, " "); print a[1]; exit }' "$TMP/out")
got_mp=$(awk -F'= ' '/restraint .arm1. dof 0 .*hinge M_p/ { split($3, a, " "); print a[1]; exit }' "$TMP/out")
check hinge_k awk -v a="$got_k" -v b="$K" 'BEGIN { exit !(a != "" && (a - b)^2 <= (1e-5 * b)^2) }'
check hinge_mp awk -v a="$got_mp" -v b="$MP" 'BEGIN { exit !(a != "" && (a - b)^2 <= (1e-5 * b)^2) }'
check six_arms cond '[ "$(grep -c "hinge M_p = sigma_y Z_p" "$TMP/out")" -eq 12 ]'
# no scalp law in the drone file: the head pairs' laws are derived from the person's layer
check no_head_law cond '! grep -q "^law \(frame_head\|arm_head\)" '"$F"' && grep -q "pairs .fh., frame on head_cranium (layer scalp, material carbon): Hertz" "$TMP/out"'
# nor for the foam: its backing is derived from the person's layer (the scalp's K of Table B1's
# law on the head, 4/3 E* sqrt(R) of scalp and carbon), no scalp law written for it
check foam_backing_derived cond '! grep -q "E1=2.23e7" '"$F"' && grep -q "pairs .cg., foam on layer scalp: backing K = 4/3 E\* sqrt(R) = 9.59907e+06" "$TMP/out"'

# a thicker wall: the hinge moves as the closed forms say
run -c "model load $F; set arm_t 1.5 mm; model notes"
read -r K2 MP2 <<EOT
$(hinge 0.0015)
EOT
got_k2=$(awk -F'= ' '/restraint .arm1. dof 0 .*hinge k = 3 E I/ { split($3, a, " "); print a[1]; exit }' "$TMP/out")
check hinge_follows_t awk -v a="$got_k2" -v b="$K2" 'BEGIN { exit !(a != "" && (a - b)^2 <= (1e-5 * b)^2) }'

# the built-in RA3 is this file with the refit's stage-1 values (the result's 'set' lines, to
# the printed digits: the values are copied, so equal to 1e-12); this file keeps the fit's start
awk '$1 == "set" { print $2, $3 }' src/models/refit-drone-result.txt >"$TMP/fit"
run -c "$(awk '{ printf "%sshow %s", (NR > 1 ? "; " : ""), $1 }' "$TMP/fit")"
check builtin_is_refit awk 'NR == FNR { v[$1] = $2; k++; next } ($1 in v) { d = $2 - v[$1]
  if (d * d > 1e-24 * v[$1] * v[$1]) exit 1; n++ } END { exit !(k == 9 && n == 9) }' "$TMP/fit" "$TMP/out"
check start_kept grep -q "^param arm_t 0.78 mm" "$F"
finish
