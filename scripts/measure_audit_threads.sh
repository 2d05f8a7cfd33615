#!/usr/bin/env bash
# `hullcover audit --threads 1` against `--threads 2` on shared scenes: the
# wall time of each (rounds alternate the two, so load from other work falls
# on both), their ratio, and whether what is printed and the JSON written are
# the same bytes (the audit's JSON has no timing field to leave out).
#
#   scripts/measure_audit_threads.sh [OUT_DIR] [SCENE...]
#
# Scenes default to recast-dungeon and sauerbraten-pandora from
# ../shared/data/scenes; each is decomposed first (kept in OUT_DIR, default
# out/audit-threads, and reused). ROUNDS (default 2) rounds per scene.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
hullcover=${HULLCOVER:-$root/build/release/apps/hullcover}
out=${1:-$root/out/audit-threads}
shift || true
scenes_dir=${SCENES_DIR:-$root/../shared/data/scenes}
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=("$scenes_dir/recast-dungeon.obj" "$scenes_dir/sauerbraten-pandora.obj")
rounds=${ROUNDS:-2}
mkdir -p "$out"

seconds() { date +%s.%N; }
least() { awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }'; }

printf '%-22s %8s %8s %8s  %s\n' scene "1 thr s" "2 thr s" ratio "same output"
for scene in "${scenes[@]}"; do
  name=$(basename "${scene%.*}")
  hulls=$out/$name-hulls.obj
  [ -s "$hulls" ] || "$hullcover" decompose "$scene" -o "$hulls" -q > /dev/null
  best1=; best2=; same=yes
  for round in $(seq "$rounds"); do
    for threads in 1 2; do
      start=$(seconds)
      status=0
      "$hullcover" audit "$scene" "$hulls" -q --threads "$threads" --json "$out/$name-t$threads.json" \
        > "$out/$name-t$threads.txt" || status=$?
      [ "$status" -le 1 ] || { echo "audit failed on $scene ($status)" >&2; exit 2; }
      took=$(awk -v a="$start" -v b="$(seconds)" 'BEGIN { printf "%.2f", b - a }')
      # The faster round of each: the one least slowed by other work.
      if [ "$threads" = 1 ]; then best1=$(least "$best1" "$took"); else best2=$(least "$best2" "$took"); fi
      echo "  $name round $round, $threads thread(s): $took s (exit $status)" >&2
    done
    cmp -s "$out/$name-t1.json" "$out/$name-t2.json" || same=no
    cmp -s "$out/$name-t1.txt" "$out/$name-t2.txt" || same=no
  done
  printf '%-22s %8.2f %8.2f %8.2f  %s\n' "$name" "$best1" "$best2" "$(awk -v a="$best1" -v b="$best2" 'BEGIN { print a / b }')" "$same"
done
