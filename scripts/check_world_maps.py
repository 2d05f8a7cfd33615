#!/usr/bin/env python3
"""A world of maps laid close together, checked as a whole and map by map.

Lays the maps (OBJ files) on a grid, COLUMNS to a row, GAP scene units
apart (each map moved, never turned, its lowest corner at its grid place;
rows along x, then z), decomposes the world at the defaults, audits it, and
then moves each map's hulls from the world back to the map's own frame and
audits them against the map alone. A hull belongs to the map of its first
face. Prints a table and exits 1 when any audit is not clean.

This is the check of docs/worlds.md ("each map's hulls from a world are
valid for the map alone"); docs/results/worlds.md gives its figures.

    scripts/check_world_maps.py --hullcover build/release/apps/hullcover \\
        --out /tmp/w --columns 7 --gap 64 maps/*.obj
"""
import argparse
import json
import os
import subprocess
import sys
import time


def read_obj(path):
    """Vertices and triangles (fans of the polygons, 0-based) of an OBJ."""
    vertices, triangles = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                ids = [int(x.split("/")[0]) for x in line.split()[1:]]
                ids = [i - 1 if i > 0 else len(vertices) + i for i in ids]
                triangles += [(ids[0], ids[k], ids[k + 1]) for k in range(1, len(ids) - 1)]
    return vertices, triangles


def box_of(vertices, triangles):
    used = {i for t in triangles for i in t}
    return ([min(vertices[i][k] for i in used) for k in range(3)],
            [max(vertices[i][k] for i in used) for k in range(3)])


def lay_out(maps, columns, gap, world_path):
    """Writes the world OBJ; returns each map's offset and face range."""
    placed, x, z, row_depth, face0 = [], 0.0, 0.0, 0.0, 0
    with open(world_path, "w") as out:
        base = 0
        for i, path in enumerate(maps):
            vertices, triangles = read_obj(path)
            low, high = box_of(vertices, triangles)
            if i and i % columns == 0:
                x, z, row_depth = 0.0, z + row_depth + gap, 0.0
            offset = [x - low[0], -low[1], z - low[2]]
            for v in vertices:
                out.write("v %.17g %.17g %.17g\n" % tuple(v[k] + offset[k] for k in range(3)))
            for t in triangles:
                out.write("f %d %d %d\n" % tuple(base + i + 1 for i in t))
            placed.append({"map": path, "offset": offset, "faces": [face0, face0 + len(triangles)]})
            base += len(vertices)
            face0 += len(triangles)
            x += high[0] - low[0] + gap
            row_depth = max(row_depth, high[2] - low[2])
    return placed


def read_hull_groups(path):
    """Each `o` group of a hull OBJ: its vertices and its faces (1-based,
    counted in the file)."""
    groups, count = [], 0
    with open(path) as f:
        for line in f:
            if line.startswith("o "):
                groups.append({"first": count + 1, "vertices": [], "faces": []})
            elif line.startswith("v "):
                groups[-1]["vertices"].append([float(x) for x in line.split()[1:4]])
                count += 1
            elif line.startswith("f "):
                groups[-1]["faces"].append([int(x) for x in line.split()[1:]])
    return groups


def write_moved_back(groups, offset, path):
    with open(path, "w") as out:
        written = 0
        for k, g in enumerate(groups):
            out.write("o hull_%d\n" % k)
            for v in g["vertices"]:
                out.write("v %.17g %.17g %.17g\n" % tuple(v[a] - offset[a] for a in range(3)))
            for face in g["faces"]:
                out.write("f " + " ".join(str(i - g["first"] + 1 + written) for i in face) + "\n")
            written += len(g["vertices"])


def run(cmd, log):
    start = time.monotonic()
    with open(log, "w") as f:
        code = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT).returncode
    return code, time.monotonic() - start


def verdict(log):
    """The audit's verdict, from the first line of its report."""
    with open(log) as f:
        parts = f.readline().split(": ")
    return parts[1] if len(parts) > 2 else "no verdict (see %s)" % log


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("maps", nargs="+", help="OBJ files, one map each")
    parser.add_argument("--hullcover", required=True, help="the hullcover executable")
    parser.add_argument("--out", required=True, help="a directory for the world, its hulls and the audits")
    parser.add_argument("--columns", type=int, default=7, help="maps to a row")
    parser.add_argument("--gap", type=float, default=64.0, help="scene units between neighbouring maps' boxes")
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    if args.columns < 1 or not args.gap >= 0.0:
        parser.error("--columns must be at least 1 and --gap a length >= 0")
    os.makedirs(args.out, exist_ok=True)
    world = os.path.join(args.out, "world.obj")
    placed = lay_out(args.maps, args.columns, args.gap, world)
    hulls, sidecar = os.path.join(args.out, "hulls.obj"), os.path.join(args.out, "hulls.json")
    code, seconds = run([args.hullcover, "decompose", world, "-o", hulls, "--json", sidecar, "-q",
                         "--threads", str(args.threads)], os.path.join(args.out, "decompose.txt"))
    if code != 0:
        sys.exit("decompose failed: see " + os.path.join(args.out, "decompose.txt"))
    with open(sidecar) as f:
        first_faces = [h["faces"][0] for h in json.load(f)["hulls"]]
    print("world: %d maps, %d triangles, %d hulls, decompose %.1f s" %
          (len(placed), placed[-1]["faces"][1], len(first_faces), seconds))
    failed = 0
    code, seconds = run([args.hullcover, "audit", world, hulls, "--threads", str(args.threads)],
                        os.path.join(args.out, "audit-world.txt"))
    failed += code != 0
    print("world audit: %s (%.1f s)" % (verdict(os.path.join(args.out, "audit-world.txt")), seconds))
    groups = read_hull_groups(hulls)
    if len(groups) != len(first_faces):
        sys.exit("the hull OBJ and its sidecar disagree")
    print("%-20s %8s %8s  %s" % ("map", "faces", "hulls", "its world hulls audited alone"))
    for p in placed:
        name = os.path.splitext(os.path.basename(p["map"]))[0]
        low, high = p["faces"]
        own = [g for g, f in zip(groups, first_faces) if low <= f < high]
        moved = os.path.join(args.out, name + ".hulls.obj")
        write_moved_back(own, p["offset"], moved)
        log = os.path.join(args.out, name + ".audit.txt")
        code, _ = run([args.hullcover, "audit", p["map"], moved, "--threads", str(args.threads)], log)
        failed += code != 0
        print("%-20s %8d %8d  %s" % (name, high - low, len(own), verdict(log)), flush=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
