#!/usr/bin/env bash
# Installs the Debian 12 packages rtcli needs, if any are missing: with apt-get as root, through
# sudo otherwise. If neither works it lists the packages to install and fails. Extra package
# names given as arguments are installed too (tools/fuzz.sh and --sanitize add clang's).
# With --tests first, the optional test tools (chromium, for the gallery's browser test; slurm-wlm
# munge and procps's pgrep, for the farm test on a one-node cluster; blender with python3-numpy, and xvfb with
# xauth for its window, for the Blender add-on's tests; povray, for rtcli bench --against povray's) are tried after them; a failure to install
# one is said but does not stop the build (that test then says it is skipped). tools/test.sh passes it; quickstart and the fuzzers do not need them.
set -euo pipefail
optional=()
if [ "${1:-}" = "--tests" ]; then
  optional=(chromium slurm-wlm munge procps blender python3-numpy xvfb xauth povray)
  shift
fi

packages=(g++ cmake ninja-build pkg-config
          libtinygltf-dev nlohmann-json3-dev libglm-dev libstb-dev zlib1g-dev libcli11-dev
          catch2 libvalijson-dev libgif-dev libjpeg-dev libopenexr-dev libcpp-httplib-dev libdraco-dev libmeshoptimizer-dev libopencolorio-dev libwebp-dev python3 tidy "$@")

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
optional_missing=()
for p in ${optional[@]+"${optional[@]}"}; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || optional_missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && [ ${#optional_missing[@]} -eq 0 ] && exit 0

echo "rtcli: installing missing packages: ${missing[*]} ${optional_missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  run=()
elif command -v sudo >/dev/null 2>&1; then
  run=(sudo)
else
  [ ${#missing[@]} -eq 0 ] && { echo "rtcli: note: not root and no sudo: ${optional_missing[*]} not installed" >&2; exit 0; }
  echo "rtcli: error: not root and no sudo; please install as root: apt-get install ${missing[*]}" >&2
  exit 1
fi
if ! { "${run[@]}" apt-get update -qq &&
       DEBIAN_FRONTEND=noninteractive "${run[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"; }; then
  echo "rtcli: error: could not install the packages; please run: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi
if [ ${#optional_missing[@]} -gt 0 ] &&
   ! DEBIAN_FRONTEND=noninteractive "${run[@]}" apt-get install -y -qq --no-install-recommends "${optional_missing[@]}"; then
  echo "rtcli: note: could not install ${optional_missing[*]} (optional: the gallery's browser test, the Slurm farm test or the Blender add-on's tests are skipped)" >&2
fi
