"""A distributed bake on Dask: each cell of a scene is one task.

    python3 -m hullcover.bake WORLD.obj -o HULLS.obj [--json H.json] [--world H.hcw]
                              [--scheduler tcp://HOST:8786] [--workers N]

Without --scheduler the bake runs on a LocalCluster of this machine's cores
(one single-threaded worker process per core). With one, the prepared scene
file (--prepared) must lie in a folder every worker reads: each worker
checks its header checksum against the client's before it uses it.

How it runs (docs/worlds.md, "The distributed bake"):
  1. The client prepares the scene (islands, cells, scene index) and writes
     it to the prepared scene file.
  2. Each cell is a task, largest first. A worker maps the prepared file
     once (StagedBake.map: the scene index is read in place, not loaded)
     and keeps it for every later task of the same file and options; after
     each task it hands the file's pages back, so its memory holds what the
     cell at hand reads, not the world. A task returns the cell's result as
     bytes (the checked form of lib/covering/src/cells/cell_result_bytes.h).
  3. The client gathers the bytes in cell order and finishes: the seam pass
     and the hulls. The output is the same, byte for byte, as
     `hullcover decompose WORLD -o HULLS.obj --world H.hcw` with the same
     options, whichever worker ran which cell, and whether or not a worker
     died on the way (Dask runs its tasks again elsewhere).

Files are written atomically (a reader never sees one half written). Exit
status: 0 done, 2 bad input or options, 1 anything else.
"""

import argparse
import ctypes
import importlib
import json
import os
import sys
import threading
import time

from . import _hullcover

# One mapped prepared scene per worker process, kept between tasks. The key
# holds the file's hash and the options, so a worker that served another
# bake maps anew.
_loaded_lock = threading.Lock()
_loaded = {}


def _libc_trim():
    # glibc keeps freed memory for reuse; a worker hands it back between
    # cells, so its peak follows the largest cell, not the sum of the
    # scraps every cell left. Elsewhere: nothing.
    try:
        return ctypes.CDLL("libc.so.6").malloc_trim
    except (OSError, AttributeError):
        return None


_trim_heap = _libc_trim()


def _fingerprint(path):
    """The prepared scene file's header checksum, as hex: it covers every
    section's checksum, which StagedBake.map checks against the sections,
    so it names the file's content without reading the whole file (docs/
    worlds.md, "The prepared scene file"). "" for a file too short."""
    with open(path, "rb") as f:
        head = f.read(16)
        if len(head) < 16:
            return ""
        count = int.from_bytes(head[12:16], "little")
        f.seek(32 + 32 * count)
        tail = f.read(8)
    return tail.hex() if len(tail) == 8 else ""


def _scene_on_this_worker(path, fingerprint, options):
    key = (path, fingerprint, tuple(sorted(options.items())))
    with _loaded_lock:
        bake = _loaded.get(key)
        if bake is None:
            found = _fingerprint(path)
            if found != fingerprint:
                raise ValueError(f"{path} on this worker is not the client's prepared scene (checksum "
                                 f"{found[:12] or 'none'}, expected {fingerprint[:12]}): give --prepared a path "
                                 f"in a folder every worker shares")
            _loaded.clear()
            bake = _hullcover.StagedBake.map(path, **_map_options(options))
            _loaded[key] = bake
        return bake


def merge_cell_task(path, fingerprint, options, cell):
    """One Dask task: the bytes of cell `cell` (run on a worker)."""
    bake = _scene_on_this_worker(path, fingerprint, options)
    try:
        return bake.merge_cell(cell)
    finally:
        bake.release_pages()
        if _trim_heap is not None:
            _trim_heap(0)


def _peak_memory_mb():
    """This process's peak resident memory, MB (run on each worker)."""
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def _map_options(options):
    # The tolerance is the prepared scene's own.
    return {k: v for k, v in options.items() if k != "tol"}


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
    p.add_argument("--prepared", help="Where to write the prepared scene file the workers map (default: a "
                                      "temporary file beside the output, removed after the bake); with "
                                      "--scheduler, in a folder every worker reads")
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
    from distributed import as_completed

    start = time.monotonic()
    path = os.path.abspath(args.scene)
    options = _options(args)
    output_folder = os.path.dirname(os.path.abspath(args.output))
    prepared = os.path.abspath(args.prepared) if args.prepared else os.path.join(
        output_folder, f".{os.path.basename(args.output)}.{os.getpid()}.hcp")
    # The client prepares the scene (it needs it for the cell count and the
    # finish) and writes it for the workers while they start.
    local = {}

    def prepare_here():
        try:
            local["bake"] = _hullcover.StagedBake.load(path, **dict(options, threads=0))
            local["bake"].write_prepared(prepared)
            local["fingerprint"] = _fingerprint(prepared)
        except Exception as e:  # reported after the join
            local["error"] = e

    preparer = threading.Thread(target=prepare_here)
    preparer.start()
    client, cluster = _client(args)
    try:
        preparer.join()
        if "error" in local:
            raise local["error"]
        staged = local["bake"]
        fingerprint = local["fingerprint"]
        count = staged.cell_count()
        cells = sorted(range(count), key=lambda c: -staged.cell_face_count(c))
        # By the module's name, so Dask pickles a reference to it, not the
        # function's globals (as it would for __main__'s under -m).
        task = importlib.import_module("hullcover.bake").merge_cell_task
        futures = [client.submit(task, prepared, fingerprint, options, c,
                                 key=f"hullcover-cell-{fingerprint}-{c}", priority=count - i, pure=False)
                   for i, c in enumerate(cells)]
        cell_of = {f.key: c for f, c in zip(futures, cells)}
        # Each result is taken as it arrives and its future let go, so the
        # worker that made it frees it at once instead of holding every
        # result it made until the end.
        ordered = [None] * count
        for done, (future, result) in enumerate(as_completed(futures, with_results=True), 1):
            ordered[cell_of[future.key]] = result
            future.release()
            if args.report_cells:
                print(f"hullcover.bake: cell {cell_of[future.key]} done ({done} of {count})",
                      file=sys.stderr, flush=True)
            elif not args.quiet:
                print(f"\rhullcover.bake: {done} of {count} cells", end="", file=sys.stderr, flush=True)
        if not args.quiet and not args.report_cells:
            print(file=sys.stderr)
        del futures
        workers_seen = len(client.scheduler_info()["workers"])
        peak_module = importlib.import_module("hullcover.bake")
        worker_peaks = sorted(client.run(peak_module._peak_memory_mb).values())
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
        if not args.prepared and os.path.exists(prepared):
            os.remove(prepared)
    baked = time.monotonic()
    d = staged.finish(ordered)
    if args.world:
        d.write_world(args.world)
    if args.json:
        d.write_json(args.json, json.dumps({"input": args.scene, "seconds_including_import":
                                            time.monotonic() - start}))
    d.write_obj(args.output)
    return {"cells": count, "hulls": d.hull_count(), "workers": workers_seen, "worker_peak_mb": worker_peaks,
            "client_peak_mb": _peak_memory_mb(),
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
    peaks = ", ".join(f"{mb:.0f}" for mb in figures["worker_peak_mb"])
    print(f"  peak memory: workers {peaks} MB, client {figures['client_peak_mb']:.0f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
