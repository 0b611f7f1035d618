# test_injury_registry.sh: a criterion added through the registry (peak thorax deflection) as a
# user meets it: off by default (the paper's columns and P unchanged), its columns and its factor
# in P when 'set use_defl 1', its curve, and grid cells/export/load carrying its value
. tests/lib.sh

# off by default: the impact row has the paper's columns; on: defl_thorax and p_defl join, and
# p is 1 - (1 - p_off)(1 - p_defl) (to the printed 6 digits)
run -c 'set format csv; case B; impact 0 0; set use_defl 1; impact 0 0'
check defl_off_header has "$TMP/out" '^dpar,dperp,contact,hic15,nij,nij_tf,nij_te,nij_cf,nij_ce,vc_thorax,vc_abdomen,p_hic,p_nij,p_vc,p$'
check defl_on_header has "$TMP/out" '^dpar,dperp,contact,hic15,nij,nij_tf,nij_te,nij_cf,nij_ce,vc_thorax,vc_abdomen,defl_thorax,p_hic,p_nij,p_vc,p_defl,p$'
off=$(grep -v '^#' "$TMP/out" | sed -n 2p); on=$(grep -v '^#' "$TMP/out" | sed -n 4p)
check defl_fused awk -v a="$off" -v b="$on" 'BEGIN { split(a, x, ","); split(b, y, ",");
  want = 1 - (1 - x[15]) * (1 - y[16]); exit !(y[12] > 0 && y[16] > 0 &&
  (y[17] - want)^2 < 1e-11 && y[17] >= x[15]) }'

# the setting: shown with the others, strict range
run -c 'show use_defl'
check defl_setting_shown has "$TMP/out" '^use_defl  *0$'
run -c 'set use_defl 2'
check defl_setting_range cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "accepted: an integer in \[0, 1\]"'

# pof defl: 0 at 0, ascending, limit defl_pof (0.09); about half of it at D50 = 62.3 mm
run -c 'set format csv; pof defl'
check pof_defl cond '[ "$RC" -eq 0 ] && grep -v "^#" "$TMP/out" | awk -F, "NR==2&&\$2!=0{bad=1}
  NR>1{if(\$2+0<p)bad=1; p=\$2+0; n++} END{exit bad || !(n>=50 && p>0.0895 && p<=0.09)}"'
run -c 'pof bric'
check pof_unknown has "$TMP/err" "accepted: hic, nij, vc, vc_thorax, vc_abdomen or defl"

# grid cells and export carry defl_thorax when on; grid load reads it back
run -c "set format csv; case A; set bag_model analytic; set use_defl 1; set step 0.25; grid; grid cells; export grid $TMP/g.csv; grid load $TMP/g.csv; grid cells"
check grid_cells_defl cond '[ "$RC" -eq 0 ] &&
  [ "$(grep -c "^dpar,dperp,contact,hic15,nij,vc_thorax,vc_abdomen,defl_thorax,p$" "$TMP/out")" -eq 2 ]'
check grid_load_defl cond '[ "$(awk -F, "/^dpar/{n++} n==1&&!/^(#|dpar)/{print \$8}" "$TMP/out" | md5sum)" = \
  "$(awk -F, "/^dpar/{n++} n==2&&!/^(#|dpar)/{print \$8}" "$TMP/out" | md5sum)" ] &&
  awk -F, "!/^(#|dpar)/ && \$8 > 0 {f=1} END{exit !f}" "$TMP/out"'

# grid load reads every registry column it knows: the times, an integer-coded value by its codes
# (one line naming them when out of range), the PoF columns
cat >"$TMP/x.csv" <<'CSV'
dpar,dperp,contact,hic15,hic_t1,hic_t2,nij,nij_mode,vc_thorax,vc_abdomen,defl_thorax,p_hic,p_nij,p_vc,p_defl,p
0,0,1,1000,0.001,0.016,0.5,2,0.1,0.05,0.02,0.3,0.1,0.01,0.001,0.4
0,0.05,0,0,0,0,0,0,0,0,0,0,0,0,0,0
CSV
run -c "set format csv; set use_defl 1; grid load $TMP/x.csv; grid cells"
check load_registry_columns cond '[ "$RC" -eq 0 ] && has "$TMP/out" "^0.000,0.000,1,1000,0.5,0.1,0.05,0.02,0.4$"'
sed 's/,0.5,2,/,0.5,7,/' "$TMP/x.csv" >"$TMP/y.csv"
run -c "grid load $TMP/y.csv"
check load_bad_code cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "y.csv:2: nij_mode is 7, expected 0 (NTF), 1 (NTE), 2 (NCF) or 3 (NCE)"'
finish
