#!/usr/bin/env bash
# Installs the Debian packages hullcover builds against, and the npm test
# tools (tests/tools/gltf-validator: the Khronos glTF validator, pinned by its
# package-lock.json). Idempotent and non-interactive: what is present is left
# alone, so a second run asks nothing of the network. Needs root (or sudo)
# only when a Debian package is missing.
set -euo pipefail

# The glTF validator the export tests run on every .glb hullcover writes
# (test_collider_export skips, saying so, where npm is absent).
install_test_tools() {
  local tools
  tools="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/tools/gltf-validator"
  if [ -d "$tools/node_modules/gltf-validator" ]; then return 0; fi
  if ! command -v npm >/dev/null; then
    echo "setup: npm not found: the glTF validator test will be skipped" >&2
    return 0
  fi
  echo "setup: installing the glTF validator (npm ci in tests/tools/gltf-validator)"
  npm ci --prefix "$tools" --no-audit --no-fund --loglevel=error
}

packages=(
  build-essential cmake pkg-config
  libfcl-dev libccd-dev libeigen3-dev liboctomap-dev libqhull-dev libassimp-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev
  libcairo2-dev
  chromium  # tests/apps/test_audit_html.cpp opens the audit's HTML report headless (skipped without it)
  clang libclang-rt-14-dev  # the fuzzing and sanitizer builds
  clang-format  # scripts/check_format.sh, in CI
  python3-dev python3-pybind11 python3-numpy python3-pytest  # the Python module (apps/python) and its tests
  python3-distributed  # the distributed bake (python3 -m hullcover.bake) on Dask
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages present"
  install_test_tools
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_test_tools
