#!/usr/bin/env bash
# README command 1: install what is missing, build, render the default scene.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/install-deps.sh"
"$root/tools/build.sh" -DRTCLI_BUILD_TESTS=OFF
cd "$root"
build/rtcli render scenes/default.json
