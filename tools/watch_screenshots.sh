#!/usr/bin/env bash
# Screenshots of `rtcli watch` for the gallery (docs/images/watch-*.png), as the browser test
# takes them (tests/cli/test_watch.cpp): scenes/cafe.json as first shown; after an edit saved to
# the material library it includes; with a mistake in the furniture file, located, the last good
# picture kept; fixed, seen as its normals. Needs chromium and curl.
#   tools/watch_screenshots.sh [--rtcli build/rtcli] [--out docs/images]
set -euo pipefail
cd "$(dirname "$0")/.."
rtcli=build/rtcli
out=docs/images
while [ $# -gt 0 ]; do
  case "$1" in
    --rtcli) rtcli=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "usage: $0 [--rtcli PATH] [--out FOLDER]" >&2; exit 2 ;;
  esac
done
rtcli=$(realpath "$rtcli")
mkdir -p "$out"
out=$(realpath "$out")
work=$(mktemp -d)
pid=
cleanup() { [ -n "$pid" ] && kill -INT "$pid" 2>/dev/null; wait 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
cp -r scenes/cafe.json scenes/library scenes/models scenes/textures "$work/"
cd "$work"
"$rtcli" watch cafe.json --port 0 --width 480 --height 300 > watch.txt 2>&1 &
pid=$!
port=
for _ in $(seq 100); do
  port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\)\/.*/\1/p' watch.txt)
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { cat watch.txt >&2; exit 1; }
status() { curl -s --noproxy '*' "http://127.0.0.1:$port/status"; }
# Waits until the status matches a Python expression over it (s).
wait_for() {
  for _ in $(seq 600); do
    status | python3 -c "import json,sys; s=json.load(sys.stdin); sys.exit(0 if ($1) else 1)" && return 0
    sleep 0.1
  done
  echo "timed out waiting for: $1" >&2
  status >&2
  exit 1
}
shot() {  # NAME [QUERY]
  timeout 60 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=2000 \
    --window-size=1000,520 --screenshot="$out/$1" "http://127.0.0.1:$port/${2:-}" >/dev/null 2>&1
  echo "wrote $out/$1"
}
done_version() { echo "s['image'] is not None and s['image']['last'] and s['image']['scene_version'] == $1"; }

wait_for "$(done_version 1)"
shot watch-1-first.png
sed -i 's/"red_paint": {"kd": \[0.7, 0.08, 0.06\]/"red_paint": {"kd": [0.85, 0.6, 0.05]/' library/materials.json
wait_for "$(done_version 2)"
shot watch-2-edited.png
sed -i 's/"name": "seat", "shape": "cylinder"/"name": "seat", "shape": "cylindre"/' library/furniture.json
wait_for "s['load_failed']"
shot watch-3-error.png
sed -i 's/"shape": "cylindre"/"shape": "cylinder"/' library/furniture.json
wait_for "$(done_version 3)"
shot watch-4-normals.png "?layer=normal"
