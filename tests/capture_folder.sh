#!/usr/bin/env bash
# What capture.json says of a folder that more than one run filled: after a
# resume (--frames N: after an interrupted run) it describes every frame
# there and the time of all the runs, not the last run's slice; a slice
# alone stays a slice. A merge of shares (and a run at once) into a folder
# that an earlier, longer capture used removes that capture's frames
# beyond the flight's end, and says so.
set -uo pipefail
planet="$1"; flight="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
summary() {  # FOLDER: "first:end" and whether its time is the sum of those frames' times
  /usr/bin/python3 - "$1" <<'PY'
import json, sys
d = json.load(open(sys.argv[1] + "/capture.json"))
first, end = d["frames"]["first"], d["frames"]["end"]
times = [json.load(open("%s/frame_%05d.json" % (sys.argv[1], f))).get("wall_seconds") for f in range(first, end)]
same = None not in times and abs(sum(times) - d["wall_seconds"]) < 1e-6
print("%d:%d %s" % (first, end, same if None not in times else "(no frame times)"))
PY
}
# The tiny ascent at 16x8: 3 frames; and a longer one (5 frames) to leave
# its frames in a folder.
sed -e 's/"width": *64/"width": 16/' -e 's/"height": *32/"height": 8/' "$flight" > "$work/flight.json"
sed 's/"frame_rate": *[0-9.]*/"frame_rate": 0.2/' "$work/flight.json" > "$work/longer.json"
cap() { "$planet" capture --quiet "$@" || fail "capture $*"; }

# A capture stopped after frame 0, resumed with --frames 1:.
cap --flight "$work/flight.json" --out "$work/resumed" --frames 0:1
cap --flight "$work/flight.json" --out "$work/resumed" --frames 1:
[ "$(summary "$work/resumed")" = "0:3 True" ] ||
  fail "after the resume capture.json says $(summary "$work/resumed"), not frames 0:3 and the sum of their times"
# The same slice into a folder of its own is a slice.
cap --flight "$work/flight.json" --out "$work/slice" --frames 1:
[ "$(summary "$work/slice")" = "1:3 True" ] || fail "a slice alone says $(summary "$work/slice")"
# Frames of another capture (another size) are not counted as this one's.
cap --flight "$work/flight.json" --out "$work/other" --frames 0:1 --scale 2
cap --flight "$work/flight.json" --out "$work/other" --frames 1:
[ "$(summary "$work/other")" = "1:3 True" ] ||
  fail "a frame of another size counted: $(summary "$work/other")"
echo "ok: capture.json after a resume: $(summary "$work/resumed")"

# Shares merged into the folder of the longer capture.
cap --flight "$work/longer.json" --out "$work/longer"
cp -r "$work/longer" "$work/merged"
cap --flight "$work/flight.json" --out "$work/merged" --shard 0/2
cap --flight "$work/flight.json" --out "$work/merged" --shard 1/2
"$planet" capture --merge "$work/merged.shares" --out "$work/merged" > "$work/merge.txt" ||
  fail "the merge"
ls "$work/merged" | grep -q "frame_0000[34]" && fail "the merge left the longer capture's frames 3 and 4"
grep -q "removed 2 frames beyond the flight's end from $work/merged (frames 3 to 4" "$work/merge.txt" ||
  fail "the merge does not say what it removed: $(cat "$work/merge.txt")"
[ "$(summary "$work/merged")" = "0:3 True" ] || fail "merged capture.json: $(summary "$work/merged")"
# A run does the same.
cp -r "$work/longer" "$work/again"
"$planet" capture --flight "$work/flight.json" --out "$work/again" --frames 0:1 > "$work/again.txt" 2>&1 ||
  fail "the run into the longer capture's folder"
ls "$work/again" | grep -q "frame_0000[34]" && fail "a run left the longer capture's frames 3 and 4"
grep -q "removed 2 frames beyond" "$work/again.txt" || fail "no word of the frames removed"
echo "ok: $(cat "$work/merge.txt")"
exit $failed
