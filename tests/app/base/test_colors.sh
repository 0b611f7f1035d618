# test_colors.sh: which terminals get colour (src/app/base/colors.c, ura_scheme_for_stream), as
# a person sees grid show in tmux. A terminal type terminfo knows without colours (vt100, vt220)
# gets plain text, as uasimpact(1), COLOURS, says ("without colours ... grid show prints plain
# text"): it was sent ANSI colour codes, since only TERM=dumb and NO_COLOR were asked. xterm, a
# type terminfo does not know, and COLORTERM keep their colours; NO_COLOR stays plain. After a
# plain grid show the viewer and the line editor work as before (terminfo's current terminal is
# given back).
. tests/lib.sh

T6=sessions/paper/grids/table06_caseC_wind0.csv
if ! command -v tmux >/dev/null 2>&1; then
  skip colour_terminal_checks "tmux is not installed"
  finish
fi
check paper_grid_present [ -r "$T6" ]
. tests/lib_tmux.sh

# grid show on terminal type $2 (and more env): coloured or not
show_on() { s=$1; shift
  start "$s" 100 40 "$@" -- "-c 'grid load $T6' -i"
  wait_for "$s" 'uasimpact\[A\]>' 10 >/dev/null || return 1
  line "$s" 'grid show'
  wait_for "$s" 'Q = 0.8469 m\^2' 10 >/dev/null
}
for t in vt100 vt220; do
  show_on "p_$t" "TERM=$t"
  check "${t}_plain" cond '! coloured "p_$t" && grep -q "legend:" "$TMP/screen"'
done
show_on c_xterm TERM=xterm
check xterm_coloured coloured c_xterm
show_on c_unknown TERM=no-such-terminal-type
check unknown_type_coloured coloured c_unknown
show_on c_colorterm TERM=vt100 COLORTERM=truecolor
check colorterm_coloured coloured c_colorterm
show_on p_nocolor TERM=xterm NO_COLOR=1
check no_color_plain cond '! coloured p_nocolor'

# after the plain grid show on vt100: the viewer opens (glyphs, no colour), q returns, and the
# line editor recalls the last command
line p_vt100 'view'
check vt100_view wait_for p_vt100 'P\{F\|Delta\}:.*@ >=90 %' 10
keys p_vt100 q
check vt100_back wait_for p_vt100 '^uasimpact\[A\]>' 10
keys p_vt100 Up
check vt100_history wait_for p_vt100 'uasimpact\[A\]> view' 10
finish
