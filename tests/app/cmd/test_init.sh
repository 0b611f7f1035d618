# test_init.sh: the start-up file (src/app/cmd/init.c, main.c): $XDG_CONFIG_HOME/uasimpact/init,
# else ~/.config/uasimpact/init, is read before an interactive session (-i, or a terminal), never
# for a script run alone, and not with -n; it may only set things: a command that computes, plots
# or writes a file is refused with the file and line, nothing is written, and the session goes on
# with what the lines before it set (a sourced file is held to the same rule).
. tests/lib.sh

CFG=$TMP/cfg
mkdir -p "$CFG/uasimpact" "$TMP/home/.config/uasimpact"
printf 'show wind; show case; show pitch\n' >"$TMP/in"
prompt() { env XDG_CONFIG_HOME="$CFG" HOME="$TMP/home" "$UASIMPACT" "$@" <"$TMP/in" >"$TMP/out" 2>"$TMP/err"; RC=$?; }

printf '# my defaults\nset wind 3\ncase B\nset pitch 5 # degrees\n' >"$CFG/uasimpact/init"
prompt -i
check read_at_prompt cond '[ "$RC" -eq 0 ] && grep -q "^wind  *3 m/s" "$TMP/out" &&
  grep -q "^case  *B" "$TMP/out" && grep -q "^pitch  *5 deg" "$TMP/out" && ! [ -s "$TMP/err" ]'
prompt -i -n
check n_skips cond 'grep -q "^wind  *0 m/s" "$TMP/out" && grep -q "^case  *A" "$TMP/out"'
env XDG_CONFIG_HOME="$CFG" "$UASIMPACT" -c 'show wind' >"$TMP/out" 2>&1
check script_never cond 'grep -q "^wind  *0 m/s" "$TMP/out"'
printf 'show wind\n' >"$TMP/s.ses"
env XDG_CONFIG_HOME="$CFG" "$UASIMPACT" "$TMP/s.ses" >"$TMP/out" 2>&1
check file_never cond 'grep -q "^wind  *0 m/s" "$TMP/out"'
# the start-up state is where undo stops
printf 'undo\n' >"$TMP/in"
prompt -i
check undo_stops cond 'grep -q "undo: nothing to undo" "$TMP/err"'

# without XDG_CONFIG_HOME (or with a relative one), ~/.config/uasimpact/init
printf 'show wind\n' >"$TMP/in"
printf 'set wind 7\n' >"$TMP/home/.config/uasimpact/init"
env -u XDG_CONFIG_HOME HOME="$TMP/home" "$UASIMPACT" -i <"$TMP/in" >"$TMP/out" 2>&1
check home_default grep -q "^wind  *7 m/s" "$TMP/out"
env XDG_CONFIG_HOME=cfg HOME="$TMP/home" "$UASIMPACT" -i <"$TMP/in" >"$TMP/out" 2>&1
check relative_xdg_ignored grep -q "^wind  *7 m/s" "$TMP/out"

# only setting: each writer, computation and plot is refused at its line, nothing is written,
# the lines before it hold and the session goes on
for cmd in "save session $TMP/w.ses" "export grid $TMP/w.csv" "report $TMP/w.html" \
  "model save $TMP/w.urm" "grid" "plot pof" "sweep wind 0" "design save x" "quit"; do
  printf 'set wind 2\n%s\nset wind 4\n' "$cmd" >"$CFG/uasimpact/init"
  prompt -i
  w=${cmd%% *}
  [ "$w" = model ] && w="model save"
  check "refuses $cmd" cond 'grep -q "init:2: .$w. is not accepted in a start-up file; accepted: set, case" "$TMP/err" &&
    [ "$(lines "$TMP/err")" -eq 1 ] && grep -q "^wind  *2 m/s" "$TMP/out" && ! ls "$TMP"/w.* >/dev/null 2>&1'
done
printf 'set output %s/w.png\nplot pof\n' "$TMP" >"$TMP/inner.ses"
printf 'source %s\n' "$TMP/inner.ses" >"$CFG/uasimpact/init"
prompt -i
check source_guarded cond 'grep -q "inner.ses:2: .plot. is not accepted" "$TMP/err" && ! [ -e "$TMP/w.png" ]'

# a bad line: one message with the file and line, the session runs
printf 'set wind 99\n' >"$CFG/uasimpact/init"
printf 'show wind\n' >"$TMP/in"
prompt -i
check bad_line cond '[ "$RC" -eq 0 ] && grep -q "init:1: set wind: 99 is out of range" "$TMP/err" &&
  grep -q "(the start-up file stopped there; -n skips it)" "$TMP/err" && grep -q "^wind  *0 m/s" "$TMP/out"'
finish
