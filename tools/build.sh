#!/usr/bin/env bash
# Configures and builds rtcli in build/ (Release unless told otherwise).
#   tools/build.sh [--dir FOLDER] [--pgo] [CMake options...]
# --pgo: a build guided by a profile (GCC): the same images 2-4% sooner on Whitted scenes, for two
# and a half times the build. An instrumented rtcli is built in FOLDER-pgo-train and trained on the
# shipped scenes (tools/pgo/train.sh), then FOLDER is built with its profile (docs/benchmark.md,
# "Round two, a twenty-second session: a build guided by a profile"). Without --pgo, FOLDER is
# built without a profile, whatever it held before.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir=build
pgo=0
while [ $# -gt 0 ]; do
  case "$1" in
    --dir) dir="${2:?tools/build.sh: --dir needs a folder}"; shift 2 ;;
    --pgo) pgo=1; shift ;;
    *) break ;;
  esac
done
configure() { cmake -S "$root" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null; }
if [ "$pgo" = 1 ]; then
  train="$root/$dir-pgo-train"
  profile="$train/profile"
  configure -B "$train" "$@" -DRTCLI_BUILD_TESTS=OFF -DRTCLI_PGO=generate "-DRTCLI_PGO_DIR=$profile"
  cmake --build "$train" --parallel --target rtcli
  rm -rf "$profile"  # counts from an earlier training (of other code) would add to this one's
  echo "tools/build.sh: training the profile (tools/pgo/train.sh)"
  "$root/tools/pgo/train.sh" "$train/rtcli"
  configure -B "$root/$dir" "$@" -DRTCLI_PGO=use "-DRTCLI_PGO_DIR=$profile"
else
  configure -B "$root/$dir" -DRTCLI_PGO= "$@"
fi
cmake --build "$root/$dir" --parallel
