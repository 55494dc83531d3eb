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
# The published gallery renders the turntable through the farm recipe on a one-node Slurm cluster
# when one can be started here (root, slurm-wlm and munge installed); locally otherwise.
farm=()
if [ ${#fast[@]} -eq 0 ] && [ "$(id -u)" -eq 0 ] && command -v slurmctld >/dev/null && command -v munged >/dev/null; then
  cluster="$(mktemp -d)"
  trap '"$root/tools/slurm/cluster.sh" stop "$cluster"' EXIT
  if "$root/tools/slurm/cluster.sh" start "$cluster" >/dev/null; then
    export SLURM_CONF="$cluster/slurm.conf"
    farm=(--farm)
  else
    echo "gallery: the Slurm cluster did not start; the turntable is rendered locally" >&2
  fi
fi
python3 "$root/tools/gallery/gallery.py" --out "$out" "${fast[@]}" "${rtcli[@]}" "${farm[@]}"
