# test_man.sh: the man pages cover the command table: every command listed by help, and every
# keyword of its usage (plot sweep, export sweep, sweep clear, model load, ...), has an entry in
# man/uasimpact.1; the pages format without errors; make install installs all three.
. tests/lib.sh

run -c help
check help_status [ "$RC" -eq 0 ]
# usage lines: "  NAME ARGS..." (a long usage stands alone on its line)
sed -n 's/^  \([a-z].*\)$/\1/p' "$TMP/out" | sed 's/  .*//' >"$TMP/usages"
check usages_read [ "$(lines "$TMP/usages")" -ge 20 ]

# the entries of the COMMANDS section, font escapes and quotes removed
sed -n '/^\.SH COMMANDS/,/^\.SH /p' man/uasimpact.1 | grep '^\.B' |
  sed 's/\\f[BIRP]//g; s/\\ / /g; s/"//g; s/^\.B[IR]* //' >"$TMP/entries"

# the keywords at the first place of a usage: lowercase words at bracket depth 0 that begin it
# or follow '|' (a usage that is one bracketed group is opened first)
keywords() { echo "$1" | awk '{
  t = $0; if (t ~ /^\[.*\]$/ && index(substr(t, 2), "[") == 0) t = substr(t, 2, length(t) - 2)
  d = 0; w = ""; start = 1
  for (i = 1; i <= length(t) + 1; i++) {
    ch = substr(t, i, 1)
    if (ch ~ /[a-z_0-9]/ && (start || w != "")) { w = w ch; start = 0; continue }
    if (w != "" && d == 0) print w
    w = ""; start = 0
    if (ch == "[") d++; if (ch == "]") d--
    if (ch == "|" && d == 0) start = 1
  }}'; }

while read -r cmd args; do
  check "man documents $cmd" grep -q "^$cmd\( \|\$\)" "$TMP/entries"
  for kw in $(keywords "$args"); do
    check "man documents $cmd $kw" grep -Eq "^$cmd( [^ ]*)*( |\||\[)$kw( |\||\]|\$)" "$TMP/entries"
  done
done <"$TMP/usages"

# the pages format (groff's warnings other than line adjustment are errors)
for p in man/uasimpact.1 man/uasimpact-model.5 man/uasimpact-injury.7; do
  if command -v groff >/dev/null 2>&1; then
    groff -man -Tutf8 -ww "$p" 2>"$TMP/groff" >/dev/null
    check "formats $p" cond '! grep -v "cannot adjust line" "$TMP/groff" | grep -q .'
  fi
done

# make install puts the binary and the three pages in place
if command -v make >/dev/null 2>&1; then
  make -s install DESTDIR="$TMP/root" PREFIX=/usr >"$TMP/make" 2>&1
  check install_status [ $? -eq 0 ]
  check install_pages cond '[ -x "$TMP/root/usr/bin/uasimpact" ] &&
    [ -s "$TMP/root/usr/share/man/man1/uasimpact.1" ] &&
    [ -s "$TMP/root/usr/share/man/man5/uasimpact-model.5" ] &&
    [ -s "$TMP/root/usr/share/man/man7/uasimpact-injury.7" ]'
fi
finish
