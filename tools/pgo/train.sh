#!/usr/bin/env bash
# The training run of a profile-guided build (tools/build.sh --pgo): an rtcli built with
# -DRTCLI_PGO=generate renders what users render, and GCC's counters (.gcda files in its
# RTCLI_PGO_DIR) record which branches and calls were hot, for the build with -DRTCLI_PGO=use.
#   tools/pgo/train.sh BUILD/rtcli
# What it runs, about a minute and a half on one core: every shipped scene (scenes/*.json) with its
# own integrator and path traced, the Blender fixture (tests/data/blender/fixture.glb) both ways,
# then a few of them again with each other instruction set this CPU runs, so that every BVH kernel
# it can choose is trained. On one thread: the counters are plain, not atomic (CMakeLists.txt).
# Not `rtcli bench`: its 300,000-triangle mesh and millions of rays would outweigh every scene
# (measured: reflection.json 0.973x the time of a build without a profile with it in the
# training, 0.955x without). Only files in the repository: a clean clone trains the same way.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rtcli="${1:?usage: tools/pgo/train.sh BUILD/rtcli}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

render() {
  if ! "$rtcli" render "$@" --threads 1 -q -o "$out/image.png" 2>"$out/errors"; then
    cat "$out/errors" >&2
    echo "tools/pgo/train.sh: failed: $rtcli render $*" >&2
    return 1
  fi
}
fixture="$root/tests/data/blender/fixture.glb"

for scene in "$root"/scenes/*.json; do
  render "$scene" --width 320 --height 240
  render "$scene" --integrator path --width 96 --height 72 --spp 16
done
render "$fixture" --width 160 --height 160
render "$fixture" --integrator path --width 160 --height 160 --spp 32

# The other kernels: RTCLI_ISA picks one; a CPU that does not run it refuses at once (exit 2).
for isa in sse avx2 avx512; do
  RTCLI_ISA=$isa "$rtcli" render "$root/scenes/default.json" --width 8 --height 8 -q -o "$out/probe.png" 2>/dev/null ||
    continue
  for scene in reflection refraction soft_shadows csg cornell_box; do
    RTCLI_ISA=$isa render "$root/scenes/$scene.json" --width 160 --height 120
  done
  RTCLI_ISA=$isa render "$fixture" --integrator path --width 96 --height 96 --spp 8
done
