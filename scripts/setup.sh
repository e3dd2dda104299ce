#!/usr/bin/env bash
# Installs the Debian packages this project needs (only those missing),
# then configures and builds it in ./build (Release). Safe to run again:
# it only does what is left to do. Both README commands start with it.
# usage: setup.sh [--tests]
#   --tests  also builds the programs only the tests run: the test
#            programs (tests/*.cc) and the program built with the
#            sanitizers (bench/first_hour.py times both commands)
set -euo pipefail
cd "$(dirname "$0")/.."
with_tests=false
case "${1:-}" in
  --tests) with_tests=true ;;
  "") ;;
  *) echo "usage: scripts/setup.sh [--tests]" >&2; exit 2 ;;
esac

packages=(libdeal.ii-dev libfclib-dev libopenblas0-pthread cmake g++ make python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "-- installing: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y "${missing[@]}"
fi

build_type="${BUILD_TYPE:-Release}"
jobs="$(nproc)"
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE="$build_type"
fi
if $with_tests; then
  cmake --build build -j "$jobs" --target all test_programs contact_sanitized
else
  cmake --build build -j "$jobs"
fi
if ! command -v pvbatch > /dev/null || ! command -v Xvfb > /dev/null; then
  echo "-- optional: ParaView pictures (scripts/render_contact.py, scripts/make_gallery.sh)"
  echo "   need: apt-get install paraview python3-paraview xvfb"
fi
