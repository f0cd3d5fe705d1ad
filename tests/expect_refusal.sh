# Sourced by the bad-input tests: `expect FRAGMENT COMMAND...` runs the
# command and checks what a user must see of bad input: exit status 2 and
# one line on stderr that holds FRAGMENT. Needs $work (a scratch folder);
# sets failed=1 on a miss.
failed=0
expect() {
  local fragment=$1; shift
  "$@" > "$work/out.txt" 2> "$work/err.txt"
  local rc=$?
  local lines
  lines=$(wc -l < "$work/err.txt")
  if [ "$rc" -ne 2 ] || ! grep -q -- "$fragment" "$work/err.txt" || [ "$lines" -ne 1 ]; then
    echo "FAIL: '$*' gave exit $rc, expected 2 and one line with '$fragment':"; cat "$work/err.txt"
    failed=1
  else
    echo "ok: $(cat "$work/err.txt")"
  fi
}
