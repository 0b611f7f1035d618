#!/bin/sh
# test_history_criteria.sh: an exported history recomputed on its own gives the criteria 'impact'
# printed. From the samples of 'export history' alone (head acceleration, upper-neck loads, plate
# deflections), awk computes HIC15 (the exact maximum over sample pairs at most 15 ms apart of
# (t2 - t1) (mean a/g)^2.5, the mean from the trapezoid integral), Nij (the engine's Fz and My
# negated, as uasimpact(1) says, and FMVSS 208's intercepts, per mode), VC of thorax and abdomen
# (the five-point rate of ECE R94, three-point at the ends) and P from the laws of
# uasimpact-injury(7) with their default constants; each must equal the row of 'impact'. The
# impact rows print 6 significant digits and the samples 9: tolerances 2e-5 relative (1e-4 for
# VC, whose rate is a difference of samples), 1e-9 absolute. Two impacts: case B under 10 m/s
# wind (HIC15 2251, Nij 0.61 in compression-extension) and case C at face 90 (Nij 10 in
# compression-extension, VC thorax 0.16 m/s).
. tests/lib.sh

recompute() { # HISTORY.csv ROW.csv: the impact's row and the history's own criteria, paired
  awk -F, '
    function lg(x) { return x > 700 ? 0 : 1 / (1 + exp(x)) }
    function phic(h) { return h <= 0 ? 0 : lg(4.9 + 200 / h - 0.00351 * h) }
    function q(a, b, n) { return (lg(a - b * n) - lg(a)) / (1 - lg(a)) }
    function pnij(n,   q2, q3, q4, q5) {
      q2 = q(2.054, 1.195, n); q3 = q(3.227, 1.969, n); q4 = q(2.693, 1.195, n); q5 = q(3.817, 1.195, n)
      if (q3 > q2) q3 = q2; if (q4 > q3) q4 = q3; if (q5 > q4) q5 = q4
      return 0.02 * (q2 - q3) + 0.10 * (q3 - q4) + 0.5 * (q4 - q5) + q5 }
    function pvc(v, v25, f,   a) { a = log(3) + 6.08 * v25; return f * q(a, 6.08, v) }
    function vc(d, d0,   i, v, m, x) {
      m = 0
      for (i = 1; i <= n; i++) {
        if (i > 2 && i < n - 1) v = (8 * (d[i + 1] - d[i - 1]) - (d[i + 2] - d[i - 2])) / (12 * T)
        else if (i == 1) v = (-3 * d[1] + 4 * d[2] - d[3]) / (2 * T)
        else if (i == n) v = (3 * d[n] - 4 * d[n - 1] + d[n - 2]) / (2 * T)
        else v = (d[i + 1] - d[i - 1]) / (2 * T)
        x = v * d[i] / d0; if (x > m) m = x
      }
      return m }
    FNR == 1 { for (k = 1; k <= NF; k++) col[FILENAME, $k] = k; next }
    FILENAME == ARGV[1] {
      n++; t[n] = $1
      a[n] = sqrt($(col[FILENAME, "head_acc_x"]) ^ 2 + $(col[FILENAME, "head_acc_y"]) ^ 2 + \
                  $(col[FILENAME, "head_acc_z"]) ^ 2) / 9.80665
      fz[n] = -$(col[FILENAME, "neck_load_fz"]); my[n] = -$(col[FILENAME, "neck_load_my"])
      dt[n] = $(col[FILENAME, "chest_defl"]); da[n] = $(col[FILENAME, "abd_defl"]); next }
    { for (k in col) { split(k, s, SUBSEP); if (s[1] == FILENAME) row[s[2]] = $(col[k]) } }
    END {
      T = t[2] - t[1]
      I[1] = 0; for (i = 2; i <= n; i++) I[i] = I[i - 1] + (a[i] + a[i - 1]) / 2 * (t[i] - t[i - 1])
      h = 0
      for (i = 1; i <= n; i++) for (j = i + 1; j <= n && t[j] - t[i] <= 0.015 + 1e-12; j++)
        if (I[j] > I[i] && (v = (I[j] - I[i]) ^ 2.5 / (t[j] - t[i]) ^ 1.5) > h) h = v
      for (i = 1; i <= n; i++) {
        m = (fz[i] >= 0 ? "tf" : "cf"); if (my[i] < 0) sub(/f$/, "e", m)
        v = (fz[i] >= 0 ? fz[i] / 6806 : -fz[i] / 6160) + (my[i] >= 0 ? my[i] / 310 : -my[i] / 135)
        if (v > N[m]) N[m] = v
      }
      nij = 0; for (m in N) if (N[m] > nij) nij = N[m]
      vt = vc(dt, 0.229); va = vc(da, 0.2185)
      pv = 1 - (1 - pvc(vt, 1.0, 0.5)) * (1 - pvc(va, 1.2, 1.0))
      p = 1 - (1 - phic(h)) * (1 - pnij(nij)) * (1 - pv)
      printf "hic15 %.9g %s 2e-5\nnij %.9g %s 2e-5\n", h, row["hic15"], nij, row["nij"]
      split("tf te cf ce", ms, " ")
      for (k = 1; k <= 4; k++) printf "nij_%s %.9g %s 2e-5\n", ms[k], N[ms[k]] + 0, row["nij_" ms[k]]
      printf "vc_thorax %.9g %s 1e-4\nvc_abdomen %.9g %s 1e-4\n", vt, row["vc_thorax"], va, row["vc_abdomen"]
      printf "p_hic %.9g %s 2e-5\np_nij %.9g %s 2e-5\np_vc %.9g %s 1e-4\np %.9g %s 2e-5\n",
        phic(h), row["p_hic"], pnij(nij), row["p_nij"], pv, row["p_vc"], p, row["p"] }' "$1" "$2"
}
agree() { # the pairs of recompute: each within its relative tolerance (1e-9 absolute)
  awk '{ d = $2 - $3; if (d < 0) d = -d; m = ($2 < 0 ? -$2 : $2); if ($3 > m) m = $3
         if (d > $4 * m + 1e-9) { print "differs:", $0; bad = 1 } n++ }
       END { exit !(n == 12 && !bad) }' "$1"
}

for spec in "B 10 0 -0.6 -0.2" "C 10 90 -0.2 0.2"; do
  set -- $spec
  tag=$(echo "$1_w$2_f$3" | tr -d -)
  run -c "set format csv; case $1; set wind $2; set face $3; impact $4 $5; export history $TMP/h.csv"
  grep -v '^#' "$TMP/out" >"$TMP/row.csv"
  check "${tag}_runs" cond '[ $RC -eq 0 ] && [ $(lines "$TMP/h.csv") -gt 200 ] && [ $(lines "$TMP/row.csv") -eq 2 ]'
  recompute "$TMP/h.csv" "$TMP/row.csv" >"$TMP/pairs.$1"
  check "${tag}_criteria_recomputed" agree "$TMP/pairs.$1"
done
# the impacts are the ones described above (a history without contact would agree trivially)
val() { awk -v k="$2" '$1 == k { print $3 }' "$TMP/pairs.$1"; }
gt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }
check impacts_hit cond 'gt "$(val B hic15)" 2000 && gt "$(val B nij_ce)" 0.5 && gt "$(val C nij_ce)" 5 &&
  gt "$(val C vc_thorax)" 0.1'
finish
