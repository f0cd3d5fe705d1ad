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
# Until the server answers: up to 30 s (with the long tier's other tests
# alongside it took past the 5 s this once waited, and the window then
# found no display), on another number if the server ends (its number in
# use by another test's server).
answered=0
for _ in 1 2 3; do
  display=":$(( 90 + RANDOM % 400 ))"
  Xvfb "$display" -screen 0 800x600x24 -nolisten tcp >/dev/null 2>&1 &
  xvfb=$!
  export DISPLAY="$display"
  for _ in $(seq 1 300); do
    xdotool getmouselocation >/dev/null 2>&1 && { answered=1; break; }
    kill -0 "$xvfb" 2>/dev/null || break
    sleep 0.1
  done
  [ "$answered" = 1 ] && break
  kill "$xvfb" 2>/dev/null
done
[ "$answered" = 1 ] || { echo "FAIL: no virtual display answered (Xvfb on three numbers, 30 s each)"; exit 1; }

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
