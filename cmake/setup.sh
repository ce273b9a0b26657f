#!/usr/bin/env bash
# Sets eomgen up on a Debian machine and does one job:
#   bash cmake/setup.sh run    install what is missing, build, run `eomgen run` on the default model
#   bash cmake/setup.sh test   install what is missing, build, run every test (CTest)
#   bash cmake/setup.sh build  install what is missing and build
# Packages come from Debian only; the build downloads nothing.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
action="${1:-build}"
build="${EOMGEN_BUILD_DIR:-$root/build}"

case "$action" in
  run|test|build) ;;
  *) echo "usage: bash cmake/setup.sh run|test|build" >&2; exit 2 ;;
esac

packages=(g++ cmake make pkg-config diffutils python3 python3-sympy python3-numpy
          libginac-dev libcln-dev libeigen3-dev libsundials-dev
          libtomlplusplus-dev libcli11-dev libfmt-dev gnuplot-nox
          libgtest-dev libgmock-dev libbenchmark-dev clang libmujoco-dev libxml2-utils
          openmpi-bin libopenmpi-dev openssh-client libjs-three chromium)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "eomgen setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
else
  echo "eomgen setup: all Debian packages present" >&2
fi

jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >&2
cmake --build "$build" -j "$jobs" >&2

case "$action" in
  run) cd "$root" && exec "$build/generator/eomgen" run ;;
  test) cd "$build" && exec ctest --output-on-failure -j "$jobs" ;;
  build) ;;
esac
