# lib_tmux.sh: drive uasimpact in tmux as a person would (after tests/lib.sh). A private tmux
# server, killed at exit; sessions started with 'start NAME W H [ENV=VALUE...] [-- ARGS...]'.
#   grab S [-e]        the screen (with -e: with escapes) into $TMP/screen
#   wait_for S RE [N]  wait up to N seconds (5) until the screen matches RE (grep -E)
#   wait_gone S RE     wait until RE is no longer on the screen
#   keys S KEY...      tmux key names (Enter, Tab, Up, C-d, ...)
#   line S TEXT        type TEXT literally, then Enter
#   coloured S         the screen holds SGR colour escapes
#   alive S            the program in S still runs
U=$(cd "$(dirname "$UASIMPACT")" && pwd)/$(basename "$UASIMPACT")
SOCK="uasimpact-test-$$"
TM() { tmux -L "$SOCK" -f /dev/null "$@"; }
trap 'tmux -L "$SOCK" kill-server 2>/dev/null; rm -rf "$TMP"' EXIT
ESC=$(printf '\033')
COLOUR="$ESC\[([0-9;]*;)?(3[0-7]|4[0-7]|38;5;[0-9]+|48;5;[0-9]+|9[0-7]|10[0-7])(;[0-9;]*)?m"

start() { name=$1; w=$2; h=$3; shift 3
  envs=""; args=""
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do envs="$envs $1"; shift; done
  [ "$1" = "--" ] && shift
  args="$*"
  TM new-session -d -s "$name" -x "$w" -y "$h" -c "$PWD" \
    "env -u NO_COLOR -u DISPLAY -u WAYLAND_DISPLAY HOME=$TMP $envs $U $args"
  TM set -t "$name" remain-on-exit on
}
grab() { TM capture-pane -p $2 -t "$1" >"$TMP/screen"; }
wait_for() { n=0; lim=$(( ${3:-5} * 10 ))
  while [ "$n" -lt "$lim" ]; do
    grab "$1"; grep -Eq -- "$2" "$TMP/screen" && return 0
    sleep 0.1; n=$((n + 1))
  done
  echo "  (waited for '$2'; the screen was:)"; sed 's/^/  | /' "$TMP/screen"; return 1
}
wait_gone() { n=0
  while [ "$n" -lt 50 ]; do
    grab "$1"; grep -Eq -- "$2" "$TMP/screen" || return 0
    sleep 0.1; n=$((n + 1))
  done
  return 1
}
keys() { s=$1; shift; TM send-keys -t "$s" "$@"; }
line() { s=$1; shift; TM send-keys -t "$s" -l "$*"; TM send-keys -t "$s" Enter; }
coloured() { grab "$1" -e; grep -Eq "$COLOUR" "$TMP/screen"; }
alive() { [ "$(TM display -p -t "$1" "#{pane_dead}")" = 0 ]; }
