#!/usr/bin/env bash
# Configures and builds rtcli in build/ (Release unless told otherwise).
#   tools/build.sh [--dir FOLDER] [CMake options...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir=build
if [ "${1:-}" = "--dir" ]; then
  dir="$2"
  shift 2
fi
cmake -S "$root" -B "$root/$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$root/$dir" --parallel
