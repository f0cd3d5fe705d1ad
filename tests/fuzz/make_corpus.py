#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpus into tests/fuzz/corpus/<target>/.

The seeds are the shipped files each parser reads, a recorded flight, and
the bad input the tests try by hand, applied to each shipped file
(truncated, a trailing comma, empty, binary garbage, a PNG, an unknown key,
NaN, out-of-range numbers, deep nesting), plus every command line of
tests/bad_input.sh. Deterministic: the same tree gives the same corpus.
Run from anywhere: python3 tests/fuzz/make_corpus.py
"""
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

root = Path(__file__).resolve().parents[2]
out = root / "tests" / "fuzz" / "corpus"
PNG = b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x10\x00\x00\x00\x08\x08\x00\x00\x00\x00"


def put(target, data, name=None):
    d = out / target
    d.mkdir(parents=True, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    name = name or hashlib.sha1(data).hexdigest()[:16]
    (d / name).write_bytes(data)


def json_variants(text):
    """The bad-input cases of the tests, applied to one JSON file."""
    yield text[: len(text) // 2]
    yield text.rstrip().rstrip("}") + ",}"
    yield ""
    yield bytes(range(256)) * 2
    yield PNG
    yield text.replace("{", '{"no_such_key": 1, ', 1)
    number = re.compile(r"(?<=[:\[ ])-?\d+(\.\d+)?([eE][-+]?\d+)?")
    yield number.sub("NaN", text, count=1)
    yield number.sub("1e308", text, count=1)
    yield number.sub("-1e308", text, count=3)
    yield number.sub("0", text)
    yield number.sub("-1", text)
    yield number.sub("2147483648", text, count=2)
    yield text.replace('"', "'", 2)
    yield "[" * 4000 + "]" * 4000
    yield '{"a": ' * 2000 + "1" + "}" * 2000


def json_seeds(target, files):
    for f in files:
        text = f.read_text()
        put(target, text)
        for v in json_variants(text):
            put(target, v)


def recorded_flight():
    """A flight as `planet fly --record` writes it: body-frame positions and
    attitudes, the clock, the exposure."""
    keyframes = []
    for i in range(3):
        keyframes.append({
            "time": i / 30.0,
            "position_body_m": [6378137.0 + 2.0 + i, 0.5 * i, 0.0],
            "body_from_camera_wxyz": [0.5, 0.5, 0.5, 0.5],
            "clock_s": i / 30.0,
            "exposure": 1.0,
        })
    return json.dumps({"body": "earth", "image": {"width": 64, "height": 32},
                       "frame_rate": 30, "vertical_fov_deg": 60, "technique": "hillaire",
                       "start_utc": "2026-06-21T12:00:00.000Z", "exposure": 1.0,
                       "keyframes": keyframes}, indent=2)


def obj_seeds():
    asteroid = (root / "data/shapes/asteroid.obj").read_text()
    put("obj_cage", asteroid)
    cube = """v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1
f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"""
    put("obj_cage", cube)
    put("obj_cage", cube.replace("f 1 4 3 2", "f 1/1 4/2 3/3 2/4").replace("f 5 6 7 8", "f -4//1 -3//1 -2//1 -1//1"))
    put("obj_cage", cube.replace("f 4 1 5 8\n", ""))                 # open
    put("obj_cage", cube.replace("f 1 4 3 2", "f 1 2 3 4"))          # flipped face
    put("obj_cage", cube.replace("f 3 4 8 7", "f 3 4 8 99"))         # index out of range
    put("obj_cage", cube.replace("v 1 1 1", "v nan 1 1"))            # not finite
    put("obj_cage", cube.replace("f 1 2 6 5", "f 1 2 6 5 1 2 6 5"))  # repeated vertices
    put("obj_cage", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n")
    put("obj_cage", "v 0 0 0\nf 1 1 1\n")
    put("obj_cage", "")
    put("obj_cage", asteroid[: len(asteroid) // 2])
    put("obj_cage", bytes(range(256)))
    # A measured model as shipped (Eros's: comments, E-notation, 3897
    # vertices): its head, cut in a vertex line, and a closed tetrahedron in
    # its number format with a NaN.
    eros = (root / "data/shapes/eros/eros007790.obj").read_text()
    put("obj_cage", eros[:2000])
    tetra = ("v    1.00000E+00   0.00000E+00  -7.07107E-01\nv   -1.00000E+00   0.00000E+00  -7.07107E-01\n"
             "v    0.00000E+00   1.00000E+00   7.07107E-01\nv    0.00000E+00  -1.00000E+00   7.07107E-01\n"
             "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n")
    put("obj_cage", eros.split("\nv ")[0] + "\n" + tetra)
    put("obj_cage", tetra.replace("1.00000E+00", "nan", 1))


def height_map_seeds(scratch):
    """Small height maps through oiiotool, each led by the byte that picks
    its extension in the target (.png .exr .tif .pgm .hdr .jpg)."""
    extensions = [".png", ".exr", ".tif", ".pgm", ".hdr", ".jpg"]
    for i, ext in enumerate(extensions):
        f = scratch / f"h{ext}"
        fmt = {".png": "uint16", ".exr": "half", ".tif": "float", ".pgm": "uint8", ".hdr": "float", ".jpg": "uint8"}[ext]
        channels = "3" if ext == ".hdr" or ext == ".jpg" else "1"
        fill = ["--fill:bottom=0,0,0:top=1,1,1", "0,0,16,8"] if channels == "3" else ["--fill:bottom=0:top=1", "0,0,16,8"]
        subprocess.run(["oiiotool", "--nosoftwareattrib", "--create", "16x8", channels, *fill, "-d", fmt, "-o", str(f)], check=True)
        data = f.read_bytes()
        put("height_map", bytes([i]) + data)
        put("height_map", bytes([i]) + data[: len(data) // 2])
    put("height_map", b"\x00" + PNG)
    put("height_map", b"\x01" + b"v/1\x01" + bytes(64))


def grid_height_seeds(scratch):
    """Elevation grids as the target reads them: a byte for the layout
    (0 int16_le, 1 int16_be, 2 png_u16; plus 3 for node rows, 6 for
    geodetic ones), the declared width (2 + 2 (b % 40)) and height
    (1 + b % 40), then the file: the shipped grids' first rows, cut to the
    declared size and beside it, and a 16-bit PNG."""
    def head(a, b):  # width 2 + 2a, height 1 + b
        return bytes([a, b])
    moon = (root / "data/elevation/moon/LDEM_4.IMG").read_bytes()
    mars = (root / "data/elevation/mars/megt90n000cb.img").read_bytes()
    for layout, data in ((0, moon), (1, mars)):
        for registration in (0, 3):
            size = 2 * 80 * 40
            put("grid_height", bytes([layout + registration]) + head(39, 39) + data[:size])
            put("grid_height", bytes([layout + registration + 6]) + head(3, 3) + data[: 2 * 8 * 4])
            put("grid_height", bytes([layout + registration]) + head(3, 3) + data[: 2 * 8 * 4 - 1])
            put("grid_height", bytes([layout + registration]) + head(3, 3) + data[: 2 * 8 * 5])
    put("grid_height", bytes([0]) + head(3, 3) + b"\x00\x80" * 32)  # missing-data values
    f = scratch / "grid.png"
    subprocess.run(["oiiotool", "--nosoftwareattrib", "--create", "8x4", "1", "--fill:bottom=0.4:top=0.6",
                    "0,0,8,4", "-d", "uint16", "-o", str(f)], check=True)
    data = f.read_bytes()
    put("grid_height", bytes([2]) + head(3, 3) + data)
    put("grid_height", bytes([5]) + head(3, 4) + data)
    put("grid_height", bytes([2]) + head(3, 3) + data[: len(data) // 2])
    put("grid_height", bytes([2]) + head(3, 3) + PNG)


def reference_seeds():
    sums = sorted((root / "data/reference").glob("stability-*-16x8-*.sums"))[:2]
    for f in sums:
        data = f.read_bytes()
        put("reference_sums", data)
        put("reference_sums", data[: len(data) - 8])
        head = data.split(b"\n")
        put("reference_sums", b"\n".join(head[:2] + [b"999999 999999 3"] + head[3:]))
        put("reference_sums", b"\n".join(head[:2] + [head[2], b"-5 -5 -5"] + head[4:]))
    put("reference_sums", "not sums\n")
    put("reference_sums", "")
    for f in sorted((root / "data/reference").glob("stability-*-16x8-*.exr"))[:3]:
        data = f.read_bytes()
        put("reference_exr", data)
        put("reference_exr", data[: len(data) // 2])
        put("reference_exr", data[:200] + bytes(len(data) - 200))
    put("reference_exr", PNG)
    put("reference_exr", "")


def lab_table_seeds():
    for f in sorted((root / "tests/fuzz/seeds/lab_tables").glob("*.json")):
        text = f.read_text()
        put("lab_tables", text)
        for v in json_variants(text):
            put("lab_tables", v)


def measured_seeds():
    capture = root / "data/measured/kider-2013-05-27/2013-05-27___09.30.00"
    for f in sorted(capture.iterdir())[:3] + [sorted(capture.iterdir())[-1]]:
        body = f.read_bytes()
        name = f.name.encode()
        put("measured_sky", name + b"\n" + body)
        put("measured_sky", name + b"\n" + body[: len(body) // 3])
        put("measured_sky", name.replace(b"_-_0____", b"_-_99999999999____") + b"\n" + body)
        put("measured_sky", name.replace(b"12.1151", b".") + b"\n" + body)
        lines = body.split(b"\n")
        put("measured_sky", name + b"\n" + b"\n".join(lines[:5] + [b"2147483647\t1.0"]))
        put("measured_sky", name + b"\n" + b"\n".join(lines[:5] + [b"abc\tdef"] + lines[5:40]))
    put("measured_sky", b"x.txt\n")


def command_line_seeds():
    work = "/tmp/planet-fuzz-work"
    flights = "data/flights"  # the targets run from the repository root
    script = (root / "tests/bad_input.sh").read_text()
    for line in script.splitlines():
        line = line.strip()
        if not line.startswith("expect "):
            continue
        try:
            words = shlex.split(line)
        except ValueError:
            continue
        words = words[2:]  # expect "message"
        if words and words[0] == "env":
            words = [w for w in words[1:] if "=" not in w]
        if not words or words[0] not in ('$planet', '"$planet"', "${sun[@]}"):
            if words and words[0].startswith("$planet"):
                pass
        argv = []
        for w in words[1:] if words and "planet" in words[0] else words:
            w = w.replace("$flights", flights).replace("$work", work)
            argv.append(w)
        if words and "sun[@]" in words[0]:
            argv = ["probe", "sun", "--planet", "earth", "--lon", "2.35", "--time", "2026-06-21T12:00:00Z"] + argv
        put("command_line", "\0".join(argv))
    for argv in (["capture", "--flight", flights + "/ascent.json", "--out", work + "/a", "--frames", "0:1", "--quiet"],
                 ["reference", "--scene", "earth_noon", "--width", "8", "--height", "4", "--spp", "16", "--out", work + "/r.exr"],
                 ["lab", "run", "--help"], ["lab", "stability", "--shard", "1/4", "--bodies", "mars"],
                 ["lab", "measured", "--captures", "09:30", "--directions", "3", "--paths", "10"],
                 ["fly", "--planet", "mars", "--technique", "hillaire:cheap", "--error-budget", "5"],
                 ["cluster", "slurm", "--shares", "4", "--", "reference", "--scene", "earth_noon"],
                 ["probe", "sky", "--planet", "earth", "--technique", "raymarch:view_steps=8"],
                 ["accuracy", "--scene", "earth_noon", "--technique", "bruneton:orders=4", "--paths", "4096"],
                 ["techniques"], ["--help"], ["capture", "--shard", "1/3", "--flight", flights + "/ascent.json"],
                 ["--version"], ["probe", "ground", "--planet", "mars", "--lat", "18.65", "--lon", "226.2"],
                 ["lab", "run", "--techniques", "raymarch:view_steps=8,light_steps=4,hillaire", "--quality",
                  "default", "fine", "--scenes", "earth_noon,", "--techniques", "oneil"],
                 ["lab", "governor", "--budget", "2,5", "10", "--canonical-only"],
                 ["soak", "--bodies", ",", "--techniques", "=,:,=x"]):
        put("command_line", "\0".join(argv))


def main():
    if out.exists():
        shutil.rmtree(out)
    scratch = root / "tests" / "fuzz" / ".scratch"
    scratch.mkdir(exist_ok=True)
    try:
        json_seeds("body", sorted((root / "data/planets").glob("*.json")))
        flights = sorted((root / "data/flights").glob("*.json")) + sorted((root / "tests/data/flights").glob("*.json"))
        # Keyframes that the shipped flights do not hold (heights above the ground).
        flights += sorted((root / "tests/fuzz/seeds/flight").glob("*.json"))
        json_seeds("flight", flights)
        put("flight", recorded_flight())
        for v in json_variants(recorded_flight()):
            put("flight", v)
        obj_seeds()
        height_map_seeds(scratch)
        grid_height_seeds(scratch)
        reference_seeds()
        lab_table_seeds()
        measured_seeds()
        json_seeds("error_model", [root / "data/lab/error_model.json"])
        command_line_seeds()
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    for d in sorted(out.iterdir()):
        print(f"{d.name}: {len(list(d.iterdir()))} seeds")


if __name__ == "__main__":
    sys.exit(main())
