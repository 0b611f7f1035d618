# test_headers.sh: every public header (include/uasimpact/*.h) is portable C11 on its own: it
# compiles alone with -std=c11 -pedantic-errors under gcc and clang (each that is installed), and
# uses no compiler extension (no __attribute__, __extension__, typeof, asm, statement
# expressions), which -pedantic-errors lets through for the GNU ones. A known-bad header is put
# through the same checks first, so that the checks are seen to fail.
. tests/lib.sh

# compile one header alone; 0 if it is clean
alone() { # CC HEADER_DIR NAME
  printf '#include "uasimpact/%s"\nint main(void) { return 0; }\n' "$3" |
    "$1" -std=c11 -pedantic-errors -Wall -Wextra -Werror -I"$2" -fsyntax-only -x c - \
    >"$TMP/cc.log" 2>&1 &&
  printf '#include "uasimpact/%s"\n' "$3" |
    "$1" -std=c11 -pedantic-errors -Werror -I"$2" -fsyntax-only -x c - >>"$TMP/cc.log" 2>&1
}
# extensions outside comments; 0 if there are none
plain() { # FILE
  ! sed 's|/\*.*\*/||g; s|//.*||' "$1" |
    grep -Eq '__attribute__|__extension__|\btypeof\b|__typeof__|\basm\b|__asm__|\(\{'
}

mkdir -p "$TMP/bad/uasimpact"
printf '#ifndef BAD_H\n#define BAD_H\ntypedef struct __attribute__((aligned(64))) { double x; } bad;\n#endif\n' \
  >"$TMP/bad/uasimpact/bad.h"
printf '#ifndef BAD2_H\n#define BAD2_H\nstruct s { int x; }\n#endif\n' >"$TMP/bad/uasimpact/bad2.h"
check self_extension_found cond '! plain "$TMP/bad/uasimpact/bad.h"'
ncc=0
for cc in gcc clang; do
  if ! command -v "$cc" >/dev/null 2>&1; then skip "headers_$cc" "$cc is not installed"; continue; fi
  ncc=$((ncc + 1))
  check "self_${cc}_fails" cond '! alone "$cc" "$TMP/bad" bad2.h'
  for h in include/uasimpact/*.h; do
    n=$(basename "$h")
    check "${cc}_alone_$n" alone "$cc" include "$n"
  done
done
check compilers_found [ "$ncc" -ge 1 ]
for h in include/uasimpact/*.h; do
  check "no_extension_$(basename "$h")" plain "$h"
done
finish
