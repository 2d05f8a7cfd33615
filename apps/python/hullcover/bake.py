"""A distributed bake on Dask: each cell of a scene is one task.

    python3 -m hullcover.bake WORLD.obj -o HULLS.obj [--json H.json] [--world H.hcw]
                              [--scheduler tcp://HOST:8786] [--workers N]

Without --scheduler the bake runs on a LocalCluster of this machine's cores
(one single-threaded worker process per core). With one, the prepared scene
file (--prepared) must lie in a folder every worker reads: each worker
checks its header checksum against the client's before it uses it.

How it runs (docs/worlds.md, "The distributed bake"):
  1. The client prepares the scene (islands, cells, scene index), writes it
     to the prepared scene file, plans and sends the tasks, and from then on
     reads the file mapped, as the workers do.
  2. Cells are batched into tasks of the remaining work's share (faces),
     shrinking towards the end, largest first,
     each batch within one group of seam cells (islands). A worker maps the
     prepared file once (StagedBake.map: the scene index is read in place,
     not loaded) and keeps it for every later task of the same file and
     options; as it goes (every HAND_BACK_FACES faces' work, and every
     HAND_BACK_SECONDS while a task runs) it hands the file's pages back,
     so its memory holds what the cells at hand read, not the world. A
     batch returns its cells' results as bytes
     (lib/covering/src/cells/cell_result_bytes.h).
  3. Each group's seam pass and hulls is a task too, on the batches of its
     cells (Dask moves their bytes between workers; the client never holds
     them). It returns the group's hulls as bytes (seam_result_bytes.h).
  4. The client puts the hulls together (flat hulls for faces no hull
     covers, every hull in order) and writes the files. The output is the
     same, byte for byte, as `hullcover decompose WORLD -o HULLS.obj --world
     H.hcw` with the same options, whichever worker ran what, and whether
     or not a worker died on the way (Dask runs its tasks again elsewhere).

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


# A worker hands the file's pages and its heap back after at least this
# many faces' work, and at the end of each task: after every cell of a
# batch of tiny ones (a world of scattered islands), the calls would cost
# more than the cells.
HAND_BACK_FACES = 2000

# While a task runs, the file's pages are also handed back this often: one
# large cell, or one large island's seam pass, reads hundreds of MB of the
# file in a single call, up to 460 MB of it within a second on the 3M
# world. The mapping is read-only, so pages dropped while the call reads
# them are read again from the page cache (a minor fault: a cell merged
# after its pages were dropped takes as long as one merged on them).
HAND_BACK_SECONDS = 0.25


class _HandBack:
    """Counts a task's work and hands pages and heap back as it goes; used
    as a context manager around the task, it also hands the file's pages
    back every HAND_BACK_SECONDS."""

    def __init__(self, bake):
        self.bake, self.faces = bake, 0
        self._stop = threading.Event()
        self._timer = threading.Thread(target=self._periodically, daemon=True)

    def __enter__(self):
        self._timer.start()
        return self

    def __exit__(self, *exception):
        self._stop.set()
        self._timer.join()
        self.now()

    def _periodically(self):
        while not self._stop.wait(HAND_BACK_SECONDS):
            self.bake.release_pages()

    def after(self, faces):
        self.faces += faces
        if self.faces >= HAND_BACK_FACES:
            self.now()

    def now(self):
        self.faces = 0
        self.bake.release_pages()
        if _trim_heap is not None:
            _trim_heap(0)


def merge_batch_task(path, fingerprint, options, cells):
    """One Dask task: [(cell, bytes)] for each of `cells` (run on a worker)."""
    bake = _scene_on_this_worker(path, fingerprint, options)
    results = []
    with _HandBack(bake) as hand_back:
        for cell in cells:
            results.append((cell, bake.merge_cell(cell)))
            hand_back.after(bake.cell_face_count(cell))
    return results


def finish_seams_task(path, fingerprint, options, seams, *batches):
    """One Dask task: [(seam cell, bytes)] for each of `seams`, from the
    batches that hold their cells (run on a worker)."""
    bake = _scene_on_this_worker(path, fingerprint, options)
    cell_bytes = {cell: data for batch in batches for cell, data in batch}
    results = []
    with _HandBack(bake) as hand_back:
        for seam in seams:
            cells = bake.seam_cells(seam)
            results.append((seam, bake.finish_seam(seam, [cell_bytes.pop(c) for c in cells])))
            hand_back.after(sum(bake.cell_face_count(c) for c in cells))
    return results


# A batch is at most the remaining work over this many per worker: the
# first batches large, few enough that Dask's per-task cost stays out of
# sight at a million cells; the last small, so no worker waits long for
# another's and a dead worker's batch costs little.
BATCHES_PER_WORKER = 8


def plan_tasks(seam_cells, cell_faces, workers):
    """Groups of seam cells, and each group's batches of cells, largest
    first: [(seams, [cells, ...])]. A group is one seam cell of at least
    the target cost (faces), or small ones together up to it. Groups come
    most faces first. A batch holds one group's cells up to the remaining
    work's share: the faces not yet in a batch over the target's divisor
    (a cell larger than that is a batch of its own). Batches so shrink
    towards the end of the plan, so the last tasks are short and no worker
    waits long for another's (a guided schedule); each group's batches
    come most faces first."""
    seam_faces = [sum(cell_faces[c] for c in cells) for cells in seam_cells]
    total = sum(seam_faces)
    divisor = max(1, workers * BATCHES_PER_WORKER)
    target = max(1, total // divisor)
    order = sorted(range(len(seam_cells)), key=lambda s: (-seam_faces[s], s))
    groups, seams, faces = [], [], 0
    for s in order:
        seams.append(s)
        faces += seam_faces[s]
        if faces >= target:
            groups.append(seams)
            seams, faces = [], 0
    if seams:
        groups.append(seams)
    groups.sort(key=lambda group: -sum(seam_faces[s] for s in group))
    plan, remaining = [], total
    for group in groups:
        cells = sorted((c for s in group for c in seam_cells[s]), key=lambda c: (-cell_faces[c], c))
        batches, batch, faces = [], [], 0
        for c in cells:
            if batch and faces + cell_faces[c] > max(1, remaining // divisor):
                batches.append(batch)
                remaining -= faces
                batch, faces = [], 0
            batch.append(c)
            faces += cell_faces[c]
        if batch:
            batches.append(batch)
            remaining -= faces
        batches.sort(key=lambda b: -sum(cell_faces[c] for c in b))
        plan.append((group, batches))
    return plan


def _peak_memory_mb():
    """This process's peak resident memory, MB (run on each worker).

    Linux's VmHWM, the peak of this process's own memory: getrusage's
    ru_maxrss is carried across exec, so a worker that a LocalCluster's
    nanny started by forking the client would report the client's memory
    at that moment (the client is preparing the scene then) as its own."""
    try:
        with open("/proc/self/status") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
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
        description="Decompose a scene on a Dask cluster (cells in batches, each group of islands' seam pass a "
                    "task); the output is the same as "
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
    # The client prepares the scene and writes it for the workers while they
    # start; once the tasks are out it lets the prepared stages go and maps
    # the file as the workers do (the finish reads only what it needs).
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
        prepared_at = time.monotonic()
        staged = local.pop("bake")
        fingerprint = local["fingerprint"]
        count = staged.cell_count()
        seam_count = staged.seam_count()
        workers = max(1, len(client.scheduler_info()["workers"]))
        plan = plan_tasks([staged.seam_cells(s) for s in range(seam_count)],
                          [staged.cell_face_count(c) for c in range(count)], workers)
        # By the module's name, so Dask pickles a reference to it, not the
        # function's globals (as it would for __main__'s under -m).
        module = importlib.import_module("hullcover.bake")
        tasks = sum(len(batches) for _, batches in plan)
        batch_futures, seam_futures, cells_of = [], [], {}
        for g, (seams, batches) in enumerate(plan):
            group_batches = []
            for cells in batches:
                # Largest first; a group's seam task before any later batch,
                # so its cells' bytes are freed as soon as they can be.
                f = client.submit(module.merge_batch_task, prepared, fingerprint, options, cells,
                                  key=f"hullcover-cells-{fingerprint}-{cells[0]}", priority=tasks - len(batch_futures),
                                  pure=False)
                cells_of[f.key] = cells
                group_batches.append(f)
                batch_futures.append(f)
            seam_futures.append(client.submit(module.finish_seams_task, prepared, fingerprint, options, seams,
                                              *group_batches, key=f"hullcover-seams-{fingerprint}-{g}",
                                              priority=2 * tasks, pure=False))
        staged = None
        staged = _hullcover.StagedBake.map(prepared, **dict(_map_options(options), threads=0))
        # Batches and seam tasks are taken as they finish, in one stream. A
        # batch's future is let go once it is counted: its bytes stay on the
        # worker only until its group's seam task has read them (Dask keeps,
        # and after a lost worker runs again, what a pending task needs). A
        # group's hulls are fetched as soon as they are made and the task
        # let go, so no worker holds finished groups until the last batch.
        done = 0
        seam_bytes = [None] * seam_count
        finished = as_completed(batch_futures + seam_futures)
        del batch_futures, group_batches, seam_futures
        for future in finished:
            cells = cells_of.get(future.key)
            if cells is None:
                for seam, data in future.result():
                    seam_bytes[seam] = data
                future.release()
                continue
            future.release()
            for cell in cells:
                done += 1
                if args.report_cells:
                    print(f"hullcover.bake: cell {cell} done ({done} of {count})", file=sys.stderr, flush=True)
            if not args.quiet and not args.report_cells:
                print(f"\rhullcover.bake: {done} of {count} cells", end="", file=sys.stderr, flush=True)
        if not args.quiet and not args.report_cells:
            print(file=sys.stderr)
        workers_seen = len(client.scheduler_info()["workers"])
        worker_peaks = sorted(client.run(module._peak_memory_mb).values())
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    baked = time.monotonic()
    try:
        d = staged.finish_seams(seam_bytes)
    finally:
        del staged
        if not args.prepared and os.path.exists(prepared):
            os.remove(prepared)
    assembled = time.monotonic()
    if args.world:
        d.write_world(args.world)
    if args.json:
        d.write_json(args.json, json.dumps({"input": args.scene, "seconds_including_import":
                                            time.monotonic() - start}))
    d.write_obj(args.output)
    return {"cells": count, "tasks": tasks + len(plan), "hulls": d.hull_count(), "workers": workers_seen,
            "worker_peak_mb": worker_peaks, "client_peak_mb": _peak_memory_mb(),
            "seconds_prepare": prepared_at - start, "seconds_cells": baked - prepared_at,
            "seconds_assembly": assembled - baked,
            "seconds_writing": time.monotonic() - assembled}


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
    print(f"{args.scene}: {figures['cells']} cells on {figures['workers']} workers ({figures['tasks']} tasks) -> "
          f"{figures['hulls']} hulls, "
          f"prepare {figures['seconds_prepare']:.1f} s, cells and seams {figures['seconds_cells']:.1f} s, "
          f"assembly {figures['seconds_assembly']:.1f} s, "
          f"writing {figures['seconds_writing']:.1f} s; wrote {args.output}")
    peaks = ", ".join(f"{mb:.0f}" for mb in figures["worker_peak_mb"])
    print(f"  peak memory: workers {peaks} MB, client {figures['client_peak_mb']:.0f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
