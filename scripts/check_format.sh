#!/usr/bin/env bash
# Checks that every C++ source and header the repository tracks is formatted
# as .clang-format says (Debian's clang-format). Prints each file that
# drifts and exits 1; with --fix, formats them in place instead.
#
# usage: scripts/check_format.sh [--fix]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
command -v clang-format >/dev/null || { echo "check_format: clang-format is not installed (apt-get install clang-format)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
drift=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f (scripts/check_format.sh --fix)"
    drift=$((drift + 1))
  fi
done
echo "check_format: ${#files[@]} files, $drift not formatted"
[ "$drift" -eq 0 ]
