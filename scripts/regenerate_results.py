#!/usr/bin/env python3
"""Regenerate the results tables that can be measured on one machine in minutes, in place.

For each shared scene (../shared/data/scenes beside the clone, or --shared
DIR) it runs, with the Release build's command line:

    hullcover decompose SCENE -o OUT/STEM.obj --world OUT/STEM.hcw --json OUT/STEM.json -q --threads N
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

Then the other marked tables (each command's output is kept in
OUT/TABLE/KEY.log, with its exit status, wall and CPU seconds and peak
memory in OUT/TABLE/KEY.json):

    docs/results/covering.md
      paper-vs-exact    decompose --conditions paper, audited, beside the
                        covering-defaults run (its logs OUT/STEM.log and
                        OUT/STEM.audit.log)
      near-merge        decompose --near-merge D x the diagonal (`hullcover
                        info --json`), five levels, every covering audited
      dissolve          decompose --dissolve off, audited, beside the defaults
      tries             threejs-collision-world at --tries 1 to 16, audited
      bar-length        sauerbraten-fdm6 at four --bar-length, audited
      coverage          faces given flat hulls, from OUT/STEM.json of the
                        covering-defaults run, with its audit's verdict
      metamorphic       build/release/tests/test_scenes --gtest_filter=
                        '*SceneMetamorphic*' (HULLCOVER_SHARED_DIR set)
    docs/results/agents.md
      agent-allowances  nav_test at --agent-radius 0.3, the gear at
                        --max-deviation 0.24, audited with the allowance
      agent-radius      three scenes at --agent-radius 0.3, agent audits
      bench             hullcover bench nav_test@1 collision-world@1
    docs/results/audit.md
      vhacd             hullcover audit of V-HACD's hulls, one thread, timed
      audit-threads     scripts/measure_audit_threads.sh
    docs/results/runtime.md
      fcl, baselines, sliding, batch-threads
                        one run of build/release/tests/hullcover_bench_queries
                        (--benchmark_out JSON); baselines puts its FCL column
                        beside the Jolt ratios as the page holds them
    docs/results/worlds.md
      world-maps        scripts/measure_world_maps.py --audit-alone-hulls on the
                        six levels
      world-cost        hullcover world, then decompose, at 1 and 3 rounds

A full run took about 38 minutes on two cores shared with a compiler. The tables that
need an external build (the Jolt harness), data not distributed with the
project (the Red Eclipse maps) or much more time (the 12-round world, the
world at an agent's radius) are left alone: the script prints the commands
that measure them.

    scripts/regenerate_results.py [--shared DIR] [--hullcover BIN] [--threads N]
                                  [--out DIR] [--scenes STEM...] [--tables NAME...]
                                  [--dry-run]
    scripts/regenerate_results.py --from-logs DIR [--tables NAME...] [--dry-run]

--tables runs only the tables named (defaults stands for covering-defaults
and audit-defaults). --scenes limits the per-scene tables to those scenes;
the other scenes' rows stay as they stand. --dry-run prints the commands it
would run and the tables it would write, and runs and writes nothing.
--from-logs DIR runs nothing either: it reads DIR/STEM.log and
DIR/STEM.audit.log (the standard output of the two commands above) for each
scene, and DIR/TABLE/KEY.log and .json for the other tables, as a run with
--out DIR leaves them; where an audit log is missing it takes the audit
columns from the pages as they stand (warning where the page's audited hull
count differs from the log's). A scene or table whose file or log is
missing keeps its rows as they stand. Standard library only.
"""

import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import time

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
    ("docs/results/runtime.md", "The example server (needs the installed example server)", [
        "scripts/check_install.sh",
    ]),
    ("docs/results/agents.md", "A world at an agent's radius (the audit alone: about 20 minutes of CPU)", [
        "hullcover world S/recast-nav_test.obj S/threejs-collision-world.glb S/recast-undulating.obj "
        "S/recast-dungeon.obj S/sauerbraten-fdm6.obj@20 S/sauerbraten-pandora.obj@20 -o world1.obj "
        "--triangles 89324",
        "hullcover decompose world1.obj -o agent.obj --agent-radius 0.3",
        "hullcover audit world1.obj agent.obj --agent-radius 0.3 --threads 2",
    ]),
    ("docs/results/audit.md", "Rays judged from the surface (needs numpy; the Red Eclipse maps)", [
        "python3 scripts/cross_check_free_space.py MAP.obj H.obj --rays 1000",
    ]),
    ("docs/results/worlds.md", "Cost against size, 6 and 12 rounds (the 12-round bake and its audit: over "
     "10 minutes of CPU each)", [
        "hullcover world S/recast-nav_test.obj S/threejs-collision-world.glb S/recast-undulating.obj "
        "S/recast-dungeon.obj S/sauerbraten-fdm6.obj@20 S/sauerbraten-pandora.obj@20 -o worldN.obj "
        "--triangles $((89324 * N))",
        "hullcover decompose worldN.obj -o HN.obj --json HN.json",
        "hullcover audit world12.obj H12.obj --threads 2",
    ]),
    ("docs/results/worlds.md", "Threads and cells; re-bake after an edit", [
        "hullcover decompose S/sauerbraten-pandora.obj -o H.obj --threads 1     # then --threads 2; --cell-size 0",
        "scripts/move_wall.py world.obj moved.obj --by 0.25",
        "hullcover decompose world.obj -o full.obj --cell-cache C",
        "hullcover decompose moved.obj -o re.obj --cell-cache C --json re.json",
        "hullcover decompose moved.obj -o full_moved.obj",
    ]),
    ("docs/results/worlds.md", "Distributed bake (needs dask)", [
        "python3 -m hullcover.bake S/recast-dungeon.obj -o bk.obj --world bk.hcw --json bk.json",
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
        text, status = run([args.hullcover, "decompose", path, "-o", obj, "--world", hcw, "--json",
                            os.path.join(args.out, name + ".json"), "-q"] + threads, args.dry_run)
        if not args.dry_run:
            save_log(os.path.join(args.out, name + ".log"), text)
        figures = parse_decompose(text) if status == 0 else None
        if not args.dry_run and figures is None:
            print(f"  {scene}: decompose failed (exit {status}); its rows are left as they stand",
                  file=sys.stderr)
            continue
        audit_text, audit_status = run([args.hullcover, "audit", path, hcw, "-q"] + threads, args.dry_run)
        if args.dry_run:
            continue
        save_log(os.path.join(args.out, name + ".audit.log"), audit_text, audit_status)
        measured[name] = figures
        audits[name] = parse_audit(audit_text, audit_status)
    return measured, audits


def save_log(path, text, status=None):
    """Keeps a command's standard output (and an audit's exit status) for --from-logs."""
    with open(path, "w", encoding="utf-8") as f:
        f.write(text or "")
    if status is not None:
        with open(path + ".status", "w", encoding="utf-8") as f:
            f.write(f"{status}\n")


def read_audit_log(path):
    """An audit's parsed figures from PATH and PATH.status, or None."""
    if not os.path.isfile(path):
        return None
    with open(path, encoding="utf-8") as f:
        text = f.read()
    status = 0
    if os.path.isfile(path + ".status"):
        with open(path + ".status", encoding="utf-8") as f:
            status = int(f.read().strip() or 0)
    return parse_audit(text, status)


def from_logs(args, scenes):
    measured, audits = {}, {}
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
        audit = read_audit_log(os.path.join(args.from_logs, name + ".audit.log"))
        if audit is not None:
            audits[name] = audit
    return measured, audits


# ---------------------------------------------------------------------------
# The other regenerated tables. Each runs its commands through Runs, which
# keeps every command's standard output in OUT/GROUP/KEY.log and its exit
# status, wall and CPU seconds and peak memory in OUT/GROUP/KEY.json, so
# that --from-logs DIR rebuilds the same tables from DIR/GROUP/KEY.*.

class Runs:
    def __init__(self, args):
        self.args = args
        self.from_logs = args.from_logs is not None
        self.dry = args.dry_run and not self.from_logs
        self.base = args.from_logs if self.from_logs else args.out

    def run(self, group, key, cmd, env=None, accept=(0, 1)):
        """A command's record {text, status, wall, cpu, user, max_rss_mb}, or None when not run."""
        log = os.path.join(self.base, group, key + ".log")
        meta = os.path.join(self.base, group, key + ".json")
        if self.from_logs:
            if not (os.path.isfile(log) and os.path.isfile(meta)):
                print(f"  no {log} (or its .json): the rows it feeds are left as they stand")
                return None
            with open(log, encoding="utf-8") as f, open(meta, encoding="utf-8") as m:
                record = json.load(m)
                record["text"] = f.read()
            if record["status"] not in accept:
                print(f"  {log}: exit {record['status']}; the rows it feeds are left as they stand")
                return None
            return record
        shown = (" ".join(f"{k}={v}" for k, v in (env or {}).items()) + " " if env else "") + shlex.join(cmd)
        print("  $ " + shown)
        if self.dry:
            return None
        os.makedirs(os.path.dirname(log), exist_ok=True)
        start = time.monotonic()
        with open(log, "w", encoding="utf-8") as out, open(log + ".stderr", "w", encoding="utf-8") as err:
            child = subprocess.Popen(cmd, stdout=out, stderr=err, cwd=ROOT,
                                     env=dict(os.environ, **env) if env else None)
            _, wait_status, usage = os.wait4(child.pid, 0)
            child.returncode = os.waitstatus_to_exitcode(wait_status)
        record = {"command": shown, "status": child.returncode, "wall": time.monotonic() - start,
                  "user": usage.ru_utime, "cpu": usage.ru_utime + usage.ru_stime,
                  "max_rss_mb": usage.ru_maxrss / 1024.0}
        with open(meta, "w", encoding="utf-8") as m:
            json.dump(record, m, indent=1)
        with open(log, encoding="utf-8") as f:
            record["text"] = f.read()
        if record["status"] not in accept:
            with open(log + ".stderr", encoding="utf-8") as f:
                sys.stderr.write(f.read()[-2000:])
            print(f"  exit {record['status']}: the rows it feeds are left as they stand", file=sys.stderr)
            return None
        return record


def seconds(x):
    x = float(x)
    return f"{x:.2f} s" if x < 10 else f"{x:.1f} s" if x < 100 else f"{x:.0f} s"


def percent(part, whole):
    return f"{100.0 * part / whole:+.1f}%" if whole else "-"


def flat(text):
    return " ".join(text.split())


def audit_figures(text, status):
    """Every figure of `hullcover audit`'s standard output the tables use."""
    f = flat(text)
    r = {"verdict": "error (exit 2)" if status == 2 else NOT_RECORDED}
    m = re.search(r": (CLEAN|VIOLATIONS)\b", f)
    if m and status != 2:
        r["verdict"] = m.group(1)
    for key, label in (("front", "front free space"), ("opening", "openings")):
        m = re.search(label + r": (\d+) of (\d+) rays lost \(([\d.]+)%\)", f)
        if m:
            r[key] = (int(m.group(1)), int(m.group(2)), float(m.group(3)))
    r["deepest"] = max([float(x) for x in re.findall(r"deepest: depth ([-\d.e+]+)", f)] or [0.0])
    m = re.search(r"lost cells: (\d+) octree", f)
    r["cells"] = int(m.group(1)) if m else None
    m = re.search(r"(\d+) faces \(([\d.]+)% of the area\) on no hull's surface", f)
    r["uncovered"] = (int(m.group(1)), float(m.group(2))) if m else None
    m = re.search(r"(\d+) missed contacts, (\d+) false contacts \((\d+) deeper than the tolerance in free space", f)
    r["contacts"] = (int(m.group(1)), int(m.group(3))) if m else None
    m = re.search(r"(\d+) mesh vertices and (\d+) edges inside hulls", f)
    r["inside"] = (int(m.group(1)), int(m.group(2))) if m else None
    return r


def rays_cell(r, key):
    if key not in r:
        return NOT_RECORDED
    lost, rays, share = r[key]
    if rays == 0:
        return "(no open edge)"
    shown = f"{share:.3g}" if share >= 0.001 else "<0.001"
    return f"{grouped(lost)} of {grouped(rays)}" + (f" ({shown}%)" if lost else "")


def verdict_of(record):
    return audit_figures(record["text"], record["status"])["verdict"] if record else NOT_RECORDED


class Context:
    """What the table generators share: the runs, the scenes chosen, the scenes' facts."""
    def __init__(self, args, scenes):
        self.args, self.runs = args, Runs(args)
        self.scenes = scenes
        self.hc = args.hullcover
        self.threads = ["--threads", str(args.threads)]
        self._info = {}

    def path(self, scene):
        return os.path.join(self.args.shared, scene)

    def chosen(self, name):
        return any(stem(s) == name for s in self.scenes)

    def scene_file(self, name):
        return next(s for s in SCENES if stem(s) == name)

    def out(self, group, *parts):
        d = os.path.join(self.runs.base, group)
        if not self.runs.from_logs and not self.runs.dry:
            os.makedirs(d, exist_ok=True)
        return os.path.join(d, *parts)

    def info(self, name):
        """`hullcover info --json` of a scene (diagonal, tolerance), or None."""
        if name not in self._info:
            r = self.runs.run("info", name, [self.hc, "info", self.path(self.scene_file(name)), "--json"],
                              accept=(0,))
            self._info[name] = json.loads(r["text"]) if r else None
        return self._info[name]

    def defaults(self, name):
        """The covering-defaults run of a scene: (decompose figures, audit record) from its logs, or None."""
        base = self.args.from_logs or self.args.out
        log, audit = os.path.join(base, name + ".log"), os.path.join(base, name + ".audit.log")
        if not (os.path.isfile(log) and os.path.isfile(audit)):
            return None
        with open(log, encoding="utf-8") as f:
            d = parse_decompose(f.read())
        with open(audit, encoding="utf-8") as f:
            text = f.read()
        status = 0
        if os.path.isfile(audit + ".status"):
            with open(audit + ".status", encoding="utf-8") as f:
                status = int(f.read().strip() or 0)
        return (d, {"text": text, "status": status}) if d else None

    def decompose(self, group, key, name, options, audit_options=None, audit=True, threads=True):
        """Decomposes a shared scene with OPTIONS (and audits the .hcw); (figures, decompose record, audit record)."""
        scene = self.path(self.scene_file(name))
        hcw = self.out(group, key + ".hcw")
        cmd = [self.hc, "decompose", scene, "-o", self.out(group, key + ".obj"), "--world", hcw, "-q"]
        d = self.runs.run(group, key, cmd + options + (self.threads if threads else []), accept=(0,))
        a = None
        if audit and (d or self.runs.dry):
            a = self.runs.run(group, key + ".audit", [self.hc, "audit", scene, hcw, "-q"] + (audit_options or [])
                              + self.threads)
        return (parse_decompose(d["text"]) if d else None), d, a


def table_groups(path, name):
    """The rows of a marked table as it stands, grouped by scene (a row with an empty first cell
    belongs to the scene above): {scene: [lines]}."""
    with open(os.path.join(ROOT, path), encoding="utf-8") as f:
        text = f.read()
    start, stop = marked_span(text, name, path)
    groups, current = {}, None
    for line in text[start:stop].splitlines()[2:]:
        if line.startswith("|"):
            first = line.strip().strip("|").split("|")[0].strip()
            if first:
                current = first
            groups.setdefault(current, []).append(line + "\n")
    return groups


def scene_table(ctx, path, name, header, rows):
    """HEADER and ROWS ({scene: [cells rows]}) in the shared scenes' order; a scene not measured
    keeps its rows as they stand. None when nothing was measured (the table is left alone)."""
    if not rows:
        return None
    old = table_groups(path, name)
    out = header
    order = [stem(s) for s in SCENES] + [k for k in old if k not in {stem(s) for s in SCENES}]
    for scene in order:
        if scene in rows:
            out += "".join("| " + " | ".join(cells) + " |\n" for cells in rows[scene])
        elif scene in old:
            out += "".join(old[scene])
    return out


# --- covering.md -------------------------------------------------------------

def gen_paper_vs_exact(ctx):
    """--conditions paper against exact (the covering-defaults run), both audited at the defaults."""
    header = ("| scene | mode | hulls | hulls/face | seconds | front rays lost | opening rays lost | lost cells "
              "| missed / deep false contacts | audit |\n|---|---|--:|--:|--:|--:|--:|--:|--:|---|\n")
    rows = {}
    for scene in ctx.scenes:
        name = stem(scene)
        d, _, a = ctx.decompose("paper-vs-exact", name, name, ["--conditions", "paper"])
        exact = ctx.defaults(name)
        if not d or not a or not exact:
            if not ctx.runs.dry and not exact:
                print(f"  {name}: no covering-defaults logs for the exact row; its rows are left as they stand")
            continue
        lines = []
        for mode, dd, aa in (("paper", d, a), ("exact", exact[0], exact[1])):
            r = audit_figures(aa["text"], aa["status"])
            contacts = f"{r['contacts'][0]} / {r['contacts'][1]}" if r["contacts"] else NOT_RECORDED
            lines.append([name if mode == "paper" else "", mode, grouped(dd["hulls"]), dd["per_face"],
                          seconds(dd["seconds"]), rays_cell(r, "front"), rays_cell(r, "opening"),
                          grouped(r["cells"]) if r["cells"] is not None else NOT_RECORDED, contacts, r["verdict"]])
        rows[name] = lines
    return scene_table(ctx, "docs/results/covering.md", "paper-vs-exact", header, rows)


NEAR_MERGE_SCENES = ["threejs-collision-world", "recast-nav_test", "recast-undulating", "sauerbraten-fdm6",
                     "recast-dungeon"]
NEAR_MERGE_FRACTIONS = [0, 0.005, 0.02, 0.05, 0.1, 0.2]


def gen_near_merge(ctx):
    """--near-merge D x the scene's diagonal: hulls and seconds, every covering audited."""
    header = ("| scene | off | 0.005 | 0.02 | 0.05 | 0.1 | 0.2 | audits |\n"
              "|---|--:|--:|--:|--:|--:|--:|---|\n")
    rows = {}
    for name in NEAR_MERGE_SCENES:
        if not ctx.chosen(name):
            continue
        info = ctx.info(name)
        if not info and not ctx.runs.dry:
            continue
        diagonal = info["tolerance"]["diagonal"] if info else 1.0
        cells, unclean, ok = [], [], True
        for fraction in NEAR_MERGE_FRACTIONS:
            d, _, a = ctx.decompose("near-merge", f"{name}-{fraction}", name, ["--near-merge", f"{fraction * diagonal:.9g}"])
            if not d or not a:
                ok = False
                continue
            cells.append(f"{grouped(d['hulls'])}, {seconds(d['seconds'])}")
            if verdict_of(a) != "CLEAN":
                unclean.append(f"{verdict_of(a)} at {fraction}")
        if ok:
            rows[name] = [[name] + cells + ["; ".join(unclean) if unclean else f"all {len(cells)} CLEAN"]]
    return scene_table(ctx, "docs/results/covering.md", "near-merge", header, rows)


def gen_dissolve(ctx):
    """--dissolve off against on (the covering-defaults run)."""
    header = ("| scene | hulls, off | hulls, on | change | seconds, off | seconds, on | time on / off | audit, off |\n"
              "|---|--:|--:|--:|--:|--:|--:|---|\n")
    rows = {}
    for scene in ctx.scenes:
        name = stem(scene)
        d, _, a = ctx.decompose("dissolve", name, name, ["--dissolve", "off"])
        on = ctx.defaults(name)
        if not d or not a or not on:
            continue
        off_h, on_h = int(d["hulls"]), int(on[0]["hulls"])
        off_s, on_s = float(d["seconds"]), float(on[0]["seconds"])
        rows[name] = [[name, grouped(off_h), grouped(on_h), percent(on_h - off_h, off_h), seconds(off_s),
                       seconds(on_s), f"{on_s / off_s:.2f}" if off_s > 0 else "-", verdict_of(a)]]
    return scene_table(ctx, "docs/results/covering.md", "dissolve", header, rows)


def gen_tries(ctx):
    name = "threejs-collision-world"
    if not ctx.chosen(name):
        return None
    header = "| --tries | hulls | seconds | audit |\n|--:|--:|--:|---|\n"
    out = header
    for n in (1, 2, 4, 8, 16):
        d, _, a = ctx.decompose("tries", f"{name}-{n}", name, ["--tries", str(n)])
        if ctx.runs.dry:
            continue
        if not d or not a:
            return None
        out += f"| {n} | {grouped(d['hulls'])} | {seconds(d['seconds'])} | {verdict_of(a)} |\n"
    return out


def gen_bar_length(ctx):
    name = "sauerbraten-fdm6"
    if not ctx.chosen(name):
        return None
    info = ctx.info(name)
    if not info and not ctx.runs.dry:
        return None
    diagonal = info["tolerance"]["diagonal"] if info else 1.0
    tol = info["tolerance"]["length"] if info else 0.0
    out = "| --bar-length | scene units | hulls | seconds | audit |\n|---|--:|--:|--:|---|\n"
    for label, key, length in (("4 x tol (default)", "default", None), ("0.001 x diagonal", "0.001", 0.001),
                               ("0.01 x diagonal", "0.01", 0.01), ("0.1 x diagonal", "0.1", 0.1)):
        options = [] if length is None else ["--bar-length", f"{length * diagonal:.9g}"]
        d, _, a = ctx.decompose("bar-length", f"{name}-{key}", name, options)
        if ctx.runs.dry:
            continue
        if not d or not a:
            return None
        units = 4 * tol if length is None else length * diagonal
        out += f"| {label} | {units:.4g} | {grouped(d['hulls'])} | {seconds(d['seconds'])} | {verdict_of(a)} |\n"
    return out


def gen_metamorphic(ctx):
    test = os.path.join(ROOT, "build", "release", "tests", "test_scenes")
    shared = os.path.dirname(os.path.dirname(os.path.abspath(ctx.args.shared)))
    r = ctx.runs.run("metamorphic", "test_scenes", [test, "--gtest_filter=*SceneMetamorphic*"],
                     env={"HULLCOVER_SHARED_DIR": shared})
    if not r:
        return None
    counts = re.findall(r"^(\S+) ([^:\n]+): (-?\d+) hulls$", r["text"], re.M)
    if not counts:
        return None
    passed = "[  PASSED  ] 2 tests" in r["text"] and r["status"] == 0
    reference = {scene: int(n) for scene, t, n in counts if t == "untransformed"}
    out = "| scene | transform | hulls | against untransformed |\n|---|---|--:|--:|\n"
    counts = [(scene, re.sub(r"\d+\.\d+", lambda m: f"{float(m.group()):g}", transform), n)
              for scene, transform, n in counts]
    last = None
    for scene, transform, n in counts:
        base = reference.get(scene)
        diff = "" if transform == "untransformed" or not base else percent(int(n) - base, base)
        out += f"| {stem(scene) if scene != last else ''} | {transform} | {grouped(n)} | {diff} |\n"
        last = scene
    out += f"\nThe test {'passed' if passed else 'FAILED'}: " + (
        "every covering above audits CLEAN and keeps within the spread allowed.\n" if passed
        else "see its output (out/results/metamorphic/test_scenes.log).\n")
    return out


def gen_coverage(ctx):
    """Faces given flat hulls in the covering-defaults run (OUT/STEM.json) and its audit's verdict."""
    header = "| scene | hulls | faces given flat hulls (thin) | strict audit |\n|---|--:|--:|---|\n"
    base = ctx.args.from_logs or ctx.args.out
    rows = {}
    for scene in ctx.scenes:
        name = stem(scene)
        report, exact = os.path.join(base, name + ".json"), ctx.defaults(name)
        if ctx.runs.dry or not os.path.isfile(report) or not exact:
            continue
        with open(report, encoding="utf-8") as f:
            totals = json.load(f)["totals"]
        rows[name] = [[name, grouped(totals["hulls"]),
                       f"{grouped(totals['faces_given_flat_hulls'])} ({grouped(totals['thin_faces_given_flat_hulls'])})",
                       verdict_of(exact[1])]]
    return scene_table(ctx, "docs/results/covering.md", "coverage", header, rows)


# --- agents.md ---------------------------------------------------------------

AGENT_ALLOWANCES = [("recast-nav_test", ["--agent-radius", "0.3"], "`--agent-radius 0.3` (metres)"),
                    ("thor-art56-gearplate", ["--max-deviation", "0.24"], "`--max-deviation 0.24` (0.2% of diagonal)")]


def gen_agent_allowances(ctx):
    header = "| scene | exact (defaults) | allowance | hulls | time | audit with the allowance |\n|---|---|---|--:|--:|---|\n"
    rows = {}
    for name, options, label in AGENT_ALLOWANCES:
        if not ctx.chosen(name):
            continue
        d, rec, a = ctx.decompose("agents", name, name, options, audit_options=options)
        exact = ctx.defaults(name)
        if not d or not a or not exact:
            continue
        h, e = int(d["hulls"]), int(exact[0]["hulls"])
        rows[name] = [[name, f"{grouped(e)}, {seconds(exact[0]['seconds'])}", label, f"{grouped(h)} ({percent(h - e, e)})",
                       seconds(d["seconds"]), f"{verdict_of(a)}, {seconds(a['wall'])}"]]
    return scene_table(ctx, "docs/results/agents.md", "agent-allowances", header, rows)


AGENT_RADIUS_SCENES = ["recast-dungeon", "threejs-collision-world", "sauerbraten-pandora"]


def gen_agent_radius(ctx):
    header = "| scene | hulls | decompose | agent audit (2 threads) |\n|---|--:|--:|---|\n"
    rows = {}
    for name in AGENT_RADIUS_SCENES:
        if not ctx.chosen(name):
            continue
        options = ["--agent-radius", "0.3"]
        d, rec, a = ctx.decompose("agent-radius", name, name, options, audit_options=options)
        if not d or not a:
            continue
        rows[name] = [[name, grouped(d["hulls"]), seconds(d["seconds"]), f"{verdict_of(a)}, {seconds(a['wall'])}"]]
    return scene_table(ctx, "docs/results/agents.md", "agent-radius", header, rows)


# The levels of the movement-covering targets, with a character's radius
# (0.3 m) in each one's units.
MOVEMENT_SCENES = [("recast-nav_test", 0.3), ("threejs-collision-world", 0.3), ("recast-undulating", 0.3),
                   ("recast-dungeon", 0.3), ("sauerbraten-fdm6", 6.0), ("sauerbraten-pandora", 6.0)]


def movement_audit_cell(record):
    """The movement audit's verdict, its sinking centres and lost contacts."""
    if not record:
        return NOT_RECORDED
    f = flat(record["text"])
    sinking = re.search(r"sinking deeper than the slop into a hull: (\d+)", f)
    lost = re.search(r"contacts lost \(no hull within the slop\): (\d+)", f)
    reach = re.search(r"(\d+) reachable centres", f)
    figures = ", ".join(x for x in [
        f"{grouped(int(reach.group(1)))} centres" if reach else "",
        f"{sinking.group(1)} sinking" if sinking else "",
        f"{lost.group(1)} lost contacts" if lost else ""] if x)
    return f"{verdict_of(record)} ({figures}), {seconds(record['wall'])}"


def gen_movement(ctx):
    """Exact, walking and flying coverings of each level, timed in one run and audited."""
    header = ("| scene | exact | walk | walk audit | fly | fly audit |\n"
              "|---|--:|--:|---|--:|---|\n")
    rows = {}
    for name, radius in MOVEMENT_SCENES:
        if not ctx.chosen(name):
            continue
        exact, _, _ = ctx.decompose("movement", name + ".exact", name, [], audit=False)
        cells = [name, f"{grouped(exact['hulls'])}, {seconds(exact['seconds'])}" if exact else NOT_RECORDED]
        for reach in ("walk", "fly"):
            options = ["--agent-radius", str(radius), "--agent-reach", reach]
            d, _, a = ctx.decompose("movement", f"{name}.{reach}", name, options, audit_options=options)
            if not d or not exact:
                cells += [NOT_RECORDED, NOT_RECORDED]
                continue
            h, e = int(d["hulls"]), int(exact["hulls"])
            cells += [f"{grouped(h)} ({percent(h - e, e)}), {seconds(d['seconds'])}", movement_audit_cell(a)]
        rows[name] = [cells]
    return scene_table(ctx, "docs/results/agents.md", "movement", header, rows)


BENCH_SCENES = ["recast-nav_test.obj@1", "threejs-collision-world.glb@1"]


def gen_bench(ctx):
    out = ctx.out("bench", "bench")
    r = ctx.runs.run("bench", "bench", [ctx.hc, "bench"] + [ctx.path(s) for s in BENCH_SCENES] + ["--out", out, "-q"])
    if not r:
        return None
    table = [line + "\n" for line in r["text"].splitlines() if line.startswith("|")]
    if not table and os.path.isfile(os.path.join(out, "bench.md")):
        with open(os.path.join(out, "bench.md"), encoding="utf-8") as f:
            table = [line for line in f if line.startswith("|")]
    return "".join(table) or None


# --- audit.md ----------------------------------------------------------------

def share_of_area(x):
    """A percentage to one decimal, to two where one would round up to 100% (99.98%)."""
    text = f"{x:.1f}"
    return (f"{x:.2f}" if text == "100.0" and x < 100 else "100" if x >= 100 else text) + "%"


def gen_vhacd(ctx):
    header = ("| scene | front rays lost | opening rays lost | deepest | uncovered surface | "
              "missed / deep false contacts | audit | seconds (1 thread) |\n|---|--:|--:|--:|--:|--:|---|--:|\n")
    peer = os.path.join(os.path.dirname(os.path.abspath(ctx.args.shared)), "peer-hulls")
    rows = {}
    for scene in ctx.scenes:
        name = stem(scene)
        hulls = os.path.join(peer, name + ".vhacd.obj")
        if not os.path.isfile(hulls) and not ctx.runs.from_logs:
            continue
        a = ctx.runs.run("vhacd", name, [ctx.hc, "audit", ctx.path(scene), hulls, "-q", "--threads", "1"])
        if not a:
            continue
        r = audit_figures(a["text"], a["status"])
        share = lambda key: (NOT_RECORDED if key not in r else "(no open edge)" if r[key][1] == 0
                             else f"{r[key][2]:.1f}%")
        rows[name] = [[name, share("front"), share("opening"), f"{r['deepest']:.3g}",
                       share_of_area(r["uncovered"][1]) if r["uncovered"] else NOT_RECORDED,
                       f"{r['contacts'][0]} / {r['contacts'][1]}" if r["contacts"] else NOT_RECORDED,
                       r["verdict"], f"{a['wall']:.1f}"]]
    return scene_table(ctx, "docs/results/audit.md", "vhacd", header, rows)


def gen_audit_threads(ctx):
    out = ctx.out("audit-threads", "work")
    if not ctx.runs.from_logs and not ctx.runs.dry and os.path.isdir(out):
        for f in os.listdir(out):  # decompose afresh: the script reuses hulls it finds
            os.remove(os.path.join(out, f))
    r = ctx.runs.run("audit-threads", "measure", [os.path.join(ROOT, "scripts", "measure_audit_threads.sh"), out],
                     env={"HULLCOVER": ctx.hc, "SCENES_DIR": ctx.args.shared}, accept=(0,))
    if not r:
        return None
    out = "| scene | 1 thread | 2 threads | ratio | stdout and JSON the same bytes |\n|---|--:|--:|--:|---|\n"
    found = False
    for line in r["text"].splitlines():
        m = re.match(r"^(\S+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+(yes|no)$", line)
        if m:
            found = True
            out += f"| {m.group(1)} | {m.group(2)} s | {m.group(3)} s | {m.group(4)} | {m.group(5)} |\n"
    return out if found else None


# --- runtime.md --------------------------------------------------------------

QUERY_FILTER = "/(touches_capsule|touches_sphere|contacts_capsule|contacts_sphere|ray|sliding_sphere|sliding_capsule" \
               "|contacts_batch_threads|ray_batch_threads)/|threads/"


def query_bench(ctx):
    """The one run of hullcover_bench_queries the runtime tables share: {name: counters}, or None."""
    if "query_bench" not in ctx._info:
        binary = os.path.join(ROOT, "build", "release", "tests", "hullcover_bench_queries")
        json_out = ctx.out("queries", "queries.json")
        shared = os.path.dirname(os.path.dirname(os.path.abspath(ctx.args.shared)))
        r = ctx.runs.run("queries", "bench", [binary, f"--benchmark_filter={QUERY_FILTER}",
                                              f"--benchmark_out={json_out}", "--benchmark_out_format=json"],
                         env={"HULLCOVER_SHARED_DIR": shared}, accept=(0,))
        rows = None
        if r and os.path.isfile(json_out):
            with open(json_out, encoding="utf-8") as f:
                rows = {b["name"].replace("/manual_time", ""): b for b in json.load(f)["benchmarks"]}
        ctx._info["query_bench"] = rows
    return ctx._info["query_bench"]


def gen_fcl(ctx):
    rows_in = query_bench(ctx)
    if not rows_in:
        return None
    out = ("| scene | yes/no capsule | yes/no sphere | capsule contacts | sphere contacts | ray |\n"
           "|---|---|---|---|---|---|\n")
    for scene in SCENES:
        cells = []
        for q in ("touches_capsule", "touches_sphere", "contacts_capsule", "contacts_sphere", "ray"):
            pair = [rows_in.get(f"query/{scene}/{size}/{q}", {}).get("speedup") for size in ("character", "large")]
            if None in pair:
                break
            cells.append(" / ".join(f"{x:.1f}" for x in pair))
        if len(cells) == 5:
            out += f"| {stem(scene)} | " + " | ".join(cells) + " |\n"
    return out


JOLT_SCENES = ["recast-dungeon", "sauerbraten-fdm6", "sauerbraten-pandora", "threejs-collision-world"]


def gen_baselines(ctx):
    """FCL's large-probe speed-ups from this run beside the Jolt ratios as the page holds them."""
    rows_in = query_bench(ctx)
    if not rows_in:
        return None
    with open(os.path.join(ROOT, "docs/results/runtime.md"), encoding="utf-8") as f:
        text = f.read()
    jolt = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 7 and cells[0] in JOLT_SCENES:
            mesh_yn, mesh_c, mesh_r, comp_yn, comp_c, comp_r = cells[1:]
            jolt[cells[0]] = {"yes/no capsule": (mesh_yn.split(" / ")[0], comp_yn.split(" / ")[0]),
                              "yes/no sphere": (mesh_yn.split(" / ")[1], comp_yn.split(" / ")[1]),
                              "contacts capsule": (mesh_c.split(" / ")[0], comp_c.split(" / ")[0]),
                              "contacts sphere": (mesh_c.split(" / ")[1], comp_c.split(" / ")[1]),
                              "ray": (mesh_r, comp_r)}
    out = ("| scene | query | vs FCL triangles | vs Jolt MeshShape | vs Jolt compound of the same hulls |\n"
           "|---|---|--:|--:|--:|\n")
    for name in JOLT_SCENES:
        scene = next(s for s in SCENES if stem(s) == name)
        first = True
        for label, q in (("yes/no capsule", "touches_capsule"), ("yes/no sphere", "touches_sphere"),
                         ("contacts capsule", "contacts_capsule"), ("contacts sphere", "contacts_sphere"),
                         ("ray", "ray")):
            fcl = rows_in.get(f"query/{scene}/large/{q}", {}).get("speedup")
            mesh, comp = jolt.get(name, {}).get(label, ("-", "-"))
            out += f"| {name if first else ''} | {label} | {f'{fcl:.1f}' if fcl else '-'} | {mesh} | {comp} |\n"
            first = False
    return out


def gen_sliding(ctx):
    rows_in = query_bench(ctx)
    if not rows_in:
        return None
    out = ("| scene | resting spheres: off on hulls | off on triangles | resting capsules: off on hulls "
           "| off on triangles |\n|---|--:|--:|--:|--:|\n")
    for scene in SCENES:
        cells = []
        for q in ("sliding_sphere", "sliding_capsule"):
            b = rows_in.get(f"query/{scene}/character/{q}")
            if not b:
                break
            cells += [f"{int(b['hull_ghosts']):,} of {int(b['hull_contacts']):,}",
                      f"{int(b['triangle_ghosts']):,} of {int(b['triangle_contacts']):,}"]
        if len(cells) == 4:
            out += f"| {stem(scene)} | " + " | ".join(cells) + " |\n"
    return out


def gen_batch_threads(ctx):
    rows_in = query_bench(ctx)
    if not rows_in:
        return None
    out = "| scene | contacts batch, character / large | ray batch, character / large |\n|---|---|---|\n"
    for scene in SCENES:
        cells = []
        for q in ("contacts_batch_threads", "ray_batch_threads"):
            pair = [rows_in.get(f"query/{scene}/{size}/{q}", {}).get("speedup") for size in ("character", "large")]
            if None in pair:
                break
            cells.append(" / ".join(f"{x:.2f}" for x in pair))
        if len(cells) == 2:
            out += f"| {stem(scene)} | " + " | ".join(cells) + " |\n"
    control = rows_in.get("threads/arithmetic_control", {}).get("speedup")
    if control:
        out += f"| arithmetic control | {control:.2f} | |\n"
    wake = rows_in.get("threads/wake_up", {})
    if "asleep_us" in wake and "awake_us" in wake:
        out += (f"| an empty batch, thread asleep / awake | {wake['asleep_us']:.1f} µs / {wake['awake_us']:.1f} µs "
                f"| |\n")
    return out


# --- worlds.md ---------------------------------------------------------------

WORLD_SCENES = ["recast-nav_test.obj", "threejs-collision-world.glb", "recast-undulating.obj", "recast-dungeon.obj",
                "sauerbraten-fdm6.obj@20", "sauerbraten-pandora.obj@20"]


def gen_world_maps(ctx):
    out = ctx.out("world-maps", "work")
    scenes = [os.path.join(ctx.args.shared, s) for s in WORLD_SCENES]
    r = ctx.runs.run("world-maps", "measure", [sys.executable, os.path.join(ROOT, "scripts", "measure_world_maps.py"),
                                               "--hullcover", ctx.hc, "--out", out, "--audit-alone-hulls"] + scenes)
    if not r:
        return None
    table, audits = "", ""
    for block in re.split(r"\n(?=map \d+ \()", r["text"])[1:]:
        m = re.match(r"map \d+ \((\S+)\), its hulls alone in the world:", block)
        if m:
            f = audit_figures(block, 0)
            audits += (f"- {stem(m.group(1))}'s hulls alone, in place of its world hulls: {f['verdict']}, "
                       f"{rays_cell(f, 'front')} front and {rays_cell(f, 'opening')} opening rays of the world lost\n")
    for line in r["text"].splitlines():
        if line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            m = re.match(r"^(.*)\.(?:obj|glb)(@\d+)?$", cells[0])
            if m:
                cells[0] = m.group(1) + (f" ({m.group(2)})" if m.group(2) else "")
            table += "| " + " | ".join(cells) + " |\n"
    if table and audits:
        table += "\nThe world audited with a map's hulls alone put in place of its world hulls, for each map beyond 1%:\n\n" + audits
    return table or None


WORLD_ROUNDS = [1, 3]


def gen_world_cost(ctx):
    out = ("| rounds | triangles | hulls | wall time | CPU time | peak memory | output stage (coverage pass) |\n"
           "|--:|--:|--:|--:|--:|--:|--:|\n")
    scenes = [os.path.join(ctx.args.shared, s) for s in WORLD_SCENES]
    for n in WORLD_ROUNDS:
        world = ctx.out("world-cost", f"world{n}.obj")
        w = ctx.runs.run("world-cost", f"world{n}", [ctx.hc, "world"] + scenes + ["-o", world, "--triangles",
                                                                                   str(89324 * n)], accept=(0,))
        if not w and not ctx.runs.dry:
            return None
        report = ctx.out("world-cost", f"H{n}.json")
        d = ctx.runs.run("world-cost", f"decompose{n}", [ctx.hc, "decompose", world, "-o",
                                                         ctx.out("world-cost", f"H{n}.obj"), "--json", report, "-q"]
                         + ctx.threads, accept=(0,))
        if not d:
            return None
        f = parse_decompose(d["text"])
        output = "-"
        if os.path.isfile(report):
            with open(report, encoding="utf-8") as r:
                output = seconds(json.load(r)["seconds"]["output"])
        out += (f"| {n} | {grouped(f['faces'])} | {grouped(f['hulls'])} | {seconds(d['wall'])} | "
                f"{seconds(d['cpu'])} | {grouped(round(d['max_rss_mb']))} MB | {output} |\n")
    return out


# Marked tables beyond the per-scene defaults: (name, page, generator).
GENERATED = [
    ("paper-vs-exact", "docs/results/covering.md", gen_paper_vs_exact),
    ("near-merge", "docs/results/covering.md", gen_near_merge),
    ("dissolve", "docs/results/covering.md", gen_dissolve),
    ("tries", "docs/results/covering.md", gen_tries),
    ("bar-length", "docs/results/covering.md", gen_bar_length),
    ("coverage", "docs/results/covering.md", gen_coverage),
    ("metamorphic", "docs/results/covering.md", gen_metamorphic),
    ("agent-allowances", "docs/results/agents.md", gen_agent_allowances),
    ("agent-radius", "docs/results/agents.md", gen_agent_radius),
    ("bench", "docs/results/agents.md", gen_bench),
    ("movement", "docs/results/agents.md", gen_movement),
    ("vhacd", ["docs/results/audit.md", "README.md"], gen_vhacd),
    ("audit-threads", "docs/results/audit.md", gen_audit_threads),
    ("fcl", ["docs/results/runtime.md", "README.md"], gen_fcl),
    ("baselines", "docs/results/runtime.md", gen_baselines),
    ("sliding", "docs/results/runtime.md", gen_sliding),
    ("batch-threads", "docs/results/runtime.md", gen_batch_threads),
    ("world-maps", "docs/results/worlds.md", gen_world_maps),
    ("world-cost", "docs/results/worlds.md", gen_world_cost),
]


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
    parser.add_argument("--tables", nargs="+", metavar="NAME",
                        choices=["defaults"] + [name for name, _, _ in GENERATED],
                        help="only these tables (default all): defaults (covering-defaults and audit-defaults), "
                             + ", ".join(name for name, _, _ in GENERATED))
    parser.add_argument("--dry-run", action="store_true", help="print the commands and tables; run and write nothing")
    args = parser.parse_args()

    scenes = SCENES
    if args.scenes:
        unknown = set(args.scenes) - {stem(s) for s in SCENES}
        if unknown:
            parser.error("unknown scenes: " + ", ".join(sorted(unknown)))
        scenes = [s for s in SCENES if stem(s) in args.scenes]

    chosen = set(args.tables or ["defaults"] + [name for name, _, _ in GENERATED])
    started = time.monotonic()
    if "defaults" in chosen:
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
        print(f"  ({time.monotonic() - started:.0f} s so far)")

    if os.path.isdir(args.shared) or args.from_logs:
        ctx = Context(args, scenes)
        for name, page, generate in GENERATED:
            if name not in chosen:
                continue
            print(f"\n{name} ({page if isinstance(page, str) else ', '.join(page)}):")
            table = generate(ctx)
            if table is None:
                if not ctx.runs.dry:
                    print(f"  {name} left as it stands")
                continue
            if args.dry_run:
                print(f"\n{table}")
            for path in [page] if isinstance(page, str) else page:
                write_table(path, name, table, args.dry_run)
            print(f"  ({time.monotonic() - started:.0f} s so far)")

    print("\nNot regenerated here (an external build, or minutes to hours); to measure them, run from the "
          "repository (S = ../shared/data/scenes, hullcover = build/release/apps/hullcover):")
    for page, what, commands in EXTERNAL:
        print(f"\n  {page}: {what}")
        for command in commands:
            print(f"    {command}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
