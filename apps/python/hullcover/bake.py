"""A distributed bake on Dask: each cell of a scene is one task.

    python3 -m hullcover.bake WORLD.obj -o HULLS.obj [--json H.json] [--world H.hcw]
                              [--scheduler tcp://HOST:8786] [--workers N]

Without --scheduler the bake runs on a LocalCluster of this machine's cores
(one single-threaded worker process per core). With one, the scene's path
must name the same file on every worker (a shared folder): each worker
checks the file's SHA-256 against the client's before it uses it.

How it runs (docs/worlds.md, "The distributed bake"):
  1. The client hashes the scene and learns its cells (as StagedBake does:
     islands, cells, scene index).
  2. Each cell is a task, largest first. A worker loads the scene once and
     keeps it for every later task of the same scene and options; a task
     returns the cell's result as bytes (the checked form of
     lib/covering/src/cells/cell_result_bytes.h).
  3. The client gathers the bytes in cell order and finishes: the seam pass
     and the hulls. The output is the same, byte for byte, as
     `hullcover decompose WORLD -o HULLS.obj --world H.hcw` with the same
     options, whichever worker ran which cell, and whether or not a worker
     died on the way (Dask runs its tasks again elsewhere).

Files are written atomically (a reader never sees one half written). Exit
status: 0 done, 2 bad input or options, 1 anything else.
"""

import argparse
import hashlib
import importlib
import json
import os
import sys
import threading
import time

from . import _hullcover

# One loaded scene per worker process, kept between tasks: loading (import,
# weld, scene index) costs far more than most cells. The key holds the file's
# hash and the options, so a worker that served another bake reloads.
_loaded_lock = threading.Lock()
_loaded = {}


def _sha256(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _scene_on_this_worker(path, sha256, options):
    key = (path, sha256, tuple(sorted(options.items())))
    with _loaded_lock:
        bake = _loaded.get(key)
        if bake is None:
            found = _sha256(path)
            if found != sha256:
                raise ValueError(f"{path} on this worker is not the client's scene (SHA-256 {found[:12]}..., "
                                 f"expected {sha256[:12]}...): bake from a folder every worker shares")
            _loaded.clear()
            bake = _hullcover.StagedBake.load(path, **options)
            _loaded[key] = bake
        return bake


def merge_cell_task(path, sha256, options, cell):
    """One Dask task: the bytes of cell `cell` (run on a worker)."""
    return _scene_on_this_worker(path, sha256, options).merge_cell(cell)


def _options(args):
    return {"tol": args.tol, "cell_size": args.cell_size, "agent_radius": args.agent_radius,
            "max_deviation": args.max_deviation, "threads": 1}


def _parser():
    p = argparse.ArgumentParser(
        prog="python3 -m hullcover.bake",
        description="Decompose a scene on a Dask cluster, one task per cell; the output is the same as "
                    "`hullcover decompose` gives on one machine.")
    p.add_argument("scene", help="Scene file (OBJ, PLY, STL, glTF/GLB, FBX); with --scheduler, a path "
                                 "every worker can read")
    p.add_argument("-o", "--output", required=True, help="The hull OBJ (as `hullcover decompose -o`)")
    p.add_argument("--json", help="Also write the report `hullcover decompose --json` writes")
    p.add_argument("--world", help="Also write the runtime file (.hcw)")
    p.add_argument("--scheduler", help="Address of a running Dask scheduler, e.g. tcp://10.0.0.5:8786 "
                                       "(default: a LocalCluster on this machine)")
    p.add_argument("--workers", type=int, default=0,
                   help="LocalCluster worker processes (default 0: one per core)")
    p.add_argument("--tol", type=float, help="Tolerance in scene units (as `hullcover decompose --tol`)")
    p.add_argument("--cell-size", type=float, help="Cell side, scene units (as `hullcover decompose`)")
    p.add_argument("--agent-radius", type=float, help="As `hullcover decompose --agent-radius`")
    p.add_argument("--max-deviation", type=float, help="As `hullcover decompose --max-deviation`")
    p.add_argument("--report-cells", action="store_true",
                   help="Print a line to stderr as each cell arrives (what tests watch)")
    p.add_argument("-q", "--quiet", action="store_true", help="No progress bar")
    return p


def _client(args):
    from distributed import Client, LocalCluster
    if args.scheduler:
        return Client(args.scheduler), None
    workers = args.workers if args.workers > 0 else (os.cpu_count() or 1)
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    return Client(cluster), cluster


def bake(args):
    """Runs the bake; returns the figures it prints."""
    from distributed import as_completed, progress

    start = time.monotonic()
    path = os.path.abspath(args.scene)
    sha256 = _sha256(path)
    options = _options(args)
    # The client needs the scene too (cell count, then the finish); it loads
    # while the workers start.
    local = {}

    def load_here():
        try:
            local["bake"] = _hullcover.StagedBake.load(path, **dict(options, threads=0))
        except Exception as e:  # reported after the join
            local["error"] = e

    loader = threading.Thread(target=load_here)
    loader.start()
    client, cluster = _client(args)
    try:
        loader.join()
        if "error" in local:
            raise local["error"]
        staged = local["bake"]
        count = staged.cell_count()
        cells = sorted(range(count), key=lambda c: -staged.cell_face_count(c))
        # By the module's name, so Dask pickles a reference to it, not the
        # function's globals (as it would for __main__'s under -m).
        task = importlib.import_module("hullcover.bake").merge_cell_task
        futures = [client.submit(task, path, sha256, options, c,
                                 key=f"hullcover-cell-{sha256[:16]}-{c}", priority=count - i, pure=False)
                   for i, c in enumerate(cells)]
        cell_of = {f.key: c for f, c in zip(futures, cells)}
        if args.report_cells:
            for done, future in enumerate(as_completed(futures), 1):
                print(f"hullcover.bake: cell {cell_of[future.key]} done ({done} of {count})",
                      file=sys.stderr, flush=True)
        elif not args.quiet:
            progress(futures)
            print(file=sys.stderr)
        results = client.gather(futures)
        ordered = [None] * count
        for c, result in zip(cells, results):
            ordered[c] = result
        workers_seen = len(client.scheduler_info()["workers"])
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    baked = time.monotonic()
    d = staged.finish(ordered)
    if args.world:
        d.write_world(args.world)
    if args.json:
        d.write_json(args.json, json.dumps({"input": args.scene, "seconds_including_import":
                                            time.monotonic() - start}))
    d.write_obj(args.output)
    return {"cells": count, "hulls": d.hull_count(), "workers": workers_seen,
            "seconds_cells": baked - start, "seconds_finish": time.monotonic() - baked}


def main(argv=None):
    parser = _parser()
    args = parser.parse_args(argv)
    if not os.path.isfile(args.scene):
        print(f"hullcover.bake: error: {args.scene}: no such file", file=sys.stderr)
        return 2
    if args.workers < 0:
        print("hullcover.bake: error: --workers must be >= 0", file=sys.stderr)
        return 2
    try:
        figures = bake(args)
    except ValueError as e:
        print(f"hullcover.bake: error: {e}", file=sys.stderr)
        return 2
    except (OSError, TimeoutError) as e:
        print(f"hullcover.bake: error: {e} (is the scheduler at {args.scheduler or 'the local cluster'} "
              f"reachable?)", file=sys.stderr)
        return 1
    print(f"{args.scene}: {figures['cells']} cells on {figures['workers']} workers -> {figures['hulls']} hulls, "
          f"cells {figures['seconds_cells']:.1f} s, finish {figures['seconds_finish']:.1f} s; wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
