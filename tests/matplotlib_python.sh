# Sourced by the tests that chart: sets $python to the python that sees
# Debian's matplotlib (one of one's own on the PATH may not), or skips the
# test (exit 77) when none does.
python=""
for p in python3 /usr/bin/python3; do
  "$p" -c 'import matplotlib' 2> /dev/null && { python="$p"; break; }
done
[ -n "$python" ] ||
  { echo "SKIPPED: python3-matplotlib is not installed (scripts/install-deps.sh installs it)"; exit 77; }
