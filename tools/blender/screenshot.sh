#!/usr/bin/env bash
# The screenshot of Blender showing an rtcli render (docs/images/blender-addon.png), taken as the
# test takes it (tests/tools/test_blender_addon.cpp): the fixture saved with the engine chosen,
# then F12 in Blender's window under Xvfb, headless. Needs blender, python3-numpy and xvfb.
#   tools/blender/screenshot.sh [--rtcli build/rtcli] [--out docs/images/blender-addon.png]
set -euo pipefail
cd "$(dirname "$0")/../.."
rtcli=build/rtcli
out=docs/images/blender-addon.png
while [ $# -gt 0 ]; do
  case "$1" in
    --rtcli) rtcli=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "usage: $0 [--rtcli PATH] [--out FILE.png]" >&2; exit 2 ;;
  esac
done
rtcli=$(realpath "$rtcli")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/config"
export BLENDER_USER_SCRIPTS="$work/scripts" BLENDER_USER_CONFIG="$work/config" TMPDIR="$work"
blender -b --factory-startup --python-exit-code 1 --python tests/data/blender/addon_test.py -- blend "$work" "$rtcli" \
  > "$work/blend.log" 2>&1 || { cat "$work/blend.log" >&2; exit 1; }
xvfb-run -a -s "-screen 0 1280x720x24" blender --factory-startup "$work/fixture.blend" \
  --python tests/data/blender/ui_test.py -- "$work" "$rtcli" > "$work/ui.log" 2>&1 || { cat "$work/ui.log" >&2; exit 1; }
grep "addon ui:" "$work/ui.log"
cp "$work/blender.png" "$out"
echo "wrote $out"
