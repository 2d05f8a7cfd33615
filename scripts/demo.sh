#!/usr/bin/env bash
# Set-up, Release build and the main job on the embedded default scene.
# Outputs go to out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
build/release/apps/hullcover demo --out out/demo
