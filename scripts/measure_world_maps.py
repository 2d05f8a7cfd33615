#!/usr/bin/env python3
"""Hull count of every map alone and inside a world of all of them.

Builds one copy of each scene alone and a world of one copy each (the
`hullcover world` command, so scaling and turns are the same), decomposes
each at the defaults, and counts the world's hulls per map (a hull belongs
to the map of its first face; the world holds the maps' faces in the order
given). Prints a table and exits 1 when a map's count in the world differs
from alone by more than --limit percent.

    scripts/measure_world_maps.py --hullcover build/release/apps/hullcover \\
        --out /tmp/w S/recast-dungeon.obj S/sauerbraten-pandora.obj@20 ...
"""
import argparse
import json
import os
import subprocess
import sys
import time


def run(cmd):
    start = time.monotonic()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return time.monotonic() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenes", nargs="+", help="scene files (SCENE@N scales as `hullcover world` does)")
    parser.add_argument("--hullcover", required=True, help="the hullcover executable")
    parser.add_argument("--out", required=True, help="folder for the worlds, hulls and JSON")
    parser.add_argument("--limit", type=float, default=1.0, help="largest difference allowed, percent (1)")
    a = parser.parse_args()
    os.makedirs(a.out, exist_ok=True)
    alone = []
    for i, scene in enumerate(a.scenes):
        world = os.path.join(a.out, f"alone-{i}.obj")
        run([a.hullcover, "world", scene, "-o", world])
        report = os.path.join(a.out, f"alone-{i}.json")
        seconds = run([a.hullcover, "decompose", world, "-o", os.path.join(a.out, f"alone-{i}-hulls.obj"),
                       "--json", report])
        with open(report) as f:
            r = json.load(f)
        alone.append((r["totals"]["faces"], len(r["hulls"]), seconds))
    world = os.path.join(a.out, "world.obj")
    run([a.hullcover, "world", *a.scenes, "-o", world])
    report = os.path.join(a.out, "world.json")
    seconds = run([a.hullcover, "decompose", world, "-o", os.path.join(a.out, "world-hulls.obj"), "--json", report])
    with open(report) as f:
        r = json.load(f)
    starts = [0]
    for faces, _, _ in alone:
        starts.append(starts[-1] + faces)
    in_world = [0] * len(alone)
    for hull in r["hulls"]:
        first = min(hull["faces"])
        in_world[max(i for i in range(len(alone)) if starts[i] <= first)] += 1
    worst = 0.0
    print(f"| map | faces | hulls alone | hulls in the world | difference | seconds alone |")
    print(f"|---|--:|--:|--:|--:|--:|")
    for scene, (faces, hulls, secs), there in zip(a.scenes, alone, in_world):
        diff = 100.0 * (there - hulls) / hulls
        worst = max(worst, abs(diff))
        print(f"| {os.path.basename(scene)} | {faces:,} | {hulls:,} | {there:,} | {diff:+.2f}% | {secs:.1f} |")
    total_alone = sum(h for _, h, _ in alone)
    print(f"| all | {starts[-1]:,} | {total_alone:,} | {len(r['hulls']):,} | "
          f"{100.0 * (len(r['hulls']) - total_alone) / total_alone:+.2f}% | {sum(s for _, _, s in alone):.1f} "
          f"(world: {seconds:.1f}) |")
    return 0 if worst <= a.limit else 1


if __name__ == "__main__":
    sys.exit(main())
