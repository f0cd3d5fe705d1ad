#!/usr/bin/env bash
# Installs every Debian package planet needs to build, test and run.
# Idempotent: packages already present are skipped, and apt is not touched
# at all when nothing is missing.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # GL: loader, EGL, Mesa's llvmpipe for headless rendering, GLFW for windows
  libepoxy-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libglfw3-dev
  # maths, geodesy, geometry, images
  libglm-dev libgeographiclib-dev libosd-dev libopenimageio-dev
  # the Sun's and the Moon's places, the Earth's orientation, leap seconds
  liberfa-dev
  # JPEG (Earth's imagery) through libjpeg-turbo itself
  libjpeg-dev
  # OpenImageIO's own oiiotool reads the captured EXRs' metadata in a test
  openimageio-tools
  # command line, JSON, logging
  libcli11-dev nlohmann-json3-dev libspdlog-dev libfmt-dev
  # HUD
  libimgui-dev libstb-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # the interactive program's test runs a real window under a virtual display
  xvfb xauth xdotool
  # the cluster test runs a one-node Slurm (scripts/slurm-one-node.sh)
  slurm-wlm munge
  # the hardening builds (scripts/hardening.sh): clang with its sanitizer and
  # libFuzzer runtimes
  clang libclang-rt-14-dev
  # Earth's day and night imagery (NASA's Blue Marble and city lights;
  # optional at run time: without it Earth has its palette's colours)
  xplanet-images
  # the lab's charts (lab/report/lab_report.py), and the browser its test opens the report in
  python3-matplotlib chromium
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo="sudo"; else
    echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
