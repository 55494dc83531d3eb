#!/usr/bin/env bash
# README command 2 (and CI, through .ci/run): install what is missing, build, run the test suite.
#
#   tools/test.sh             the style check (tools/format.sh --check), then the whole suite twice:
#                             a Release build (build/), then a build under AddressSanitizer +
#                             UndefinedBehaviorSanitizer (build-asan/)
#   tools/test.sh --plain     only the style check, the Release build and its suite
#   tools/test.sh --sanitize  only the sanitizers: the whole suite under ASan + UBSan, then the
#                             rendering, BVH and threading tests under ThreadSanitizer (build-tsan/)
#
# Every suite runs through CTest; a sanitizer report fails the test that triggered it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mode="${1:-}"
case "$mode" in
  "" | --plain | --sanitize) ;;
  *) echo "usage: tools/test.sh [--plain | --sanitize]" >&2; exit 2 ;;
esac
"$root/tools/install-deps.sh" --tests clang-format
jobs="$(nproc)"

plain() {
  echo "== Style: every C++ file as .clang-format says (tools/format.sh --check)" >&2
  "$root/tools/format.sh" --check
  echo "== Release suite (build/)" >&2
  "$root/tools/build.sh" -DRTCLI_BUILD_TESTS=ON
  ctest --test-dir "$root/build" --output-on-failure --parallel "$jobs"
}

# Sanitizer reports end the process with an error; leak checking stays on.
export ASAN_OPTIONS="abort_on_error=0:detect_leaks=1:strict_string_checks=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"

# -O1 with line tables: what the sanitizers' authors recommend, and a third of -O2's compile time
# on the template-heavy JSON and glTF code. Assertions stay on.
sanitizer_build=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1"
                 -DRTCLI_BUILD_TESTS=ON)

# Under both sanitizers, every test but those that time whole programs for minutes and check
# no code path of their own: the gallery's two (dozens of renders and headless Chromium), the
# benchmark's (its loops are the kernels the BVH tests run), the Slurm farm's (158 s under
# ASan, against 34 s in Release: path-traced tiles on a cluster of this machine; the merge,
# encode and farm code it drives runs under the sanitizers in tests/cli/test_cli_split.cpp) and
# the Blender add-on's (Blender and Cycles, mostly; the rtcli options and glTF extras it uses are
# tested under the sanitizers in tests/cli/test_cli_progress.cpp and test_gltf_world.cpp).
# They are most of the sanitized suite's time, which CI's 15-minute aim cannot spare, and they
# load both cores, so that time-bounded tests beside them fail; the Release suite runs them.
sanitizer_skip="^gallery: |^cli: bench runs on a small model|^farm: |^blender add-on: "

asan() {
  echo "== AddressSanitizer + UndefinedBehaviorSanitizer suite (build-asan/)" >&2
  "$root/tools/build.sh" --dir build-asan "${sanitizer_build[@]}" \
    -DRTCLI_SANITIZE="address,undefined,float-cast-overflow"
  ctest --test-dir "$root/build-asan" --output-on-failure --parallel "$jobs" --exclude-regex "$sanitizer_skip"
}

tsan() {
  echo "== ThreadSanitizer: rendering, BVH build and threads (build-tsan/)" >&2
  "$root/tools/build.sh" --dir build-tsan "${sanitizer_build[@]}" -DRTCLI_SANITIZE=thread
  ctest --test-dir "$root/build-tsan" --output-on-failure --parallel "$jobs" --exclude-regex "$sanitizer_skip" \
    --tests-regex "render|determinism|BVH|thread|Ctrl-C|bench|glTF materials|glTF samples|test binaries"
}

case "$mode" in
  "") plain; asan ;;
  --plain) plain ;;
  --sanitize) asan; tsan ;;
esac
