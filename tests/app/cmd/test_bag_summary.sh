#!/bin/sh
# test_bag_summary.sh: the bag lines of the viewer's cell inspection (src/app/cmd/bag_summary.c)
# for a bag that never touched the person, in tmux: the RA3 in case A with the front bag fitted
# beside the bottom one (analytic bags, a coarse 0.3 m grid: seconds), Enter at the centre cell.
# The front bag keeps its volume: the panel says "volume 0.0 L (0.0 %)", never "-0.0", and it
# says nothing about bottoming for that bag (bottoming is the drone reaching the person through
# the bag: a bag without contact cannot be bottomed); the bottom bag, which the head meets, keeps
# its bottoming line and its volume lost.
. tests/lib.sh

if ! command -v tmux >/dev/null 2>&1; then
  skip bag_summary_checks "tmux is not installed"
  finish
fi
. tests/lib_tmux.sh

start s1 160 60
check prompt wait_for s1 'uasimpact\[A\]>'
line s1 "case A; set bag_model analytic; set bag_front 1; set step 0.3; grid; view"
check keys_help wait_for s1 'Enter inspect  p plot  b bag  q back' 60
check centre wait_for s1 'dpar 0.00 m  dperp 0.00 m'
keys s1 Enter
check panel_front wait_for s1 'bag_front \(analytic\): peak' 60
check panel_bottom wait_for s1 'bag_bottom \(analytic\): peak' 5
check panel_trace wait_for s1 'head acceleration vs time'
# the front bag's lines: from its name to the next bag or the trace
awk '/bag_front \(analytic\)/ { f = 1; print; next } f && /\((analytic|membrane)\)|head acceleration/ { f = 0 }
  f' "$TMP/screen" >"$TMP/front"
awk '/bag_bottom \(analytic\)/ { f = 1; print; next } f && /\((analytic|membrane)\)|head acceleration/ { f = 0 }
  f' "$TMP/screen" >"$TMP/bottom"
sed 's/^/  front| /' "$TMP/front"
check no_negative_zero cond '! grep -q -- "-0\.0 " "$TMP/screen"'
check front_volume grep -Eq 'volume 0\.0 L \(0\.0 %\)' "$TMP/front"
check front_no_bottoming cond '! grep -q "bottomed" "$TMP/front" && grep -q "no contact with the person" "$TMP/front"'
check bottom_bottoming grep -Eq '(not )?bottomed: ' "$TMP/bottom"
check bottom_volume grep -Eq 'volume -[0-9.]+ L \(-[0-9.]+ %\)' "$TMP/bottom"
keys s1 Escape
keys s1 q
check alive_at_end alive s1
finish
