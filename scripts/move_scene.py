#!/usr/bin/env python3
"""Writes an OBJ scene turned about an axis through the origin and then moved,
every coordinate with 17 significant digits (what a double holds), so a
reader in double sees the moved scene exactly as computed.

Only `v` lines change; every other line is copied. For a scene in another
format, write it as OBJ first (`hullcover world SCENE -o S.obj` writes one
copy of it, unturned, at the origin).

usage: scripts/move_scene.py IN.obj OUT.obj --move DX DY DZ [--turn RADIANS] [--up x|y|z]
"""
import argparse
import math
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("source")
    parser.add_argument("target")
    parser.add_argument("--move", nargs=3, type=float, default=[0.0, 0.0, 0.0], metavar=("DX", "DY", "DZ"))
    parser.add_argument("--turn", type=float, default=0.0, help="radians about the up axis, before the move")
    parser.add_argument("--up", choices="xyz", default="y")
    args = parser.parse_args()
    up = "xyz".index(args.up)
    a, b = [k for k in range(3) if k != up]
    c, s = math.cos(args.turn), math.sin(args.turn)
    with open(args.source, encoding="utf-8", errors="replace") as src, open(args.target, "w", encoding="utf-8") as out:
        for number, line in enumerate(src, 1):
            words = line.split()
            if not words or words[0] != "v":
                out.write(line)
                continue
            try:
                p = [float(w) for w in words[1:4]]
            except (ValueError, IndexError):
                sys.exit(f"move_scene: {args.source}:{number}: a position needs three numbers")
            # A right-handed turn about `up` (a -> b).
            q = list(p)
            q[a] = c * p[a] - s * p[b]
            q[b] = s * p[a] + c * p[b]
            q = [q[k] + args.move[k] for k in range(3)]
            out.write("v " + " ".join(repr(x) if abs(x) < 1e16 else "%.17g" % x for x in q) + "\n")


if __name__ == "__main__":
    main()
