# test_output.sh: what case/output.c and base/table.c write for other programs. An exported CSV
# is plain (a header and rows: no '#' line), its notes, units and provenance are in the sidecar
# FILE.meta.json (valid JSON, read back by grid load: a difference grid stays one), old exports
# with '#' note lines still load, 'set format json' prints every table (show too) as JSON that a
# JSON parser reads, a field with a comma is quoted, and Debian's pandas.read_csv reads every
# kind of export with its default arguments.
. tests/lib.sh

PY=/usr/bin/python3 # Debian's, with python3-pandas (scripts/setup.sh installs it)

# every kind of export from one short session (the analytic bag in case A here and at the prompt
# below: the exports are checked, whatever the bag; the membrane bag, A's default at the switch,
# costs ~20 s CPU per grid of A at 0.2 m)
run -c "set step 0.2; case C; impact 0 0; export history $TMP/h.csv; export contacts $TMP/c.csv;\
 grid; export grid $TMP/g.csv; design save c; case A; set bag_model analytic; grid; design save a;\
 sweep wind 0,4; export sweep $TMP/s.csv;\
 dist wind uniform 0 4; set surface_nodes 3; montecarlo 8; export montecarlo $TMP/m.csv;\
 design compare c a; export grid $TMP/d.csv"
check exports_ran [ "$RC" -eq 0 ]
for k in h c g s m d; do
  check "plain_$k" cond '[ -s "$TMP/$k.csv" ] && ! grep -q "^#" "$TMP/$k.csv"'
  check "sidecar_$k" [ -s "$TMP/$k.csv.meta.json" ]
done
check grid_header has "$TMP/g.csv" '^dpar,dperp,contact,hic15,nij,vc_thorax,vc_abdomen,p$'
check notes_not_on_stderr_in_script cond '! grep -q "^# grid of case" "$TMP/err"'

# the sidecar: JSON with the command, the program, the columns' units and the notes
if [ -x "$PY" ]; then
  "$PY" - "$TMP" >"$TMP/py" 2>&1 <<'PYEOF'
import json, sys
d = sys.argv[1]
m = json.load(open(d + "/g.csv.meta.json"))
t = m["tables"][0]
units = {c["name"]: c["unit"] for c in t["columns"]}
print("command", m["command"])
print("program", m["program"].split()[0])
print("dpar", units["dpar"], "p", repr(units["p"]), "vc", units["vc_thorax"])
print("rows", t["rows"])
print("note", "grid of case C" in t["notes"][0])
hm = json.load(open(d + "/h.csv.meta.json"))
hu = {c["name"]: c["unit"] for c in hm["tables"][0]["columns"]}
print("history", hu["t"], hu["head_acc_x"], hu["neck_load_my"])
mm = json.load(open(d + "/m.csv.meta.json"))
mu = {c["name"]: c["unit"] for c in mm["tables"][0]["columns"]}
print("montecarlo", mu["wind"], mu["q"], mu["mean"], mu["p95"], repr(mu["sample"]))
dm = json.load(open(d + "/d.csv.meta.json"))
print("diffnote", any("difference P_b - P_a" in n for n in dm["tables"][0]["notes"]))
PYEOF
  check sidecar_command has "$TMP/py" '^command export grid$'
  check sidecar_program has "$TMP/py" '^program uasimpact$'
  check sidecar_units has "$TMP/py" "^dpar m p '' vc m/s$"
  check sidecar_rows cond '[ "$(sed -n "s/^rows //p" "$TMP/py")" -eq "$(($(lines "$TMP/g.csv") - 1))" ]'
  check sidecar_notes has "$TMP/py" '^note True$'
  check sidecar_history_units has "$TMP/py" '^history s m/s^2 N m$'
  check sidecar_montecarlo_units has "$TMP/py" "^montecarlo m/s m^2 m^2 m^2 ''$"
  check sidecar_diff_note has "$TMP/py" '^diffnote True$'
else
  skip sidecar_json "no /usr/bin/python3"
fi

# grid load reads the sidecar: the difference grid loads back as one (p in [-1, 1]), and the
# plain grid with its case; without the sidecar the difference's negative p is refused
run -c "grid load $TMP/d.csv; grid show"
check diff_loads_back cond '[ "$RC" -eq 0 ] && grep -qi "P_b - P_a\|ΔP" "$TMP/out"'
cp "$TMP/d.csv" "$TMP/bare.csv"
if grep -q ',-0\.[0-9]*[1-9]' "$TMP/bare.csv"; then
  run -c "grid load $TMP/bare.csv"
  check diff_without_sidecar_refused cond '[ "$RC" -eq 1 ] && has "$TMP/err" "outside \[0, 1\]"'
fi
run -c "grid load $TMP/g.csv; grid show"
check plain_loads_case has "$TMP/out" '^case C, wind 0 m/s, face 0 deg: Q = '

# an export of the earlier form ('#' note lines before the header) still loads, its notes read
{ echo "# grid of case B, wind 4 m/s, face 0 deg (computed); status: complete"
  cat "$TMP/g.csv"; } >"$TMP/old.csv"
mv "$TMP/g.csv.meta.json" "$TMP/g.meta.away"
run -c "grid load $TMP/old.csv; grid show"
check old_form_loads cond '[ "$RC" -eq 0 ] && grep -q "^case B, wind 4 m/s, face 0 deg: Q = " "$TMP/out"'

mv "$TMP/g.meta.away" "$TMP/g.csv.meta.json"

# set format json: one object per table and line, show included; a JSON parser reads each
run -c "set format json; set bag_model analytic; descent; show; show wind; grid load $TMP/g.csv; grid"
check json_ran [ "$RC" -eq 0 ]
if [ -x "$PY" ]; then
  "$PY" -c '
import json, sys
for line in open(sys.argv[1]):
    o = json.loads(line)
    print(len(o["columns"]), len(o["rows"]), o["columns"][0])
' "$TMP/out" >"$TMP/py" 2>&1
  check json_each_line_parses cond '[ "$(lines "$TMP/py")" -eq 4 ] && ! grep -q Error "$TMP/py"'
  check json_descent has "$TMP/py" '^4 6 case$'
  check json_show has "$TMP/py" '^4 [1-9][0-9][0-9]* name$'
  check json_show_one has "$TMP/py" '^4 1 name$'
fi
# the listings that are tables too: model params, model parts, dist
run -c "set format json; model params bag_p; model parts; dist wind weibull 5 2; dist"
if [ -x "$PY" ]; then
  "$PY" -c '
import json, sys
for line in open(sys.argv[1]):
    o = json.loads(line)
    print(" ".join(o["columns"]), len(o["rows"]))
' "$TMP/out" >"$TMP/py" 2>&1
  check json_listings cond '[ "$(lines "$TMP/py")" -eq 3 ] && has "$TMP/py" "^name value unit set_by [1-9]" &&
    has "$TMP/py" "^part origin [1-9]" && has "$TMP/py" "^input distribution 1$"'
fi
run -c "set format json; set bag_model analytic; descent; show; show wind; grid load $TMP/g.csv; grid"
check json_numbers_are_numbers has "$TMP/out" '"wind":4,"speed":8\.482'
check json_null_for_empty has "$TMP/out" '"source":null'

# show in JSON names where a derived value comes from; in CSV it keeps its aligned lines
run -c "set format json; show along_min; set format csv; show along_min"
check show_json_source has "$TMP/out" '"source":"derived: every cell where contact is possible, padded by one cell"'
check show_csv_lines has "$TMP/out" '^along_min  *[-0-9.]* m  (derived: '
# (a field holding a comma is quoted: tests/app/base/test_table.c)

# pandas.read_csv with default arguments on every export (Debian's python3-pandas)
if [ -x "$PY" ] && "$PY" -c 'import pandas' 2>/dev/null; then
  for k in h c g s m d; do
    "$PY" -c '
import sys, pandas
f = pandas.read_csv(sys.argv[1])
n = sum(1 for _ in open(sys.argv[1])) - 1
h = open(sys.argv[1]).readline().strip().split(",")
assert list(f.columns) == h, (list(f.columns), h)
assert len(f) == n, (len(f), n)
print("ok", len(f), len(f.columns))
' "$TMP/$k.csv" >"$TMP/pd" 2>&1
    check "pandas_reads_$k" has "$TMP/pd" '^ok [1-9]'
  done
  "$PY" -c '
import sys, pandas
g = pandas.read_csv(sys.argv[1])
assert g["p"].dtype.kind == "f" and g["dpar"].dtype.kind == "f"
print("numeric")' "$TMP/g.csv" >"$TMP/pd" 2>&1
  check pandas_numeric_columns has "$TMP/pd" '^numeric$'
else
  skip pandas_read_csv "python3-pandas cannot be imported by /usr/bin/python3"
fi

# at the prompt (tmux, 80 columns): the sora table folds to fit (no row wraps), and an export's
# notes are shown on standard error while the file stays plain
if command -v tmux >/dev/null 2>&1; then
  . tests/lib_tmux.sh
  start t1 80 60
  check tty_prompt wait_for t1 'uasimpact'
  line t1 'set pager off; set step 0.3; set bag_model analytic; sora'
  check tty_sora wait_for t1 'igrc_quant' 20
  grab t1 -J
  check tty_sora_fits awk 'length($0) > 80 { bad = 1 } END { exit bad }' "$TMP/screen"
  check tty_sora_folded cond '[ "$(grep -c "^ *case " "$TMP/screen")" -ge 2 ]'
  line t1 "grid; export grid $TMP/tty.csv"
  check tty_export_notes wait_for t1 '^# grid of case A, wind 0 m/s' 20
  # the notes go to the terminal before the rows are written and the file is put in place: wait
  # for the file (up to 20 s; under load the check raced the rename)
  n=0; while [ ! -s "$TMP/tty.csv" ] && [ "$n" -lt 200 ]; do sleep 0.1; n=$((n + 1)); done
  check tty_export_plain cond '[ -s "$TMP/tty.csv" ] && ! grep -q "^#" "$TMP/tty.csv"'
else
  skip tty_output "tmux is not installed"
fi
finish
