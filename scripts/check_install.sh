#!/usr/bin/env bash
# Checks that hullcover installs as a CMake package a game project can use:
#   1. configures and builds hullcover (Release) in BUILD_DIR (default build/install-check),
#   2. installs it into a temporary prefix,
#   3. configures and builds apps/example_server (a separate project, copied
#      out of the source tree) against that prefix alone, and checks that it
#      found hullcover there and nothing of the source or build tree,
#   4. bakes a runtime file with the installed `hullcover` and runs the server
#      on it: sauerbraten-pandora from ../shared when present (8 threads x
#      10,000 sweeps), else the demo scene.
# Exit status non-zero on any failure, including a character ending inside a hull.
#
# usage: scripts/check_install.sh [BUILD_DIR]
# environment: JOBS (parallel build jobs, default: all cores)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build/install-check}"
case "$build" in /*) ;; *) build="$repo/$build" ;; esac
jobs="${JOBS:-$(nproc)}"
pandora="$repo/../shared/data/scenes/sauerbraten-pandora.obj"

work="$(mktemp -d "${TMPDIR:-/tmp}/hullcover-install-check.XXXXXX")"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
started=$SECONDS

step() { printf '\n== %s (%ds)\n' "$*" "$((SECONDS - started))"; }
fail() { printf 'check_install: FAILED: %s\n' "$*" >&2; exit 1; }

# Nothing from the caller's environment may point CMake elsewhere.
unset CMAKE_PREFIX_PATH hullcover_DIR hullcover_ROOT HULLCOVER_ROOT

step "build hullcover in $build"
# A build folder already configured (CI's Release build of the tests) keeps
# its own settings; a new one builds the libraries and the tool only.
if [ -f "$build/CMakeCache.txt" ]; then
  cmake -S "$repo" -B "$build" >/dev/null
else
  cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DHULLCOVER_BUILD_TESTS=OFF -DHULLCOVER_BUILD_BENCHMARKS=OFF >/dev/null
fi
cmake --build "$build" -j "$jobs"

step "install into $prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
config="$(find "$prefix" -name hullcoverConfig.cmake -print -quit)"
[ -n "$config" ] || fail "no hullcoverConfig.cmake under $prefix"
[ -f "$(dirname "$config")/hullcoverConfigVersion.cmake" ] || fail "no hullcoverConfigVersion.cmake beside $config"
[ -f "$prefix/include/hullcover/bvh/hull_world.h" ] || fail "public headers not installed"
# Exactly the expected headers (scripts/check_public_headers.py's list): no
# internal header (files, threads, kernels) reaches a user's include path.
expected="$(python3 - "$repo/scripts/check_public_headers.py" <<'PY'
import importlib.util, sys
spec = importlib.util.spec_from_file_location("check", sys.argv[1])
check = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check)
print("\n".join(sorted(check.EXPECTED)))
PY
)"
installed="$(cd "$prefix/include" && find hullcover -name '*.h' | LC_ALL=C sort)"
if [ "$installed" != "$(printf '%s\n' "$expected" | LC_ALL=C sort)" ]; then
  diff <(printf '%s\n' "$expected" | LC_ALL=C sort) <(printf '%s\n' "$installed") >&2 || true
  fail "the installed headers differ from the expected list (above: < expected, > installed)"
fi
printf 'installed headers: %d, the expected list\n' "$(printf '%s\n' "$installed" | wc -l)"
[ -x "$prefix/bin/hullcover" ] || fail "the hullcover tool not installed"
[ -z "$(find "$prefix/include" -path '*/src/*')" ] || fail "private sources installed"

step "build the example server against $prefix only"
consumer="$work/example_server"
cp -R "$repo/apps/example_server" "$consumer"
cmake -S "$consumer" -B "$work/example_server-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF >/dev/null
found_dir="$(sed -n 's/^hullcover_DIR:PATH=//p' "$work/example_server-build/CMakeCache.txt")"
case "$found_dir" in
  "$prefix"/*) echo "found hullcover in $found_dir" ;;
  *) fail "the example server found hullcover in '$found_dir', not in $prefix" ;;
esac
cmake --build "$work/example_server-build" -j "$jobs"
# The compile and link lines must name the prefix, never the source or build tree.
if grep -rlF -e "$repo/" --include=flags.make --include=link.txt "$work/example_server-build"; then
  fail "the example server's build refers to the source tree $repo"
fi
server="$work/example_server-build/hullcover_example_server"
[ -x "$server" ] || fail "no example server binary"
"$server" --help >/dev/null || fail "example_server --help"
status=0
"$server" "$work/missing.hcw" 2>/dev/null || status=$?
[ "$status" -eq 2 ] || fail "example_server on a missing file exited $status, not 2"

if [ -f "$pandora" ]; then
  step "decompose sauerbraten-pandora (2-3 minutes)"
  "$prefix/bin/hullcover" decompose "$pandora" -o "$work/pandora-hulls.obj" --world "$work/pandora.hcw" -q
  world="$work/pandora.hcw"
  # Cube units: Sauerbraten's player (15 units tall) is about 1.8 m.
  scale=(--units-per-metre 8)
else
  echo "skipping pandora: ../shared not present ($pandora); running on the demo scene"
  step "decompose the demo scene"
  "$prefix/bin/hullcover" demo --out "$work/demo" >/dev/null
  "$prefix/bin/hullcover" decompose "$work/demo/demo-scene.obj" -o "$work/demo-hulls.obj" --world "$work/demo.hcw" -q
  world="$work/demo.hcw"
  scale=(--units-per-metre 1)  # the demo scene is in metres
fi

step "run the example server"
"$server" "$world" --threads 8 --sweeps 10000 "${scale[@]}" || fail "example server exited $?"

step "install check passed"
