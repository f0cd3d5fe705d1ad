#!/usr/bin/env bash
# The command line as a newcomer reads it, in three parts:
#   help    `--help` is short and says where the techniques are listed;
#           `planet techniques` holds their table; `--version` answers.
#   places  every list of bodies is the one in data/planets; longitudes
#           run -180 to 360 east and are named east and west; a range
#           error writes its bounds as a person would.
#   lists   every list option takes its items with commas, with spaces,
#           or with the option repeated, and a technique's own settings
#           (which hold commas) stay with it.
#   command_line.sh PLANET PART WORK   (PLANET_ROOT: the source tree)
# Nothing here starts GL: each case is help, a probe, or bad input
# refused before any work.
set -uo pipefail
planet="$1"; part="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect_refusal.sh"
fail() { echo "FAIL: $*"; failed=1; }

# Runs the command, which must succeed; its standard output in $work/out.txt.
succeed() {
  if ! "$@" > "$work/out.txt" 2> "$work/err.txt"; then
    fail "'$*' failed:"; cat "$work/err.txt"
  fi
}

case "$part" in
help)
  # The table of techniques, 60 lines, under every command's --help
  # drowned its options.
  for command in "" capture fly soak probe "probe sun" "probe moon" "probe ground" lab accuracy eclipse; do
    # shellcheck disable=SC2086
    succeed "$planet" $command --help
    lines=$(wc -l < "$work/out.txt")
    if grep -q "Atmosphere techniques:" "$work/out.txt"; then
      fail "planet $command --help holds the table of techniques"
    fi
    echo "planet $command --help: $lines lines"
  done
  succeed "$planet" --help
  [ "$(wc -l < "$work/out.txt")" -le 25 ] || fail "planet --help is over 25 lines"
  grep -q "planet techniques" "$work/out.txt" || fail "planet --help does not point at planet techniques"
  succeed "$planet" probe --help
  [ "$(wc -l < "$work/out.txt")" -le 20 ] || fail "planet probe --help is over 20 lines"
  # The eclipse of a day, its figures in a few lines (docs/bodies.md#eclipses).
  succeed "$planet" eclipse 2024-04-08
  grep -q "^eclipse  *solar, total" "$work/out.txt" || fail "planet eclipse 2024-04-08 is not total"
  grep -q "^path width  *197" "$work/out.txt" || fail "planet eclipse 2024-04-08: no 197 km path"
  succeed "$planet" eclipse 2022-11-08
  grep -q "^U2  *10:16" "$work/out.txt" || fail "planet eclipse 2022-11-08: no U2 at 10:16"
  # The Moon's light (docs/eclipses.md#moonlight): the full Moon of
  # 2022-12-08 nearly overhead gives 0.1 to 0.3 lux on level ground; the
  # first quarter of 2022-12-30, as high, about a tenth of it.
  succeed "$planet" probe moon --lat 25 --lon -60 --time 2022-12-08T04:08:00Z
  full=$(sed -n 's/^ *\([0-9.]*\) lux under the air.*/\1/p' "$work/out.txt")
  level=$(sed -n 's/^ *\([0-9.]*\) lux on level ground/\1/p' "$work/out.txt")
  awk -v l="$level" 'BEGIN { exit !(l >= 0.1 && l <= 0.3) }' ||
    fail "the full Moon overhead gives '$level' lux on level ground, not 0.1 to 0.3"
  grep -q "^phase  *2\.[0-9]* deg" "$work/out.txt" || fail "the full Moon's phase is not 2-3 deg"
  succeed "$planet" probe moon --lat 0 --lon -100 --time 2022-12-30T01:21:00Z
  quarter=$(sed -n 's/^ *\([0-9.]*\) lux under the air.*/\1/p' "$work/out.txt")
  awk -v q="$quarter" -v f="$full" 'BEGIN { exit !(f > 0 && q / f > 0.06 && q / f < 0.14) }' ||
    fail "the quarter Moon gives '$quarter' lux against the full Moon's '$full', not about a tenth"
  # Every scene --scene takes is listed, the eclipse scenes too.
  succeed "$planet" reference --list
  for scene in earth_noon earth_eclipse_total earth_eclipse_400km; do
    grep -q "^$scene " "$work/out.txt" || fail "planet reference --list does not list $scene"
  done
  succeed "$planet" techniques
  grep -q "Atmosphere techniques:" "$work/out.txt" || fail "planet techniques has no table"
  for t in hillaire raymarch bruneton oneil; do
    grep -q "$t" "$work/out.txt" || fail "planet techniques does not list $t"
  done
  # Each technique says whether it takes the Moon's shadow (an eclipse's
  # occluded sun) and a second light (the Moon's): every one takes the
  # first, none the second yet.
  for t in raymarch hillaire bruneton oneil hillaire2020; do
    block=$(awk -v t="$t" 'index($0, t " (") == 1 { on = 1; next } /^$/ { on = 0 } on' "$work/out.txt")
    grep -q "^  the Moon's shadow (the occluded sun): yes" <<< "$block" ||
      fail "planet techniques: $t does not say that it takes the Moon's shadow"
    grep -q "^  a second light (the Moon's): no$" <<< "$block" ||
      fail "planet techniques: $t does not say that it draws no second light"
  done
  version=$(sed -n 's/^project(planet VERSION \([0-9.]*\).*/\1/p' "$PLANET_ROOT/CMakeLists.txt")
  succeed "$planet" --version
  [ "$(cat "$work/out.txt")" = "planet $version" ] ||
    fail "planet --version said '$(cat "$work/out.txt")', not 'planet $version'"
  ;;
places)
  # The bodies a user is offered are the files in data/planets, whatever
  # they are: here a root whose planets are the Moon and a made-up one.
  root="$work/root"; mkdir -p "$root/data/planets"
  cp "$PLANET_ROOT/data/planets/moon.json" "$root/data/planets/"
  sed 's/"name": "Moon"/"name": "Selene"/' "$PLANET_ROOT/data/planets/moon.json" \
    > "$root/data/planets/selene.json"
  for command in "probe sun" "probe ground" "probe transmittance" "probe sky" "probe oneil-fit" \
                 fly soak; do
    # shellcheck disable=SC2086
    succeed env PLANET_ROOT="$root" "$planet" $command --help
    grep -q "(moon, selene)" "$work/out.txt" ||
      fail "planet $command --help does not list the bodies of data/planets (moon, selene):
$(grep -i "body\|bodies" "$work/out.txt")"
    grep -q "asteroid" "$work/out.txt" && fail "planet $command --help lists a body not in data/planets"
  done
  expect "vulcan: no such body file, and no body of that name in $root/data/planets (moon, selene)" \
    env PLANET_ROOT="$root" "$planet" probe ground --planet vulcan --lat 0 --lon 0
  # The shipped lists say what each body is where its name does not: the
  # asteroid is a tiny planet, Eros the real one (their files' summaries).
  for command in "" "probe ground"; do
    # shellcheck disable=SC2086
    succeed "$planet" $command --help
    grep -q "asteroid \[a 30 km tiny planet under a dense purple atmosphere, after Hillaire 2020; not a real asteroid (eros is one)\]" "$work/out.txt" ||
      fail "planet $command --help does not say the asteroid is a tiny planet"
    grep -q "eros \[the real asteroid 433 Eros" "$work/out.txt" ||
      fail "planet $command --help does not say eros is the real asteroid"
  done
  # Mars' maps count longitudes 0-360 east: Jezero's 77.5 E, Olympus
  # Mons' 226.2 E (133.8 W).
  succeed "$planet" probe ground --planet mars --lat 18.65 --lon 226.2
  grep -q "lon 226.200000 deg E (133.800000 deg W)" "$work/out.txt" ||
    fail "probe ground does not name 226.2 E as 133.8 W: $(head -1 "$work/out.txt")"
  succeed "$planet" probe sun --planet mars --lat 18.65 --lon 226.2 --time 2026-06-21T12:00:00Z
  grep -q "lon 226.2000 deg E (133.8000 deg W)" "$work/out.txt" ||
    fail "probe sun does not name 226.2 E as 133.8 W: $(grep place "$work/out.txt")"
  succeed "$planet" probe sun --planet moon --lat 0 --lon -70 --time 2026-06-21T12:00:00Z
  grep -q "lon 70.0000 deg W" "$work/out.txt" ||
    fail "probe sun does not name -70 as 70 W: $(grep place "$work/out.txt")"
  expect "--lon: 361 is not a longitude (-180 to 360 deg east" \
    "$planet" probe ground --planet mars --lat 0 --lon 361
  expect "--lat: 95 is not a latitude (-90 to 90 deg)" \
    "$planet" probe ground --planet mars --lat 95 --lon 0
  # Bounds as written, not as std::to_string writes a double.
  expect "--zenith: Value 181 not in range 0 to 180" \
    "$planet" probe transmittance --planet earth --zenith 181
  expect "--height: Value -1 not in range 0 to 1000000000 (" \
    "$planet" probe sky --planet earth --height -1
  expect "--terrain-cache-mib: Value 4 not in range 8 to 65536" "$planet" soak --terrain-cache-mib 4
  expect "--exposure: Value 0 is not above 0" "$planet" fly --exposure 0
  ;;
lists)
  # Each list three ways; the error names the one bad item, which shows
  # that the items before it were taken apart and accepted.
  for form in "raymarch,nope" "raymarch nope" "raymarch --techniques nope"; do
    # shellcheck disable=SC2086
    expect "unknown atmosphere technique 'nope'" \
      "$planet" lab run --techniques $form --no-report --out "$work/lab"
  done
  [ -e "$work/lab" ] && fail "a refused lab run left its folder"
  expect "'nope' is not a canonical scene" \
    "$planet" lab run --techniques raymarch,hillaire --scenes earth_noon,nope --no-report \
    --out "$work/lab"
  expect "lab run --quality: no technique of the sweep has a quality point 'nope'" \
    "$planet" lab run --techniques raymarch,hillaire --quality default,nope --no-report \
    --out "$work/lab"
  expect "lab stability --bodies: 'venus' is not one of earth, mars, asteroid" \
    "$planet" lab stability --bodies earth,venus --list
  expect "unknown atmosphere technique 'nope'" \
    "$planet" lab stability --techniques hillaire,nope --list
  expect "lab governor --budget" \
    "$planet" lab governor --budget 2,-1 --canonical-only --out "$work/governor"
  expect "--budget: 'x' is not a FLOAT" \
    "$planet" lab governor --budget 2,x --canonical-only --out "$work/governor"
  expect "'nope' is not a canonical scene" "$planet" accuracy --scene earth_noon,nope
  expect "unknown atmosphere technique 'nope'" \
    "$planet" lab measured --techniques raymarch,nope --no-report --out "$work/measured"
  expect "vulcan: no such body file" "$planet" soak --bodies earth,vulcan
  expect "vulcan: no such body file" "$planet" soak --bodies earth vulcan
  # A technique's settings hold commas of their own: two techniques here.
  expect "unknown atmosphere technique 'nope'" \
    "$planet" soak --techniques raymarch:view_steps=8,light_steps=4,nope
  expect "raymarch: view_steps=0 is outside 1 to 512" \
    "$planet" soak --techniques hillaire,raymarch:light_steps=4,view_steps=0
  expect "--techniques: names nothing" "$planet" soak --techniques ,
  ;;
*)
  echo "usage: command_line.sh PLANET help|places|lists WORK" >&2; exit 2 ;;
esac
exit $failed
