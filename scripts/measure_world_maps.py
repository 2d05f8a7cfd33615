#!/usr/bin/env python3
"""Hull count of every map alone and inside a world of all of them.

Builds one copy of each scene alone and a world of one copy each (the
`hullcover world` command, so scaling and turns are the same), decomposes
each at the defaults, and counts the world's hulls per map (a hull belongs
to the map of its first face; the world holds the maps' faces in the order
given). Prints a table and exits 1 when a map's count in the world differs
from alone by more than --limit percent.

With --audit-alone-hulls, each map beyond the limit is put to the test the
other way: the world is audited with that map's hulls ALONE put in place
(turned and moved as `hullcover world` placed the map) beside the other
maps' world hulls. Lost space there shows the world's own free space (other
maps' rays) ruling those hulls out, not the decomposer's path.

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


def read_obj(path):
    """Vertices and, per `o` object (or the whole file), faces as 0-based
    vertex indices."""
    vertices, objects = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append(tuple(float(x) for x in line.split()[1:4]))
            elif line.startswith("o "):
                objects.append([])
            elif line.startswith("f "):
                if not objects:
                    objects.append([])
                objects[-1].append([int(x.split("/")[0]) - 1 for x in line.split()[1:]])
    return vertices, objects


# The turns `hullcover world` gives a copy: multiples of 90 degrees about y.
TURNS = [lambda p: (p[0], p[1], p[2]), lambda p: (p[2], p[1], -p[0]),
         lambda p: (-p[0], p[1], -p[2]), lambda p: (-p[2], p[1], p[0])]


def placement(alone_corners, world_corners):
    """The turn and shift taking a map's corners alone onto the world's."""
    for turn in TURNS:
        shifts = [tuple(w[k] - t[k] for k in range(3)) for t, w in
                  zip((turn(p) for p in alone_corners), world_corners)]
        if all(max(abs(s[k] - shifts[0][k]) for k in range(3)) <= 1e-6 * (1 + max(map(abs, shifts[0])))
               for s in shifts):
            return turn, shifts[0]
    raise SystemExit("cannot tell how the world placed a map (the script assumes `hullcover world`'s defaults: "
                     "one copy per map, turned about y)")


def audit_alone_hulls(a, m, starts, owners):
    """Audits the world with map m's hulls alone put in place of its world hulls."""
    def scene(name):
        vertices, objects = read_obj(os.path.join(a.out, name))
        return vertices, [face for faces in objects for face in faces]
    world_v, world_f = scene("world.obj")
    alone_v, alone_f = scene(f"alone-{m}.obj")
    # The map's first face in world.obj: the OBJ faces of the maps before it
    # (`starts` counts prepared faces, for the hulls' face indices).
    first = sum(len(scene(f"alone-{i}.obj")[1]) for i in range(m))
    sample = range(0, len(alone_f), max(1, len(alone_f) // 200))
    turn, shift = placement([alone_v[alone_f[k][c]] for k in sample for c in range(3)],
                            [world_v[world_f[first + k][c]] for k in sample for c in range(3)])
    path = os.path.join(a.out, f"world-with-alone-{m}.obj")
    with open(path, "w") as out:
        def write(vertices, faces, place):
            used = sorted({v for face in faces for v in face})
            local = {v: i for i, v in enumerate(used)}
            out.write(f"o hull_{write.count}\n")
            write.count += 1
            for v in used:
                out.write("v %.17g %.17g %.17g\n" % place(vertices[v]))
            for face in faces:
                out.write("f " + " ".join(str(write.base + local[v] + 1) for v in face) + "\n")
            write.base += len(used)
        write.count, write.base = 0, 0
        hull_v, hulls = read_obj(os.path.join(a.out, "world-hulls.obj"))
        for faces, owner in zip(hulls, owners):
            if owner != m:
                write(hull_v, faces, lambda p: p)
        hull_v, hulls = read_obj(os.path.join(a.out, f"alone-{m}-hulls.obj"))
        for faces in hulls:
            write(hull_v, faces, lambda p: tuple(q + d for q, d in zip(turn(p), shift)))
    result = subprocess.run([a.hullcover, "audit", os.path.join(a.out, "world.obj"), path], capture_output=True,
                            text=True)
    print(f"\nmap {m} ({os.path.basename(a.scenes[m])}), its hulls alone in the world:")
    # The audit exits 0 when clean, 1 on violations; anything else is a failed run.
    if result.returncode not in (0, 1):
        raise SystemExit(f"audit failed ({result.returncode}): {result.stderr.strip()}")
    print("\n".join(result.stdout.splitlines()[:6]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenes", nargs="+", help="scene files (SCENE@N scales as `hullcover world` does)")
    parser.add_argument("--hullcover", required=True, help="the hullcover executable")
    parser.add_argument("--out", required=True, help="folder for the worlds, hulls and JSON")
    parser.add_argument("--limit", type=float, default=1.0, help="largest difference allowed, percent (1)")
    parser.add_argument("--audit-alone-hulls", action="store_true",
                        help="audit the world with each map beyond the limit given its hulls alone")
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
    owners = []
    for hull in r["hulls"]:
        first = min(hull["faces"])
        owners.append(max(i for i in range(len(alone)) if starts[i] <= first))
        in_world[owners[-1]] += 1
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
    if a.audit_alone_hulls:
        for m, ((_, hulls, _), there) in enumerate(zip(alone, in_world)):
            if abs(100.0 * (there - hulls) / hulls) > a.limit:
                audit_alone_hulls(a, m, starts, owners)
    return 0 if worst <= a.limit else 1


if __name__ == "__main__":
    sys.exit(main())
