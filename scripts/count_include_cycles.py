#!/usr/bin/env python3
"""Counts include cycles between units of the libraries (lib, bvh, validate).

A unit is a source file and its header taken together: lib/covering's
src/validity/scene_index.cpp and src/validity/scene_index.h (or a header
of the same name in include/hullcover/covering/ or internal/hullcover/
covering/) are one unit. Unit A depends on unit B when any file of A
includes a header of B. Every strongly connected group of more than one
unit is a cycle: the script prints each, with the includes that close it,
and exits 1 when there is any (0 when none).

Usage: scripts/count_include_cycles.py [REPOSITORY_ROOT]
       scripts/count_include_cycles.py --self-test  (a made-up tree with a
       known cycle must be found, one without must not)
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
ROOTS = ("lib", "bvh", "validate")


def module_of(path):
    """The module folder holding `path`: the one with include/ or src/ under it."""
    parts = path.split(os.sep)
    for i, part in enumerate(parts):
        if part in ("include", "internal", "src"):
            return os.sep.join(parts[:i])
    return os.path.dirname(path)


def collect(root):
    files = []
    for top in ROOTS:
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in names:
                if name.endswith((".h", ".hpp", ".cpp")):
                    files.append(os.path.relpath(os.path.join(folder, name), root))
    return sorted(files)


def self_test():
    import tempfile

    def tree(files):
        root = tempfile.mkdtemp()
        for path, text in files.items():
            full = os.path.join(root, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w", encoding="utf-8") as out:
                out.write(text)
        return root

    # a.cpp includes b.h, b.cpp includes the public a.h: units a and b form a cycle.
    cyclic = tree({"lib/m/include/hullcover/m/a.h": "", "lib/m/src/a.cpp": '#include "b.h"\n',
                   "lib/m/src/b.h": "", "lib/m/src/b.cpp": '#include "hullcover/m/a.h"\n'})
    acyclic = tree({"lib/m/include/hullcover/m/a.h": "", "lib/m/src/a.cpp": '#include "sub/b.h"\n',
                    "lib/m/src/sub/b.h": "", "lib/m/src/sub/b.cpp": "#include <vector>\n"})
    found = count(cyclic, quiet=True), count(acyclic, quiet=True)
    print(f"self-test: {found[0]} cycle(s) in the cyclic tree, {found[1]} in the acyclic one")
    return 0 if found == (1, 0) else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    groups = count(root, quiet=False)
    return 1 if groups else 0


def count(root, quiet):
    """The number of cycles under `root`; each printed unless `quiet`."""
    files = collect(root)
    unit_of = {f: (module_of(f), os.path.splitext(os.path.basename(f))[0]) for f in files}
    # Public headers by their include path; private headers by module and name.
    public = {}
    private = {}
    for f in files:
        if not f.endswith((".h", ".hpp")):
            continue
        for folder in ("include", "internal"):
            marker = os.sep + folder + os.sep
            if marker in f:
                public[f.split(marker, 1)[1].replace(os.sep, "/")] = unit_of[f]
                break
        else:
            private[(module_of(f), os.path.basename(f))] = unit_of[f]
    edges = {}
    why = {}
    for f in files:
        with open(os.path.join(root, f), encoding="utf-8", errors="replace") as text:
            body = text.read()
        for target in INCLUDE.findall(body):
            unit = public.get(target) or private.get((module_of(f), os.path.basename(target)))
            if unit is None or unit == unit_of[f]:
                continue
            edges.setdefault(unit_of[f], set()).add(unit)
            why.setdefault((unit_of[f], unit), f + ' includes "' + target + '"')
    units = sorted(set(unit_of.values()))
    # Tarjan's strongly connected components, iteratively.
    index, low, on_stack, stack, groups = {}, {}, set(), [], []
    counter = [0]
    for start in units:
        if start in index:
            continue
        work = [(start, iter(sorted(edges.get(start, ()))))]
        index[start] = low[start] = counter[0]
        counter[0] += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            advanced = False
            for child in children:
                if child not in index:
                    index[child] = low[child] = counter[0]
                    counter[0] += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(edges.get(child, ())))))
                    advanced = True
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                if len(group) > 1:
                    groups.append(sorted(group))
    if quiet:
        return len(groups)
    for group in groups:
        print("cycle: " + ", ".join(m + "/" + n for m, n in group))
        members = set(group)
        for a in group:
            for b in sorted(edges.get(a, ())):
                if b in members:
                    print("  " + why[(a, b)])
    print(f"{len(units)} units, {sum(len(v) for v in edges.values())} dependencies, {len(groups)} cycles")
    return len(groups)


if __name__ == "__main__":
    sys.exit(main())
