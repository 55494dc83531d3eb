#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, with AddressSanitizer and UndefinedBehaviorSanitizer) in
# build-fuzz/ and runs one of them:
#
#   tools/fuzz.sh TARGET SECONDS [libFuzzer options...]
#
#   scene         JSON scene files: parse, check, build, render a few pixels
#   gltf          glTF models (.gltf text and .glb): import, place, build a BVH
#   bvh           the BVH builder and traversal on triangles with extreme coordinates
#   texture       image bytes of any format: identify, decode (PNG, JPEG), build mip levels, sample
#                 with every filter and wrap
#   texture_file  the same bytes as a scene file's texture file: load, build, render 4x4
#   gltf_image    the same bytes as a glTF image in a buffer view, used in every material slot
#   extras_image  the same bytes as the image file a glTF material's rtcli_bump extras name
#   environment   Radiance .hdr bytes: decode, build the sampling distribution, sample and look up
#   environment_exr  OpenEXR bytes as a scene's environment file: load (bounded reader, structure
#                 walk, OpenEXR's RGBA interface, texel budget), sample and look up
#   exr           OpenEXR bytes as a tile for rtcli merge: read every channel and attribute within a
#                 pixel limit of 2^20 (so every channel x pixel product is in reach), merge
#
#   tools/fuzz.sh all SECONDS    every target in turn, SECONDS each
#
# The corpus lives in build-fuzz/corpus/TARGET, seeded on the first run from scenes/, tests/,
# ../shared/gltf and tests/fuzz/regressions/TARGET. An input that crashes, leaks, hangs (10 s),
# runs out of memory (2 GiB) or breaks an invariant is saved in build-fuzz/artifacts/TARGET/.
# Once fixed, copy it into tests/fuzz/regressions/TARGET/: the normal test suite replays it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
targets="scene gltf bvh texture texture_file gltf_image extras_image environment environment_exr exr"
if [ $# -lt 2 ] || ! [[ " $targets all " == *" $1 "* ]] || ! [[ "$2" =~ ^[0-9]+$ ]]; then
  echo "usage: tools/fuzz.sh ${targets// /|}|all SECONDS [libFuzzer options...]" >&2
  exit 2
fi
if [ "$1" = all ]; then
  for t in $targets; do "$0" "$t" "${@:2}" || exit $?; done
  exit 0
fi
target="$1" seconds="$2"
shift 2

"$root/tools/install-deps.sh" clang libclang-rt-14-dev
build="$root/build-fuzz"
CXX=clang++ CC=clang cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRTCLI_FUZZ=ON -DRTCLI_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target "fuzz_$target"

corpus="$build/corpus/$target" artifacts="$build/artifacts/$target"
mkdir -p "$corpus" "$artifacts"
seed() {  # copies files (up to 256 KiB each) into the corpus, named by content
  for f in "$@"; do
    [ -f "$f" ] && [ "$(stat -c %s "$f")" -le 262144 ] || continue
    cp "$f" "$corpus/seed-$(sha1sum "$f" | cut -c1-16)"
  done
}
if [ -z "$(ls -A "$corpus")" ]; then
  shopt -s nullglob globstar
  case "$target" in
    scene) seed "$root"/scenes/*.json "$root"/tests/data/**/*.json ;;
    gltf) seed "$root"/scenes/models/*.gl* "$root"/../shared/gltf/**/*.gltf "$root"/../shared/gltf/**/*.glb ;;
    bvh) python3 "$root/tests/fuzz/make_bvh_seeds.py" "$corpus" ;;
    environment) seed "$root"/scenes/textures/*.hdr ;;
    exr | environment_exr) seed "$root"/tests/fuzz/regressions/exr/* ;;
    texture | texture_file | gltf_image | extras_image)
      seed "$root"/tests/data/images/* "$root"/tests/data/bad/textures/*.png "$root"/tests/fuzz/regressions/texture/*
      if [ "$target" = texture ]; then seed "$root"/scenes/textures/*.png "$root"/../shared/gltf/**/*.png; fi ;;
  esac
  seed "$root"/tests/fuzz/regressions/"$target"/*
fi
echo "fuzzing $target for $seconds s; corpus $(ls "$corpus" | wc -l) files" >&2
cd "$build"  # libFuzzer writes crash-* files relative to -artifact_prefix
dict=()
[ -f "$root/tests/fuzz/$target.dict" ] && dict=(-dict="$root/tests/fuzz/$target.dict")
[[ "$target" =~ texture|image ]] && dict=(-dict="$root/tests/fuzz/image.dict")
exec "$build/fuzz_$target" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=262144 "${dict[@]}" -artifact_prefix="$artifacts/" -print_final_stats=1 "$@"
