# Sourced by the window tests: a virtual display of their own for `planet
# fly`, with xdotool to type into it. Exits 77 (skipped) where Xvfb or
# xdotool is missing; sets DISPLAY and $xvfb (the server's pid, for the
# caller's trap to end).
for tool in Xvfb xdotool; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIPPED: $tool is not installed (scripts/install-deps.sh installs it)"
    exit 77
  fi
done
# Xvfb picks a free display number itself (-displayfd: it writes the
# number once it takes connections). A number drawn at random could be one
# another window test's server holds: this test then talked to that
# server, and lost its display when that test ended ("GLFW: cannot
# initialise"). Up to 30 s for the server to answer (with the long tier's
# other tests alongside it took past 5 s).
display_file="$(mktemp)"  # the number Xvfb writes
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$display_file" >/dev/null 2>&1 &
xvfb=$!
answered=0
for _ in $(seq 1 300); do
  if [ -s "$display_file" ]; then
    export DISPLAY=":$(head -1 "$display_file")"
    xdotool getmouselocation >/dev/null 2>&1 && { answered=1; break; }
  fi
  kill -0 "$xvfb" 2>/dev/null || break
  sleep 0.1
done
rm -f "$display_file"
[ "$answered" = 1 ] || { echo "FAIL: no virtual display answered (Xvfb -displayfd, 30 s)"; exit 1; }

# await_fly_window OUT ERR: waits for `planet fly`'s window (up to 60 s),
# then for its first "body: " line in OUT (the window is mapped and drawn
# by then) and focuses it; sets $window. ERR is shown if none appears.
await_fly_window() {
  window=""
  for _ in $(seq 1 300); do
    window=$(xdotool search --name "planet fly" 2>/dev/null | head -1)
    [ -n "$window" ] && break
    sleep 0.2
  done
  [ -n "$window" ] || { echo "FAIL: no window appeared"; cat "$2"; exit 1; }
  for _ in $(seq 1 300); do
    grep -q "^body: " "$1" && xdotool windowfocus "$window" 2>/dev/null && break
    sleep 0.2
  done
  sleep 0.5
}
# GLFW samples key state once a frame: hold_key KEY holds it across a few.
hold_key() { xdotool keydown "$1"; sleep 0.5; xdotool keyup "$1"; }
