# test_format.sh: every C source (scripts/format-files.sh) is in the house style: clang-format
# (.clang-format) would leave it unchanged; 'make format' applies it. Sources listed in
# .clang-format-pending (the transitional list of those not yet formatted, which 'make format'
# deletes) are left out. A misformatted copy of a source is put through the same check first, so
# that the check is seen to fail.
. tests/lib.sh

CF=${CLANG_FORMAT:-clang-format}
if ! command -v "$CF" >/dev/null 2>&1; then
  skip format "$CF is not installed"
  finish
fi

# 0 if FILE is as clang-format would write it (the style of the .clang-format next to it)
clean() { "$CF" --style=file "$1" | cmp -s - "$1"; }

check style_file [ -s .clang-format ]
cp .clang-format "$TMP/.clang-format"
printf 'int f(int a){\nif(a)return a+1;\n  return 0;}\n' >"$TMP/bad.c"
check self_detects_misformat cond '! clean "$TMP/bad.c"'
"$CF" --style=file -i "$TMP/bad.c"
check self_accepts_formatted clean "$TMP/bad.c"

pending=""
if [ -f .clang-format-pending ]; then pending=$(grep -v '^#' .clang-format-pending); fi
for f in $pending; do
  check "pending_exists_$f" [ -f "$f" ]
done
n=0
for f in $(sh scripts/format-files.sh); do
  case "$NL$pending$NL" in *"$NL$f$NL"*) continue ;; esac
  n=$((n + 1))
  check "formatted_$f" clean "$f"
done
check some_files_checked [ "$n" -ge 1 ]
finish
