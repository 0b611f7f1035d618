# test_cmd_history.sh: history's time range FROM:TO (ms from tau) when it keeps no sample. The
# samples of an impact start some way after tau (case C's near 11 ms, case A's near 24 ms), so
# 'history head_acc 0:2' printed a bare header, and a user could not tell an empty range from a
# lost impact: now a note says where the samples run, for channels and for all; a range that
# keeps samples gets no such note. Case C's centre impact: a fraction of a second.
. tests/lib.sh

run -c 'case C; impact 0 0; set format csv; history head_acc; history head_acc 0:2; history 1000:;
  history :1; history head_acc 12:13'
check status [ "$RC" -eq 0 ]
# where the samples run, as history itself prints them (s from tau)
T0=$(awk -F, '$1 == "t" { h++; next } h == 1 && $1 ~ /^[0-9]/ { print $1; exit }' "$TMP/out")
T1=$(awk -F, '$1 == "t" { h++; next } h == 1 && $1 ~ /^[0-9]/ { t = $1 } END { print t }' "$TMP/out")
check samples_read cond '[ -n "$T0" ] && [ -n "$T1" ]'
RUN=$(awk -v a="$T0" -v b="$T1" 'BEGIN { printf "run from %.4g to %.4g ms", 1e3 * a, 1e3 * b }')
check note_channels grep -q "^# no samples in 0:2 ms from tau: the last impact's samples $RUN" "$TMP/out"
check note_all_open_to grep -q "^# no samples in 1000: ms from tau: the last impact's samples $RUN" "$TMP/out"
check note_all_open_from grep -q "^# no samples in :1 ms from tau" "$TMP/out"
# three empty ranges, three notes; the range 12:13 keeps samples and gets none
check notes_only_empty [ "$(grep -c "^# no samples in" "$TMP/out")" -eq 3 ]
check range_kept awk -F, '$1 == "t" { h++; n = 0; bad = 0; next }
  h == 5 && $1 ~ /^[0-9]/ { n++; if ($1 < 0.012 || $1 > 0.013) bad++ } END { exit !(n > 0 && !bad) }' "$TMP/out"
finish
