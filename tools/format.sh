#!/usr/bin/env bash
# The code's one style (.clang-format, clang-format 14 as Debian 12 ships it), over every C++ file
# git tracks (the fuzzers' regression inputs are data, not code).
#   tools/format.sh           rewrite the files that differ
#   tools/format.sh --check   change nothing; list the files that differ and fail if any do
#                             (tools/test.sh runs this before the suite)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
check=0
case "${1:-}" in
  "") ;;
  --check) check=1 ;;
  *) echo "usage: tools/format.sh [--check]" >&2; exit 2 ;;
esac
format="$(command -v clang-format-14 || command -v clang-format || true)"
[ -n "$format" ] || { echo "format: clang-format is not installed (apt-get install clang-format)" >&2; exit 1; }
cd "$root"
mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.cpp.in' | grep -v '^tests/fuzz/regressions/')
if [ "$check" -eq 0 ]; then
  "$format" -i "${files[@]}"
  exit 0
fi
differ=()
for f in "${files[@]}"; do
  "$format" --dry-run --Werror "$f" >/dev/null 2>&1 || differ+=("$f")
done
if [ ${#differ[@]} -gt 0 ]; then
  printf 'format: %s differs from .clang-format\n' "${differ[@]}" >&2
  echo "format: ${#differ[@]} of ${#files[@]} files differ; tools/format.sh rewrites them" >&2
  exit 1
fi
echo "format: ${#files[@]} files in the style of .clang-format" >&2
