#!/usr/bin/env bash
# README command 2 (and CI): install what is missing, build with tests, run the whole suite.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/install-deps.sh"
"$root/tools/build.sh" -DRTCLI_BUILD_TESTS=ON
ctest --test-dir "$root/build" --output-on-failure --parallel "$(nproc)"
