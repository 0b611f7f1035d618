#!/bin/sh
# replay-pins.sh: the NAME=VALUE settings of src/models/replay.pins (or FILE) on one line, for
# calibrate's command line when a logged fit is replayed or resumed (see that file). Lines that
# are not a plain NAME=NUMBER (after '#' comments are cut) are refused with their line number.
#   sh scripts/replay-pins.sh [FILE]
f=${1:-src/models/replay.pins}
[ -r "$f" ] || { echo "replay-pins.sh: $f: cannot read" >&2; exit 1; }
awk '{ sub(/#.*/, ""); gsub(/^[ \t]+|[ \t]+$/, "") }
  $0 == "" { next }
  $0 !~ /^[A-Za-z_][A-Za-z0-9_]*=[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ {
    printf "replay-pins.sh: %s:%d: expected NAME=NUMBER, got \"%s\"\n", FILENAME, NR, $0 > "/dev/stderr"
    bad = 1; exit 1 }
  { out = out (n++ ? " " : "") $0 }
  END { if (!bad && n) print out }' "$f"
