#!/usr/bin/env bash
# Set-up, build and the whole test suite.
#   scripts/test.sh             Release build (what CI runs)
#   scripts/test.sh sanitize    Debug build under AddressSanitizer + UBSan
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
scripts/setup.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j"$(nproc)"
ctest --preset "$preset" -j"$(nproc)"
