#!/usr/bin/env python3
"""Regenerate the results tables that are cheap to measure, in place.

For each shared scene (../shared/data/scenes beside the clone, or --shared
DIR) it runs, with the Release build's command line:

    hullcover decompose SCENE -o OUT/STEM.obj --world OUT/STEM.hcw -q --threads N
    hullcover audit SCENE OUT/STEM.hcw -q --threads N

and writes what they print into the tables between the marker comments

    <!-- results:NAME begin -->
    ...
    <!-- results:NAME end -->

of every page that holds them:

    covering-defaults  docs/results/covering.md, README.md
                       scene, triangles, hulls, hulls/face, islands / cells,
                       seconds, audit verdict
    audit-defaults     docs/results/audit.md
                       scene, hulls, front and opening rays lost, verdict

The other tables (the Jolt harness, which needs its own build of Jolt;
`hullcover bench`; the worlds and Red Eclipse maps, minutes to hours) are
left alone: the script prints the commands that measure them.

    scripts/regenerate_results.py [--shared DIR] [--hullcover BIN] [--threads N]
                                  [--out DIR] [--scenes STEM...] [--dry-run]
    scripts/regenerate_results.py --from-logs DIR [--dry-run]

--dry-run prints the commands it would run and the tables it would write,
and runs and writes nothing. --from-logs DIR runs nothing either: it reads
DIR/STEM.log, the standard output of the decompose command above, for each
scene, and takes the audit columns from the pages as they stand (warning
where the page's audited hull count differs from the log's). A scene whose
file or log is missing keeps its row as it stands. Standard library only.
"""

import argparse
import os
import re
import shlex
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The shared scenes, in the order of the tables.
SCENES = [
    "threejs-collision-world.glb",
    "recast-nav_test.obj",
    "recast-dungeon.obj",
    "recast-undulating.obj",
    "sauerbraten-fdm6.obj",
    "sauerbraten-pandora.obj",
    "stanford-bunny-res2.ply",
    "thor-art56-gearplate.stl",
]

# Which marked tables live in which files (paths relative to the repository).
TABLE_FILES = {
    "covering-defaults": ["docs/results/covering.md", "README.md"],
    "audit-defaults": ["docs/results/audit.md"],
}

COVERING_HEADER = ("| scene | triangles | hulls | hulls/face | islands / cells | seconds | audit |\n"
                   "|---|--:|--:|--:|--:|--:|---|\n")
AUDIT_HEADER = ("| scene | hulls | front rays lost | opening rays lost | audit |\n"
                "|---|--:|--:|--:|---|\n")

NOT_RECORDED = "not recorded"

# Tables this script does not re-run, with the commands that measure them.
EXTERNAL = [
    ("docs/results/runtime.md", "Against Jolt Physics (needs the harness's own build of Jolt 5.5.1)", [
        "# build Jolt and the harness as ../shared/bench/jolt-anchor/README.md says, then per scene:",
        "hullcover decompose <scene> -o <stem>.hullcover.obj --world <stem>.hcw",
        "cd ../shared/bench/jolt-anchor && $HARNESS_BUILD/jolt_anchor -n 4000 -r 5 -H $HULLS -o out.md",
    ]),
    ("docs/results/runtime.md", "Hulls against the FCL triangle world; contact normals; batches on threads", [
        "build/release/tests/hullcover_bench_queries",
        "build/release/tests/hullcover_bench_queries --benchmark_filter='threads/|batch_threads'",
    ]),
    ("docs/results/agents.md", "Speed against error (minutes)", [
        "hullcover bench ../shared/data/scenes/recast-nav_test.obj@1 "
        "../shared/data/scenes/threejs-collision-world.glb@1",
    ]),
    ("docs/results/covering.md", "Paper vs exact", [
        "scripts/compare_conditions.sh ../shared/data/scenes",
    ]),
    ("docs/results/audit.md", "V-HACD's hulls; audit threads", [
        "hullcover audit ../shared/data/scenes/SCENE ../shared/data/peer-hulls/STEM.vhacd.obj",
        "scripts/measure_audit_threads.sh",
    ]),
    ("docs/results/worlds.md", "Cost against size (the 12-round bake: minutes; its audit: minutes)", [
        "hullcover world S/recast-nav_test.obj S/threejs-collision-world.glb S/recast-undulating.obj "
        "S/recast-dungeon.obj S/sauerbraten-fdm6.obj@20 S/sauerbraten-pandora.obj@20 -o worldN.obj "
        "--triangles $((89324 * N))",
        "hullcover decompose worldN.obj -o HN.obj --json HN.json",
        "hullcover audit world12.obj H12.obj --threads 2",
    ]),
    ("docs/results/worlds.md", "A map in the world against the map alone", [
        "scripts/measure_world_maps.py --hullcover build/release/apps/hullcover --out DIR "
        "S/recast-nav_test.obj S/threejs-collision-world.glb S/recast-undulating.obj S/recast-dungeon.obj "
        "S/sauerbraten-fdm6.obj@20 S/sauerbraten-pandora.obj@20",
    ]),
    ("docs/results/worlds.md", "Re-bake after an edit", [
        "scripts/move_wall.py world.obj moved.obj --by 0.25",
        "hullcover decompose world.obj -o full.obj --cell-cache C",
        "hullcover decompose moved.obj -o re.obj --cell-cache C --json re.json",
        "hullcover decompose moved.obj -o full_moved.obj",
    ]),
    ("docs/results/worlds.md", "Maps never seen; a world of 48 maps (needs the Red Eclipse packages; hours)", [
        "scripts/export_redeclipse_maps.sh OUT MAP...",
        "scripts/check_world_maps.py --hullcover build/release/apps/hullcover --out W --columns 7 --gap 64 MAPS...",
    ]),
]

DECOMPOSE_LINE = re.compile(r"^(?P<path>.*): (?P<faces>\d+) faces -> (?P<hulls>\d+) hulls "
                            r"\((?P<fewer>[-\d.]+)% fewer, (?P<per_face>[\d.]+) hulls/face\), "
                            r"(?P<seconds>[\d.]+) s")
ISLANDS_LINE = re.compile(r"^\s+(?P<islands>\d+) islands?, (?P<cells>\d+) cells?, threads (?P<threads>\d+)")
VERDICT_LINE = re.compile(r": (CLEAN|VIOLATIONS)\b")
FRONT_LINE = re.compile(r"front free space:\s+(\d+) of (\d+) rays lost")
OPENING_LINE = re.compile(r"openings:\s+(\d+) of (\d+) rays lost")


def stem(scene):
    return os.path.splitext(scene)[0]


def grouped(number):
    return f"{int(number):,}"


def parse_decompose(text):
    """The figures of `hullcover decompose`'s standard output, or None."""
    figures = None
    for line in text.splitlines():
        m = DECOMPOSE_LINE.match(line)
        if m and figures is None:
            figures = {k: m.group(k) for k in ("faces", "hulls", "per_face", "seconds")}
            continue
        m = ISLANDS_LINE.match(line)
        if m and figures is not None:
            figures["islands"], figures["cells"] = m.group("islands"), m.group("cells")
    return figures


def parse_audit(text, status):
    """The verdict and ray counts of `hullcover audit`'s standard output."""
    result = {"verdict": NOT_RECORDED, "front": NOT_RECORDED, "opening": NOT_RECORDED}
    if status == 2:
        result["verdict"] = "error (exit 2)"
        return result
    for line in text.splitlines():
        m = VERDICT_LINE.search(line)
        if m and result["verdict"] == NOT_RECORDED:
            result["verdict"] = m.group(1)
        m = FRONT_LINE.search(line)
        if m:
            result["front"] = f"{grouped(m.group(1))} of {grouped(m.group(2))}"
        m = OPENING_LINE.search(line)
        if m:
            lost, rays = m.group(1), m.group(2)
            result["opening"] = "(no open edge)" if rays == "0" else f"{grouped(lost)} of {grouped(rays)}"
    return result


def marked_span(text, name, path):
    """(start, end) of the text between NAME's begin and end markers."""
    begin = f"<!-- results:{name} begin -->\n"
    end = f"<!-- results:{name} end -->"
    start = text.find(begin)
    if start < 0 or text.find(begin, start + 1) >= 0:
        raise SystemExit(f"{path}: needs exactly one '{begin.strip()}'")
    start += len(begin)
    stop = text.find(end, start)
    if stop < 0:
        raise SystemExit(f"{path}: '{begin.strip()}' has no '{end}' after it")
    return start, stop


def read_rows(path, name):
    """The rows of a marked table as it stands: {scene: [cells]}."""
    with open(os.path.join(ROOT, path), encoding="utf-8") as f:
        text = f.read()
    start, stop = marked_span(text, name, path)
    rows = {}
    for line in text[start:stop].splitlines()[2:]:  # past the header and its rule
        if line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            rows[cells[0]] = cells
    return rows


def write_table(path, name, table, dry_run):
    full = os.path.join(ROOT, path)
    with open(full, encoding="utf-8") as f:
        text = f.read()
    start, stop = marked_span(text, name, path)
    if text[start:stop] == table:
        print(f"  {path}: {name} unchanged")
        return
    if dry_run:
        print(f"  {path}: {name} would change")
        return
    with open(full, "w", encoding="utf-8") as f:
        f.write(text[:start] + table + text[stop:])
    print(f"  {path}: {name} written")


def render(header, rows):
    return header + "".join("| " + " | ".join(cells) + " |\n" for cells in rows)


def build_tables(measured, audits):
    """Both tables from the figures measured; a scene not measured keeps its rows."""
    covering_old = read_rows(TABLE_FILES["covering-defaults"][0], "covering-defaults")
    audit_old = read_rows(TABLE_FILES["audit-defaults"][0], "audit-defaults")
    covering_rows, audit_rows = [], []
    for scene in SCENES:
        name = stem(scene)
        d = measured.get(name)
        if d is None:
            if name in covering_old:
                covering_rows.append(covering_old[name])
            if name in audit_old:
                audit_rows.append(audit_old[name])
            continue
        a = audits.get(name)
        if a is None:  # from logs: the audit columns as the pages hold them
            old = audit_old.get(name)
            if old is not None and old[1] != grouped(d["hulls"]):
                print(f"  warning: {name}: the page's audit is of {old[1]} hulls, the log has "
                      f"{grouped(d['hulls'])}; its verdict is kept as it stands", file=sys.stderr)
            verdict = old[4] if old else covering_old.get(name, [NOT_RECORDED] * 7)[6]
            a = {"verdict": verdict, "front": old[2] if old else NOT_RECORDED,
                 "opening": old[3] if old else NOT_RECORDED}
        cells = f"{d.get('islands', '?')} / {d.get('cells', '?')}"
        covering_rows.append([name, grouped(d["faces"]), grouped(d["hulls"]), d["per_face"], cells,
                              d["seconds"], a["verdict"]])
        audit_rows.append([name, grouped(d["hulls"]), a["front"], a["opening"], a["verdict"]])
    return {"covering-defaults": render(COVERING_HEADER, covering_rows),
            "audit-defaults": render(AUDIT_HEADER, audit_rows)}


def run(cmd, dry_run):
    print("  $ " + shlex.join(cmd))
    if dry_run:
        return None, None
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode not in (0, 1):
        sys.stderr.write(done.stderr)
    return done.stdout, done.returncode


def measure(args, scenes):
    measured, audits = {}, {}
    if not os.path.isdir(args.shared):
        print(f"no shared scenes at {args.shared} (give --shared DIR): the per-scene tables are left as "
              "they stand")
        return None
    if not args.dry_run and not os.access(args.hullcover, os.X_OK):
        raise SystemExit(f"no hullcover at {args.hullcover}: build first (scripts/test.sh), or give --hullcover")
    if not args.dry_run:
        os.makedirs(args.out, exist_ok=True)
    for scene in scenes:
        path = os.path.join(args.shared, scene)
        if not os.path.isfile(path):
            print(f"  {scene}: not in {args.shared}; its rows are left as they stand")
            continue
        name = stem(scene)
        obj, hcw = os.path.join(args.out, name + ".obj"), os.path.join(args.out, name + ".hcw")
        threads = ["--threads", str(args.threads)]
        text, status = run([args.hullcover, "decompose", path, "-o", obj, "--world", hcw, "-q"] + threads,
                           args.dry_run)
        figures = parse_decompose(text) if status == 0 else None
        if not args.dry_run and figures is None:
            print(f"  {scene}: decompose failed (exit {status}); its rows are left as they stand",
                  file=sys.stderr)
            continue
        audit_text, audit_status = run([args.hullcover, "audit", path, hcw, "-q"] + threads, args.dry_run)
        if args.dry_run:
            continue
        measured[name] = figures
        audits[name] = parse_audit(audit_text, audit_status)
    return measured, audits


def from_logs(args, scenes):
    measured = {}
    for scene in scenes:
        name = stem(scene)
        log = os.path.join(args.from_logs, name + ".log")
        print(f"  reading {log}")
        if not os.path.isfile(log):
            print(f"  {name}: no log; its rows are left as they stand")
            continue
        with open(log, encoding="utf-8") as f:
            figures = parse_decompose(f.read())
        if figures is None:
            print(f"  {name}: {log} holds no decompose summary line; its rows are left as they stand",
                  file=sys.stderr)
            continue
        measured[name] = figures
    return measured, {}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shared", default=os.path.normpath(os.path.join(ROOT, "..", "shared", "data", "scenes")),
                        help="folder of the shared scenes (default ../shared/data/scenes beside the clone)")
    parser.add_argument("--hullcover", default=os.path.join(ROOT, "build", "release", "apps", "hullcover"),
                        help="the hullcover command (default build/release/apps/hullcover)")
    parser.add_argument("--threads", type=int, default=2, help="--threads for decompose and audit (default 2)")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "results"),
                        help="folder for the coverings (default out/results)")
    parser.add_argument("--scenes", nargs="+", metavar="STEM", help="only these scenes (default all eight)")
    parser.add_argument("--from-logs", metavar="DIR",
                        help="read DIR/STEM.log (decompose's standard output) instead of running anything")
    parser.add_argument("--dry-run", action="store_true", help="print the commands and tables; run and write nothing")
    args = parser.parse_args()

    scenes = SCENES
    if args.scenes:
        unknown = set(args.scenes) - {stem(s) for s in SCENES}
        if unknown:
            parser.error("unknown scenes: " + ", ".join(sorted(unknown)))
        scenes = [s for s in SCENES if stem(s) in args.scenes]

    print("Per-scene tables (covering-defaults, audit-defaults):")
    got = from_logs(args, scenes) if args.from_logs else measure(args, scenes)
    if got is not None and args.dry_run and not args.from_logs:
        for name, paths in TABLE_FILES.items():
            print(f"  would write {name} into " + ", ".join(paths))
    if got is not None and not (args.dry_run and not args.from_logs):
        tables = build_tables(*got)
        for name, table in tables.items():
            if args.dry_run:
                print(f"\n{name}:\n{table}")
            for path in TABLE_FILES[name]:
                write_table(path, name, table, args.dry_run)

    print("\nNot regenerated here (an external build, or minutes to hours); to measure them, run from the "
          "repository (S = ../shared/data/scenes, hullcover = build/release/apps/hullcover):")
    for page, what, commands in EXTERNAL:
        print(f"\n  {page}: {what}")
        for command in commands:
            print(f"    {command}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
