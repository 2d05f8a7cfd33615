#!/usr/bin/env bash
# Set-up, build and the whole test suite.
#   scripts/test.sh                       Release build, every test (what CI runs)
#   scripts/test.sh sanitize              Debug build under AddressSanitizer + UBSan
#   scripts/test.sh sanitize-optimized    the same on an optimized build (the scene tier in minutes)
#   scripts/test.sh PRESET LABEL          one tier only: LABEL is unit (seconds) or scene (the shared scenes)
# HULLCOVER_WARNINGS_AS_ERRORS=ON in the environment fails the build on any warning (CI sets it).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
label="${2:-}"
scripts/setup.sh
cmake --preset "$preset" -DHULLCOVER_WARNINGS_AS_ERRORS="${HULLCOVER_WARNINGS_AS_ERRORS:-OFF}" >/dev/null
cmake --build --preset "$preset" -j"$(nproc)"
if [ -n "$label" ]; then
  ctest --preset "$preset" -j"$(nproc)" -L "$label"
else
  ctest --preset "$preset" -j"$(nproc)"
fi
