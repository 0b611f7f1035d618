#!/bin/sh
# layers.sh [ROOT]: check that every #include "..." in the sources under ROOT (default .) keeps
# the declared order of folders (src/README, section 1): a file may include headers of its own
# folder, of a folder lower in the order, and the public headers (include/uasimpact/); nothing
# that climbs, nothing from a sibling folder of the same rank, no core file anything of the
# application, no application file a core internal header. One line per include that breaks
# the order ("FILE: includes HEADER: RANK-A may not include RANK-B"), exit status 1 if any.
#
# The order, lowest first (a folder's rank; one name per room):
#   core:  contact injury risk membrane = 1  <  engine (and engine/kernels) = 2
#          <  modellang impact = 3
#   app:   base 1  <  case 2  <  cmd (and cmd/risk) 3  <  ui 4  <  report 5  <  scale 6
#          <  main.c 7
# The generated build/version.h (base/version.c) is the one header outside the tree.
root=${1:-.}
cd "$root" || exit 2

# every file of the tree, then each source's includes as "FILE<TAB>HEADER", read by one awk
{
  find src include -type f | sed 's/^/F\t/'
  find src \( -name '*.c' -o -name '*.h' \) -type f | LC_ALL=C sort | while read -r f; do
    sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$f" | sed "s|^|I\t$f\t|"
  done
} | awk -F'\t' '
# "DOMAIN RANK ROOM" of a path relative to the root; "public 0 public" for the public headers,
# "none 0 none" for what is not a source of either library
function where(p) {
  if (p ~ /^include\/uasimpact\//) return "public 0 public"
  if (p ~ /^src\/core\/contact\//) return "core 1 contact"
  if (p ~ /^src\/core\/injury\//) return "core 1 injury"
  if (p ~ /^src\/core\/risk\//) return "core 1 risk"
  if (p ~ /^src\/core\/membrane\//) return "core 1 membrane"
  if (p ~ /^src\/core\/engine\//) return "core 2 engine"
  if (p ~ /^src\/core\/modellang\//) return "core 3 modellang"
  if (p ~ /^src\/core\/impact\//) return "core 3 impact"
  if (p ~ /^src\/core\//) return "core 9 unknown"
  if (p ~ /^src\/app\/base\//) return "app 1 base"
  if (p ~ /^src\/app\/case\//) return "app 2 case"
  if (p ~ /^src\/app\/cmd\//) return "app 3 cmd"
  if (p ~ /^src\/app\/ui\//) return "app 4 ui"
  if (p ~ /^src\/app\/report\//) return "app 5 report"
  if (p ~ /^src\/app\/scale\//) return "app 6 scale"
  if (p == "src/app/main.c") return "app 7 main"
  if (p ~ /^src\/app\//) return "app 9 unknown"
  return "none 0 none"
}
# a path with ./ and dir/../ taken out
function norm(path,   a, n, i, k, q, s) {
  n = split(path, a, "/"); k = 0
  for (i = 1; i <= n; i++) {
    if (a[i] == "." || a[i] == "") continue
    if (a[i] == ".." && k > 0 && q[k] != "..") { k--; continue }
    q[++k] = a[i]
  }
  s = q[1]; for (i = 2; i <= k; i++) s = s "/" q[i]
  return s
}
$1 == "F" { have[$2] = 1; next }
$1 == "I" {
  f = $2; inc = $3
  split(where(f), fw, " ")
  if (fw[1] == "none") next
  dir = f; sub(/\/[^\/]*$/, "", dir)
  t = norm(dir "/" inc)
  if (!(t in have)) t = norm("include/" inc)
  if (!(t in have)) {
    if (f == "src/app/base/version.c" && inc == "version.h") next
    print f ": includes " inc ": no such header in the tree"; bad = 1; next
  }
  split(where(t), tw, " ")
  if (tw[1] == "public") next
  if (tw[1] != fw[1]) {
    print f ": includes " inc ": " fw[1] " (" fw[3] ") may not include " tw[1] " (" tw[3] ") headers"
    bad = 1
  } else if (tw[3] != fw[3] && tw[2] + 0 >= fw[2] + 0) {
    print f ": includes " inc ": " fw[3] " (rank " fw[2] ") may not include " tw[3] " (rank " tw[2] ")"
    bad = 1
  } else if (tw[3] == "unknown" || fw[3] == "unknown") {
    print f ": includes " inc ": a folder the order does not name"; bad = 1
  }
}
END { exit bad }
'
