#!/usr/bin/env bash
# Shares that do not make one render, as bad_input.sh checks bad input: a
# share missing from a merge, one of another scene, spp, model or code
# version, and one given twice are each one line naming the share and what
# is wrong, exit status 2, and nothing merged is written. Shares merged in
# any order, run again, give the bytes of the render made at once.
set -uo pipefail
planet="$1"; flight="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
export PLANET_CACHE_DIR="$work/cache"
source "$(dirname "$0")/expect_refusal.sh"
nothing_written() {
  for f in "$@"; do
    [ -e "$f" ] && { echo "FAIL: a refused merge wrote $f"; failed=1; }
  done
  return 0
}
share() {  # share OUT K/N [SPP]
  "$planet" reference --scene earth_noon --width 4 --height 2 --spp "${3:-64}" --quiet \
    --out "$1" --shard "$2" > /dev/null || { echo "FAIL: share $2 of $1"; failed=1; }
}

# The render at once, and its four shares, run out of order and one twice.
"$planet" reference --scene earth_noon --width 4 --height 2 --spp 64 --quiet \
  --out "$work/whole.exr" > /dev/null || { echo "FAIL: the whole render"; failed=1; }
for k in 3 1 0 2 1; do share "$work/a.exr" "$k/4"; done
"$planet" reference --merge "$work/a.shares" --out "$work/merged.exr" > /dev/null ||
  { echo "FAIL: the merge of four shares"; failed=1; }
cmp "$work/whole.exr" "$work/merged.exr" && cmp "$work/whole.png" "$work/merged.png" &&
  echo "ok: four shares, one run twice, merge to the bytes of the render at once" ||
  { echo "FAIL: the merged reference differs from the render at once"; failed=1; }

out=(--out "$work/m/bad.exr")
mkdir -p "$work/b" "$work/twice"
mv "$work/a.shares/share-2-of-4.sums" "$work/b/"
expect "share 2/4 of earth_noon is missing from $work/a.shares (3 of 4 found)" \
  "$planet" reference --merge "$work/a.shares" "${out[@]}"
cp "$work/a.shares/share-1-of-4.sums" "$work/twice/"
expect "share 1/4 is given twice: $work/a.shares/share-1-of-4.sums and $work/twice/share-1-of-4.sums" \
  "$planet" reference --merge "$work/a.shares" "$work/b" "$work/twice" "${out[@]}"
"$planet" reference --scene earth_sunset --width 4 --height 2 --spp 64 --quiet \
  --out "$work/sunset.exr" --shard 2/4 > /dev/null
expect "sunset.shares/share-2-of-4.sums: share 2/4 is of scene earth_sunset, the other shares of earth_noon" \
  "$planet" reference --merge "$work/a.shares" "$work/sunset.shares" "${out[@]}"
share "$work/spp.exr" 2/4 32
expect "spp.shares/share-2-of-4.sums: share 2/4 is of spp 32, the other shares of 64" \
  "$planet" reference --merge "$work/a.shares" "$work/spp.shares" "${out[@]}"
# A share of another model of the same view, or from another tracer: its
# header says so (the sums after it stay as they were).
mkdir -p "$work/model" "$work/version"
LC_ALL=C sed 's/^model [0-9a-f]*$/model 00000000deadbeef/' "$work/b/share-2-of-4.sums" \
  > "$work/model/share-2-of-4.sums"
expect "model/share-2-of-4.sums: share 2/4 is of model 00000000deadbeef, this program's for earth_noon is" \
  "$planet" reference --merge "$work/a.shares" "$work/model" "${out[@]}"
LC_ALL=C sed 's/^tracer [0-9]*$/tracer 1/' "$work/b/share-2-of-4.sums" > "$work/version/share-2-of-4.sums"
expect "version/share-2-of-4.sums: share 2/4 is of tracer version 1, this program's for earth_noon is" \
  "$planet" reference --merge "$work/a.shares" "$work/version" "${out[@]}"
echo "not a share" > "$work/version/share-3-of-4.sums"
expect "version/share-3-of-4.sums: not a share of a reference" \
  "$planet" reference --merge "$work/version" "${out[@]}"
expect "--merge $work/nowhere: no such file or folder" \
  "$planet" reference --merge "$work/nowhere" "${out[@]}"
expect "--shard '4/4': K must be 0 to N-1" \
  "$planet" reference --scene earth_noon --out "$work/m/x.exr" --shard 4/4
expect "--shard 'two': expected K/N" \
  "$planet" reference --scene earth_noon --out "$work/m/x.exr" --shard two
nothing_written "$work/m"

# A capture's shares: one missing, one twice, one of another flight.
sed -e 's/"width": *[0-9]*/"width": 32/' -e 's/"height": *[0-9]*/"height": 16/' "$flight" \
  > "$work/flight.json"
sed 's/"exposure": *[0-9.]*/"exposure": 9.0/' "$work/flight.json" > "$work/other.json"
for k in 0 1; do
  "$planet" capture --flight "$work/flight.json" --out "$work/cap" --shard "$k/3" --quiet ||
    { echo "FAIL: capture share $k/3"; failed=1; }
done
"$planet" capture --flight "$work/other.json" --out "$work/other" --shard 2/3 --quiet ||
  { echo "FAIL: capture share 2/3 of another flight"; failed=1; }
expect "share 2/3 of the capture is missing from $work/cap.shares (2 of 3 found)" \
  "$planet" capture --merge "$work/cap.shares" --out "$work/mc"
expect "share 0/3 is given twice" \
  "$planet" capture --merge "$work/cap.shares" "$work/cap.shares/share-0-of-3" --out "$work/mc"
expect "other.shares/share-2-of-3: share 2/3 is of flight script (hash)" \
  "$planet" capture --merge "$work/cap.shares" "$work/other.shares" --out "$work/mc"
expect "flight.json has 3 frames, too few for 8 shares (give at most 3)" \
  "$planet" capture --flight "$work/flight.json" --out "$work/mc" --shard 5/8
nothing_written "$work/mc"

# A job for a command that is not split, or not as given.
expect "cluster: 'accuracy' is not split into shares" \
  "$planet" cluster slurm --tasks 4 accuracy --scene earth_noon
expect "cluster: reference --shard: the job gives each task its own --shard" \
  "$planet" cluster slurm --tasks 4 reference --scene earth_noon --out x.exr --shard 1/4
expect "'earth_nope' is not a canonical scene" \
  "$planet" cluster kubernetes --tasks 4 reference --scene earth_nope --out x.exr
expect "cluster: --tasks N (the shares) is required" \
  "$planet" cluster slurm reference --scene earth_noon --out x.exr
exit $failed
