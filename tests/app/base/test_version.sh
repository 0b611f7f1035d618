# test_version.sh: uasimpact --version and -V (src/app/base/version.c, the Makefile): the version and
# the commit the binary was built from; a git archive carries the commit in its COMMIT file
. tests/lib.sh

run --version
check version_status [ "$RC" -eq 0 ]
check version_line cond '[ "$(lines "$TMP/out")" -eq 1 ] &&
  grep -Eq "^uasimpact [0-9]+\.[0-9]+(\.[0-9]+)? \(commit [^)]+\)$" "$TMP/out"'
cp "$TMP/out" "$TMP/long"
run -V
check version_short cmp -s "$TMP/out" "$TMP/long"
run -h
check usage_names_version has "$TMP/out" "-V, --version"
run --versio
check unknown_option_still cond '[ "$RC" -eq 2 ] && has "$TMP/err" "unknown option .--versio."'

# built in a checkout: git's commit of the work tree, -dirty with uncommitted changes
if command -v git >/dev/null 2>&1 && [ "$(git rev-parse --show-toplevel 2>/dev/null)" = "$(pwd)" ]; then
  H=$(git rev-parse --short=12 HEAD)
  check version_commit grep -Eq "\(commit $H(-dirty)?\)$" "$TMP/long"
  # git archive fills the COMMIT file (export-subst), which a build outside a checkout reads
  git archive HEAD COMMIT .gitattributes | tar -x -C "$TMP"
  check archive_commit cond '[ "$(cat "$TMP/COMMIT")" = "$(git rev-parse --short HEAD)" ]'
  check checkout_commit_unfilled grep -q '^\$Format:%h\$$' COMMIT
else
  skip version_commit "not a git checkout"
fi
finish
