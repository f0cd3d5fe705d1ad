#!/usr/bin/env bash
# Bad input on the command line: one line naming the option and the reason,
# exit status 2, and no window or capture started.
set -uo pipefail
planet="$1"; flights="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect_refusal.sh"
sun=("$planet" probe sun --planet earth --lon 2.35 --time 2026-06-21T12:00:00Z)
expect "--lat: 91" "${sun[@]}" --lat 91
expect "--time: '2026-06-21T25:00:00Z'" "$planet" probe sun --lat 0 --lon 0 --time 2026-06-21T25:00:00Z
expect "--time: 'noon'" "$planet" probe sun --lat 0 --lon 0 --time noon
expect "--lat: 95" "$planet" probe moon --lat 95 --lon 0 --time 2022-12-08T04:08:00Z
expect "--time: 'midnight'" "$planet" probe moon --lat 0 --lon 0 --time midnight
expect "vulcan" "$planet" probe sun --planet vulcan --lat 0 --lon 0 --time 2026-06-21T12:00:00Z
expect "the date: '2024-13-08' has no month 13" "$planet" eclipse 2024-13-08
expect "the date: '2024-04-08T12:00Z' must be a day (YYYY-MM-DD), not a time" \
  "$planet" eclipse 2024-04-08T12:00Z
expect "--lat: 91" "$planet" fly --lat 91
expect "--height: -7e+06 m is below the ground" "$planet" fly --height -7e6
expect "--technique: unknown atmosphere technique 'nope'" "$planet" fly --technique nope
expect "--antialiasing: 3 samples a pixel: give 1 (none), 2, 4, 8 or 16" "$planet" fly --antialiasing 3
expect "hillaire has no quality parameter 'foo' (its parameters: sky_view_steps," \
  "$planet" fly --technique hillaire:foo=1
expect "raymarch: view_steps=0 is outside 1 to 512" "$planet" fly --technique raymarch:view_steps=0
expect "bruneton: orders=0 is outside 1 to 50" "$planet" fly --technique bruneton:orders=0
expect "bruneton: orders=51 is outside 1 to 50" "$planet" accuracy --technique bruneton:orders=51
expect "--technique: bruneton: a scattering table of 8192 x 256 x 128 texels" \
  "$planet" accuracy --scene earth_noon --technique bruneton:nu_size=64,mu_s_size=128,r_size=128
expect "--technique: bruneton: tables of 2048 x 512 x 128 texels need 14336 MiB, more than the 3072 MiB" \
  "$planet" accuracy --scene earth_noon --technique bruneton:r_size=128,mu_size=512,mu_s_size=128,nu_size=16
expect "--technique: bruneton: mu_size=7 must be even" \
  "$planet" accuracy --scene earth_noon --technique bruneton:mu_size=7
expect "raymarch: light_steps=2.5 is not a whole number" "$planet" fly --technique raymarch:light_steps=2.5
expect "hillaire: path=sideways is not one of by_altitude, luts, per_pixel" \
  "$planet" fly --technique hillaire:path=sideways
expect "hillaire: 'per_pixel_steps' is not key=value" "$planet" fly --technique hillaire:per_pixel_steps
expect "oneil: samples=1 is outside 2 to 16" "$planet" fly --technique oneil:samples=1
expect "oneil: samples=17 is outside 2 to 16" "$planet" fly --technique oneil:samples=17
expect "oneil: scale=foo is not one of fitted, chapter" "$planet" fly --technique oneil:scale=foo
sed 's/"technique": "hillaire"/"technique": "hillaire:per_pixel_steps=2"/' "$flights/ascent.json" > "$work/steps.json"
expect "steps.json: technique: hillaire: per_pixel_steps=2 is outside 4 to 256" \
  "$planet" capture --flight "$work/steps.json" --out "$work/s" --quiet
[ -e "$work/s" ] && { echo "FAIL: a capture with a bad technique left its folder"; failed=1; }
# A keyframe under the ground (3111 m there) is refused, unless the script allows it.
sed 's/"height_above_ground_m": 2.0,/"height_m": 500.0,/' "$flights/ascent.json" > "$work/under.json"
expect "under.json: keyframes.0.: the camera is 2610.7 m below the ground (height_m 500.0, the ground 3110.7 m" \
  "$planet" capture --flight "$work/under.json" --out "$work/u" --quiet
sed 's/"technique": "hillaire",/"technique": "hillaire", "allow_below_ground": true,/' "$work/under.json" \
  > "$work/under_allowed.json"
"$planet" capture --flight "$work/under_allowed.json" --out "$work/ua" --frames 0:1 --quiet ||
  { echo "FAIL: allow_below_ground did not allow it"; failed=1; }
expect "vulcan" "$planet" fly --planet vulcan
expect "--time: 'yesterday'" "$planet" fly --time yesterday
expect "never reaches latitude" "$planet" fly --lat 60 --height 400000 --orbit-inclination 30 --time 2026-01-01T00:00:00Z
expect "outside the flight" "$planet" capture --flight "$flights/ascent.json" --out "$work/c" --frames 40:99 --quiet
expect "not a frame number" "$planet" capture --flight "$flights/ascent.json" --out "$work/c" --frames x:3 --quiet
expect "--width: Value 0 not in range 1 to 8192" "$planet" reference --scene earth_noon --width 0 --out "$work/r.exr"
expect "not expected: --bogus" "$planet" reference --bogus
expect "planet needs a command: capture," "$planet"
expect "planet probe needs a command: transmittance, sky, sun, moon, ground" "$planet" probe
expect "'flz' is not a command of planet (capture, " "$planet" flz
expect "'wind' is not a command of planet probe (transmittance" "$planet" probe wind --planet earth
expect "flights: cannot open file: it is a directory" "$planet" capture --flight "$flights" --out "$work/d" --quiet
[ -e "$work/d" ] && { echo "FAIL: a capture of a directory left its folder"; failed=1; }
expect "--out /proc/planet-nowhere/x: cannot create the folder" \
  "$planet" capture --flight "$flights/ascent.json" --out /proc/planet-nowhere/x --quiet
touch "$work/a_file"
expect "--out $work/a_file/x: cannot be a folder: $work/a_file is a file" \
  "$planet" capture --flight "$flights/ascent.json" --out "$work/a_file/x" --quiet
expect "--frames 3:1 is empty or reversed" \
  "$planet" capture --flight "$flights/ascent.json" --out "$work/c" --frames 3:1 --quiet
# Checked before GL starts: no banner line before the error.
sed 's/"technique": "hillaire"/"technique": "bruneton9"/' "$flights/ascent.json" > "$work/unknown.json"
expect "unknown.json: technique: unknown atmosphere technique 'bruneton9'" \
  "$planet" capture --flight "$work/unknown.json" --out "$work/k"
mkdir -p "$work/cache/reference"
echo "not sums" > "$work/cache/reference/earth_noon-4x2-64spp-rgb-0123456789abcdef.sums"
expect "earth_noon-4x2-64spp-rgb-0123456789abcdef.sums: not the sums of a reference render" \
  env PLANET_CACHE_DIR="$work/cache" "$planet" reference --scene earth_noon --width 4 --height 2 \
  --spp 96 --out "$work/r.exr" --quiet
[ -e "$work/r.exr" ] && { echo "FAIL: a reference was written from broken sums"; failed=1; }
# A body's elevation grid: truncated, or another body's (its datum), is one
# line naming the file before any frame.
planets="$(dirname "$flights")/planets"
head -c 2000000 "$(dirname "$flights")/elevation/mars/megt90n000cb.img" > "$work/short.img"
sed "s|data/elevation/mars/megt90n000cb.img|$work/short.img|" "$planets/mars.json" > "$work/mars_short.json"
expect "short.img: 2000000 bytes, but a grid of 1440 x 720 16-bit samples is 2073600 bytes (truncated?)" \
  "$planet" probe ground --planet "$work/mars_short.json" --lat 0 --lon 0
sed 's|"radius_m": 3396000.0|"radius_m": 1737400.0|' "$planets/mars.json" > "$work/mars_moon_datum.json"
expect "mars_moon_datum.json: terrain.height.datum.radius_m: " \
  "$planet" probe ground --planet "$work/mars_moon_datum.json" --lat 0 --lon 0
sed "s|\"body\": \"mars\"|\"body\": \"$work/mars_short.json\"|" "$flights/mars_sunset.json" > "$work/short_flight.json"
expect "short.img: 2000000 bytes" "$planet" capture --flight "$work/short_flight.json" --out "$work/g"
[ -e "$work/g" ] && { echo "FAIL: a capture over a truncated grid left its folder"; failed=1; }
exit $failed
