#!/usr/bin/env bash
# Paper vs exact conditions on the shared scenes, one Markdown table row per
# scene and mode: hulls, hulls per face, decomposition seconds, and the
# audit's lost front / opening points, lost free volume (default probe) and
# its verdict (CLEAN also means full coverage and no missed contact).
#   scripts/compare_conditions.sh [SCENES_DIR [SCENE...]]
# (default ../shared/data/scenes, all eight shared scenes)
# Needs a Release build (scripts/demo.sh or scripts/test.sh makes one).
set -euo pipefail
cd "$(dirname "$0")/.."
scenes="${1:-../shared/data/scenes}"
shift || true
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(threejs-collision-world.glb recast-nav_test.obj recast-dungeon.obj recast-undulating.obj
                                 sauerbraten-fdm6.obj sauerbraten-pandora.obj stanford-bunny-res2.ply
                                 thor-art56-gearplate.stl)
bin=build/release/apps/hullcover
[ -x "$bin" ] || { echo "build first: scripts/test.sh" >&2; exit 2; }
[ -d "$scenes" ] || { echo "no shared scenes at $scenes" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| scene | mode | hulls | hulls/face | seconds | front lost | openings lost | free volume lost | audit |"
echo "|---|---|---|---|---|---|---|---|---|"
for scene in "${names[@]}"; do
  for mode in paper exact; do
    line=$("$bin" decompose "$scenes/$scene" -q --conditions "$mode" -o "$out/h.obj" --world "$out/h.hcw" | head -1)
    hulls=$(sed -E 's/.* -> ([0-9]+) hulls.*/\1/' <<<"$line")
    per_face=$(sed -E 's/.* ([0-9.]+) hulls\/face.*/\1/' <<<"$line")
    seconds=$(sed -E 's/.*hulls\/face\), ([0-9.]+) s.*/\1/' <<<"$line")
    audit=$("$bin" audit "$scenes/$scene" "$out/h.hcw" --proxies 100 || true)
    front=$(grep "front free space" <<<"$audit" | sed -E 's/.*: +([0-9]+) of ([0-9]+) points lost \(([0-9.]+%)\).*/\1 (\3)/')
    openings=$(grep "openings:" <<<"$audit" | sed -E 's/.*: +([0-9]+) of ([0-9]+) points lost \(([0-9.]+%)\).*/\1 (\3)/')
    volume=$(grep "free volume" <<<"$audit" | sed -E 's/.*\(([0-9.]+%)\).*/\1/')
    verdict=$(head -1 <<<"$audit" | sed -E 's/^[^:]*: ([A-Z]+).*/\1/')
    echo "| $scene | $mode | $hulls | $per_face | $seconds | $front | $openings | $volume | $verdict |"
  done
done
