#!/bin/sh
# Anti-aliasing error against a reference (docs/rendering.md, "Anti-aliasing"): renders SCENE (default
# scenes/antialias.json) with uniform 16 x 16 samples as the reference, then with each sampler
# setting below, and prints the render time, camera rays per pixel and RMS error (levels of 255)
# of each.
# Usage: tools/aa_error.sh [SCENE]   (after tools/build.sh)
set -eu
cd "$(dirname "$0")/.."
scene=${1:-scenes/antialias.json}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rtcli=build/rtcli
render() {  # name, options...: prints the camera rays per pixel and the render time
  name=$1
  shift
  "$rtcli" render "$scene" -o "$out/$name.png" --seed 1 "$@" 2>&1 |
    sed -n -e 's/.*(\([0-9.]*\) camera rays).*/\1/p' -e 's/.* in \([0-9.]*\) s (load.*/\1/p' | tr '\n' ' '
}

render reference --aa uniform --aa-samples 16 >/dev/null
printf '%-72s %8s %12s %8s\n' "options" "time (s)" "camera rays" "RMS"
while read -r name options; do
  set -- $(render "$name" $options)
  rms=$(build/imagediff "$out/reference.png" "$out/$name.png" | sed -n 's/^rms \([0-9.]*\).*/\1/p')
  printf '%-72s %8s %12s %8s\n' "$options" "$1" "$2" "$rms"
done <<'LIST'
none --aa none
u2 --aa uniform --aa-samples 2
u3 --aa uniform --aa-samples 3
u4 --aa uniform --aa-samples 4
a1 --aa adaptive --aa-depth 1 --aa-threshold 0.1
a2 --aa adaptive --aa-depth 2 --aa-threshold 0.1
a3 --aa adaptive --aa-depth 3 --aa-threshold 0.1
a3t05 --aa adaptive --aa-depth 3 --aa-threshold 0.05
a3t02 --aa adaptive --aa-depth 3 --aa-threshold 0.02
a4t05 --aa adaptive --aa-depth 4 --aa-threshold 0.05
c2 --aa adaptive --aa-depth 2 --aa-threshold 0.1 --aa-positions centres
c3 --aa adaptive --aa-depth 3 --aa-threshold 0.1 --aa-positions centres
LIST
