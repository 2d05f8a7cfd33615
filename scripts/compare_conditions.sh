#!/usr/bin/env bash
# Paper vs exact conditions on the shared scenes, one Markdown table row per
# scene and mode: hulls, hulls per face, decomposition seconds, and the
# strict audit's lost front and opening rays (of those traced), the octree
# cells holding a lost ray's deepest point, and its verdict (CLEAN also means
# full coverage and no missed contact). scripts/regenerate_results.py
# --tables paper-vs-exact writes the same comparison into
# docs/results/covering.md; this script prints it for any scenes.
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
echo "| scene | mode | hulls | hulls/face | seconds | front rays lost | opening rays lost | lost cells | audit |"
echo "|---|---|--:|--:|--:|--:|--:|--:|---|"
for scene in "${names[@]}"; do
  for mode in paper exact; do
    line=$("$bin" decompose "$scenes/$scene" -q --threads 2 --conditions "$mode" -o "$out/h.obj" --world "$out/h.hcw")
    line=$(head -1 <<<"$line")
    hulls=$(sed -E 's/.* -> ([0-9]+) hulls.*/\1/' <<<"$line")
    per_face=$(sed -E 's/.* ([0-9.]+) hulls\/face.*/\1/' <<<"$line")
    seconds=$(sed -E 's/.*hulls\/face\), ([0-9.]+) s.*/\1/' <<<"$line")
    audit=$("$bin" audit "$scenes/$scene" "$out/h.hcw" -q --threads 2 || true)
    # "front free space: 2538 of 245555 rays lost (1.034%), ..." and "openings:  9 of 2463 rays lost (0.365%), ..."
    front=$(grep "front free space:" <<<"$audit" | sed -E 's/.*: +([0-9]+) of ([0-9]+) rays lost \(([0-9.]+%)\).*/\1 of \2 (\3)/')
    openings=$(grep "openings:" <<<"$audit" | sed -E 's/.*: +([0-9]+) of ([0-9]+) rays lost \(([0-9.]+%)\).*/\1 of \2 (\3)/')
    [ "$openings" != "0 of 0 (0.000%)" ] || openings="(no open edge)"
    cells=$(grep "lost cells:" <<<"$audit" | sed -E 's/.*: +([0-9]+) octree cells.*/\1/')
    verdict=$(head -1 <<<"$audit" | sed -E 's/^.*: (CLEAN|VIOLATIONS):.*/\1/')
    echo "| $scene | $mode | $hulls | $per_face | $seconds | $front | $openings | $cells | $verdict |"
  done
done
