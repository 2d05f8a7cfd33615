#!/usr/bin/env python3
"""Move one wall of an OBJ scene: the edit the re-bake measurement makes.

    scripts/move_wall.py IN.obj OUT.obj [--by 0.25] [--up y] [--rank 0] [--near X,Y,Z]

The wall is the largest vertical face's plane region: every vertical face in
that plane (within 1e-6 of the scene's size) reachable from it through
shared vertices. Its vertices move along the wall's normal by --by scene
units; faces sharing those vertices stretch with them. --rank k takes the
k-th largest vertical face instead; --near picks the largest vertical face
whose centroid lies within 10 units of a point. Only 'v' lines change:
every other line (faces, materials, groups) is copied as it is, so every
cell the wall does not touch keeps its faces.
"""

import argparse
import math
import sys


def read_obj(path):
    positions, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                positions.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                faces.append([int(x.split("/")[0]) - 1 for x in line.split()[1:4]])
    return positions, faces


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("input")
    p.add_argument("output")
    p.add_argument("--by", type=float, default=0.25, help="How far the wall moves, scene units")
    p.add_argument("--up", choices="xyz", default="y")
    p.add_argument("--rank", type=int, default=0)
    p.add_argument("--near", help="X,Y,Z: take the largest wall face within 10 units of this point")
    p.add_argument("--interior", type=float, default=50.0,
                   help="Take only walls with scene on both sides within this distance, farther than --by "
                        "(an inner wall: moving it leaves the scene's outline, so its islands and cells, alone)")
    args = p.parse_args()
    positions, faces = read_obj(args.input)
    up = [0.0, 0.0, 0.0]
    up["xyz".index(args.up)] = 1.0
    size = max(max(abs(c) for c in v) for v in positions)
    near = [float(x) for x in args.near.split(",")] if args.near else None
    normals, areas = [], []
    for a, b, c in faces:
        n = cross(sub(positions[b], positions[a]), sub(positions[c], positions[a]))
        length = math.sqrt(dot(n, n))
        normals.append([x / length for x in n] if length > 0 else [0.0, 0.0, 0.0])
        areas.append(0.5 * length)
    vertical = [f for f in range(len(faces)) if areas[f] > 0 and abs(dot(normals[f], up)) < 1e-6]
    if near:
        def centre(f):
            return [sum(positions[v][i] for v in faces[f]) / 3 for i in range(3)]
        vertical = [f for f in vertical if math.dist(centre(f), near) < 10.0]
    if args.interior > 0:
        def inner(f):
            n, c = normals[f], positions[faces[f][0]]
            level = dot(n, c)
            reach = args.interior
            near_levels = [dot(n, v) for v in positions
                           if all(abs(v[i] - c[i]) < reach for i in range(3))]
            return min(near_levels) < level - 2 * abs(args.by) and max(near_levels) > level + 2 * abs(args.by)
        vertical = sorted(vertical, key=lambda f: -areas[f])[:200]
        vertical = [f for f in vertical if inner(f)]
    if len(vertical) <= args.rank:
        sys.exit("move_wall.py: no such vertical face")
    seed = sorted(vertical, key=lambda f: -areas[f])[args.rank]
    normal = normals[seed]
    offset = dot(normal, positions[faces[seed][0]])
    in_plane = {f for f in vertical
                if abs(abs(dot(normals[f], normal)) - 1) < 1e-9
                and all(abs(dot(normal, positions[v]) - offset) <= 1e-6 * size for v in faces[f])}
    faces_of_vertex = {}
    for f in in_plane:
        for v in faces[f]:
            faces_of_vertex.setdefault(v, []).append(f)
    wall, todo = {seed}, [seed]
    while todo:
        f = todo.pop()
        for v in faces[f]:
            for g in faces_of_vertex[v]:
                if g not in wall:
                    wall.add(g)
                    todo.append(g)
    moved = {v for f in wall for v in faces[f]}
    for v in moved:
        positions[v] = [positions[v][i] + args.by * normal[i] for i in range(3)]
    with open(args.input) as source, open(args.output, "w") as out:
        out.write(f"# {args.input} with one wall ({len(wall)} faces, {len(moved)} vertices) moved by "
                  f"{args.by} along {normal}\n")
        index = 0
        for line in source:
            if line.startswith("v "):
                if index in moved:
                    line = "v %.17g %.17g %.17g\n" % tuple(positions[index])
                index += 1
            out.write(line)
    centre = [sum(positions[v][i] for v in moved) / len(moved) for i in range(3)]
    print(f"moved a wall of {len(wall)} faces ({sum(areas[f] for f in wall):.3g} square units) by {args.by}, "
          f"centred at {centre[0]:.2f},{centre[1]:.2f},{centre[2]:.2f}")


if __name__ == "__main__":
    main()
