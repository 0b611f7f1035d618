# test_man.sh: the man pages cover the command table: every command listed by help, and every
# keyword of its usage (plot sweep, export sweep, sweep clear, model load, ...), has an entry in
# man/uasimpact.1, and a usage the page gives whole is help's; the pages format without errors;
# make install installs all three.
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

# a usage of one form (no | outside brackets) that the man page gives whole (the name, then
# arguments in capitals or brackets) is help's too (help said 'show [NAME]' while the page and
# the command take 'show [NAME|PREFIX]')
tr -s ' ' <"$TMP/entries" >"$TMP/entries1"
one_form() { echo "$1" | awk '{ d = 0; for (i = 1; i <= length($0); i++) { ch = substr($0, i, 1)
  if (ch == "[") d++; if (ch == "]") d--; if (ch == "|" && d == 0) exit 1 } }'; }
while read -r cmd args; do
  one_form "$args" || continue
  whole=$(grep -E "^$cmd [A-Z[]" "$TMP/entries1" | head -1)
  [ -n "$whole" ] || continue
  check "help's usage of $cmd is the page's" [ "$whole" = "$cmd $args" ]
done <"$TMP/usages"

# the pages format with no warning at all (groff -ww -z, on its default device and on the
# terminal's: a long unbreakable list warns "cannot adjust line" there)
for p in man/*.[1-8]; do
  if command -v groff >/dev/null 2>&1; then
    { groff -man -ww -z "$p"; groff -man -Tutf8 -ww -z "$p"; } 2>"$TMP/groff" >/dev/null
    check "formats $p" cond '! [ -s "$TMP/groff" ]'
  else
    skip "formats $p" "groff is not installed"
  fi
done

# a font-alternating macro (.BR, .RB, ...) swallows what follows on its line: a sentence after
# its last argument would alternate fonts word by word (".RB ( x ). The curves ..."); quoted
# arguments are removed before looking for an unquoted capitalised word after a full stop
swallow() { sed -n '/^\.\(BR\|RB\|IR\|RI\|BI\|IB\) /{s/"[^"]*"/Q/g;/[.;:] \{1,\}[A-Z][a-z]/p;}' "$@"; }
for p in man/*.[1-8]; do
  check "no swallowed sentence in $p" cond '[ -z "$(swallow "$p")" ]'
done
printf '.TH X 1\n.RB ( "set use_defl 1" ). The curves are here.\n' >"$TMP/bad.1"
check swallow_check_fails cond '[ -n "$(swallow "$TMP/bad.1")" ]'
if command -v groff >/dev/null 2>&1; then
  printf '.TH X 1\n.SH A\n.BR a , b , c , d , e , f , g , h , i , j , k , l , m , n , o , p , q , r , s , t , u , v , w , x , y , z , aa , bb , cc , dd , ee , ff , gg , hh , ii , jj , kk , ll .\n' >"$TMP/long.1"
  groff -man -Tutf8 -ww -z "$TMP/long.1" 2>"$TMP/groff"
  check groff_check_fails cond '[ -s "$TMP/groff" ]'
fi

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
