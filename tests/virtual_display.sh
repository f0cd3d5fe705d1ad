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
display=":$(( 90 + RANDOM % 400 ))"
Xvfb "$display" -screen 0 800x600x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
export DISPLAY="$display"
# Until the server answers.
for _ in $(seq 1 50); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.1; done
