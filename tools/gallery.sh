#!/usr/bin/env bash
# Renders every scene of the gallery and writes the static site (tools/gallery/gallery.py).
#   tools/gallery.sh            the published page: docs/index.html, docs/style.css, docs/gallery/
#   tools/gallery.sh --fast     small images into a temporary folder (what the tests run); never docs/
#   tools/gallery.sh --fast --out DIR [--rtcli PATH]   (PATH: the rtcli to render with, the thumbnail tool beside it; default build/rtcli)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
fast=() out="" rtcli=()
while [ $# -gt 0 ]; do
  case "$1" in
    --fast) fast=(--fast) ;;
    --out) out="$2"; shift ;;
    --rtcli) rtcli=(--rtcli "$2"); shift ;;
    *) echo "usage: tools/gallery.sh [--fast] [--out DIR] [--rtcli PATH]" >&2; exit 2 ;;
  esac
  shift
done
if [ -z "$out" ]; then
  if [ ${#fast[@]} -gt 0 ]; then out="$(mktemp -d)"; else out="$root/docs"; fi
fi
[ ${#rtcli[@]} -gt 0 ] || { [ -x "$root/build/rtcli" ] && [ -x "$root/build/thumbnail" ]; } || "$root/tools/build.sh"
python3 "$root/tools/gallery/gallery.py" --out "$out" "${fast[@]}" "${rtcli[@]}"
