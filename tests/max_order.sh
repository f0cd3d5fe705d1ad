#!/usr/bin/env bash
# The ground truth split by orders of scattering: `reference --max-order 1`
# is single scattering alone, cached apart from the full render (its file
# says "order1"), darker than it on average, and carried by its shares;
# `probe sky --max-order` the same in one direction. Out-of-range counts are
# refused in one line with exit 2.
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"
export PLANET_CACHE_DIR="$work/cache"
source "$(dirname "$0")/expect_refusal.sh"  # expect(), failed=0
fail() { echo "FAIL: $*"; failed=1; }
render() {  # render OUT [--max-order N]
  local out="$1"; shift
  "$planet" reference --scene earth_noon --width 8 --height 4 --spp 512 --out "$work/$out.exr" \
    "$@" > "$work/$out.txt" 2>&1 || fail "reference $* failed: $(cat "$work/$out.txt")"
}
render all
render first --max-order 1
grep -q "orders 1 to 1" "$work/first.txt" || fail "no word of the orders: $(cat "$work/first.txt")"
ls "$PLANET_CACHE_DIR"/reference/earth_noon-order1-8x4-512spp-rgb-*.exr > /dev/null 2>&1 ||
  fail "no order1 file in the cache: $(ls "$PLANET_CACHE_DIR/reference")"
ls "$PLANET_CACHE_DIR"/reference/earth_noon-8x4-512spp-rgb-*.exr > /dev/null 2>&1 ||
  fail "the full render is not cached apart"
# The mean of each channel: single scattering below every order.
if command -v oiiotool > /dev/null; then
  avg() { oiiotool --stats "$work/$1.exr" | sed -n 's/.*Stats Avg: \([^ ]*\) \([^ ]*\) \([^ ]*\).*/\1 \2 \3/p'; }
  read -r a1 a2 a3 <<< "$(avg all)"
  read -r f1 f2 f3 <<< "$(avg first)"
  awk -v a="$a1 $a2 $a3" -v f="$f1 $f2 $f3" 'BEGIN {
    split(a, x); split(f, y);
    for (i = 1; i <= 3; ++i) if (!(y[i] > 0 && y[i] < 0.97 * x[i])) exit 1 }' ||
    fail "single scattering ($f1 $f2 $f3) is not below every order ($a1 $a2 $a3)"
fi
# One direction: the first order below all of them.
probe() {  # probe [--max-order N]
  "$planet" probe sky --planet earth --view-zenith 60 --sun-zenith 30 --paths 10000 "$@" 2>/dev/null |
    sed -n 's/^linear sRGB (rgb mode): //p'
}
read -r p1 _ _ <<< "$(probe)"
read -r q1 _ _ <<< "$(probe --max-order 1)"
awk -v p="$p1" -v q="$q1" 'BEGIN { exit !(q > 0 && q < 0.97 * p) }' ||
  fail "probe sky: first order $q1 not below all orders $p1"
# A share of an order-limited render says so, and merges to its bytes.
for k in 0 1; do
  "$planet" reference --scene earth_noon --width 8 --height 4 --spp 512 --max-order 1 --quiet \
    --shard "$k/2" --out "$work/shared.exr" > /dev/null 2>&1 || fail "share $k/2 failed"
done
grep -aq "^orders 1$" "$work/shared.shares/share-0-of-2.sums" || fail "the share names no orders"
"$planet" reference --merge "$work/shared.shares" --out "$work/merged.exr" > /dev/null 2>&1 ||
  fail "the merge of the order-1 shares failed"
cmp -s "$work/merged.exr" "$work/first.exr" || fail "the merged shares differ from the render at once"
# Refused before any work.
expect "is not an order count from 1 to 1000" \
  "$planet" reference --scene earth_noon --spp 64 --out "$work/x.exr" --max-order 1001
expect "is not an order count from 1 to 1000" \
  "$planet" accuracy --technique raymarch --scene earth_noon --max-order -1
[ -e "$work/x.exr" ] && fail "a refused reference wrote its image"
[ "$failed" -eq 0 ] && echo "ok: single scattering cached apart, below every order, and sharded"
exit $failed
