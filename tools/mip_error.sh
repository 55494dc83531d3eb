#!/bin/sh
# Texture filtering error against a reference (docs/rendering.md, "Textures"): renders scenes/receding_plane.json
# (a checkered table top receding to the horizon) with 16 x 16 samples per pixel and bilinear
# filtering as the reference, then at one sample per pixel with each filter, and prints the RMS
# error (levels of 255) and time of each. Usage: tools/mip_error.sh [SCENE]   (after tools/build.sh)
set -eu
cd "$(dirname "$0")/.."
scene=${1:-scenes/receding_plane.json}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
render() {  # name, options...: prints the render time
  name=$1
  shift
  build/rtcli render "$scene" -o "$out/$name.png" "$@" 2>&1 | sed -n 's/.* in \([0-9.]*\) s (load.*/\1/p'
}
render reference --texture-filter bilinear --aa uniform --aa-samples 16 >/dev/null
printf '%-58s %8s %8s\n' "options" "time (s)" "RMS"
while read -r name options; do
  time=$(render "$name" $options)
  rms=$(build/imagediff "$out/reference.png" "$out/$name.png" | sed -n 's/^rms \([0-9.]*\).*/\1/p')
  printf '%-58s %8s %8s\n' "$options" "$time" "$rms"
done <<'LIST'
nearest --aa none --texture-filter nearest
bilinear --aa none --texture-filter bilinear
trilinear --aa none --texture-filter trilinear
bilinear4 --aa uniform --aa-samples 4 --texture-filter bilinear
trilinear4 --aa uniform --aa-samples 4 --texture-filter trilinear
adaptive --aa adaptive --texture-filter trilinear
LIST
