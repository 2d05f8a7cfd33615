"""The distributed bake (python3 -m hullcover.bake) on Dask, on loopback.

The fault test starts a dask-scheduler and two dask-worker processes, starts
a bake of a many-cell scene, kills one worker with SIGKILL once cells have
come back, and requires the bake to finish with output byte-identical to the
scene decomposed in one call on this machine. Run by ctest (python_bake) with
PYTHONPATH at the build's python/ folder; skipped where Debian's
python3-distributed is missing.
"""

import json
import os
import signal
import socket
import subprocess
import sys
import time

import numpy as np
import pytest

distributed = pytest.importorskip("distributed", reason="python3-distributed (Debian) is not installed")

from hullcover import _hullcover  # noqa: E402

# Cells of this side cut the terrain below into about a hundred cells.
CELL_SIZE = 4.0
DEADLINE_SECONDS = 300


def write_terrain(path, n=64):
    """A rolling terrain of 2 n^2 triangles over [-16, 16]^2 (y up): curved
    everywhere, so every cell has real merging to do."""
    xs = np.linspace(-16.0, 16.0, n + 1)
    with open(path, "w") as f:
        for x in xs:
            for z in xs:
                y = 0.6 * np.sin(0.9 * x) * np.cos(0.7 * z) + 0.05 * x
                f.write("v %.17g %.17g %.17g\n" % (x, y, z))
        for i in range(n):
            for j in range(n):
                a, b = i * (n + 1) + j + 1, (i + 1) * (n + 1) + j + 1
                f.write(f"f {a} {a + 1} {b + 1}\nf {a} {b + 1} {b}\n")


def without_timings(report):
    """The JSON report less what differs between runs: timings."""
    if isinstance(report, dict):
        return {k: without_timings(v) for k, v in report.items() if "seconds" not in k}
    if isinstance(report, list):
        return [without_timings(v) for v in report]
    return report


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    """The scene, and the one-machine reference: OBJ, .hcw and JSON bytes."""
    folder = tmp_path_factory.mktemp("bake")
    path = str(folder / "terrain.obj")
    write_terrain(path)
    reference = _hullcover.decompose_file(path, cell_size=CELL_SIZE)
    files = {name: str(folder / f"reference.{name}") for name in ("obj", "hcw", "json")}
    reference.write_obj(files["obj"])
    reference.write_world(files["hcw"])
    reference.write_json(files["json"], json.dumps({"input": path}))
    cells = _hullcover.StagedBake.load(path, cell_size=CELL_SIZE).cell_count()
    assert cells > 50
    return path, files, cells


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for_port(port, process):
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        if process.poll() is not None:
            raise RuntimeError("dask-scheduler exited early")
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=1):
                return
        except OSError:
            time.sleep(0.2)
    raise RuntimeError("dask-scheduler did not listen")


def bake_command(path, out, *extra):
    return [sys.executable, "-m", "hullcover.bake", path, "-o", out + ".obj", "--world", out + ".hcw",
            "--json", out + ".json", "--cell-size", str(CELL_SIZE), *extra]


def assert_same_as_reference(out, files):
    for name in ("obj", "hcw"):
        with open(out + "." + name, "rb") as a, open(files[name], "rb") as b:
            assert a.read() == b.read(), f"the bake's .{name} differs from the one-machine decomposition"
    with open(out + ".json") as a, open(files["json"]) as b:
        assert without_timings(json.load(a)) == without_timings(json.load(b))


def test_the_bake_survives_a_worker_killed_mid_bake(scene, tmp_path):
    path, files, cells = scene
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    processes = []
    try:
        scheduler = subprocess.Popen(["dask-scheduler", "--host", "127.0.0.1", "--port", str(port),
                                      "--no-dashboard"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        processes.append(scheduler)
        wait_for_port(port, scheduler)
        workers = [subprocess.Popen(["dask-worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                                     "--name", f"worker-{k}"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) for k in range(2)]
        processes += workers
        with distributed.Client(address, timeout=60) as client:
            client.wait_for_workers(2, timeout=60)
        out = str(tmp_path / "baked")
        bake = subprocess.Popen(bake_command(path, out, "--scheduler", address, "--report-cells"),
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        processes.append(bake)
        done_before_kill = done_after_kill = 0
        total = None
        killed = False
        deadline = time.monotonic() + DEADLINE_SECONDS
        for line in bake.stderr:
            assert time.monotonic() < deadline, "the bake took too long"
            if "done (" not in line:
                continue
            total = int(line.rsplit(" of ", 1)[1].rstrip(")\n"))
            if killed:
                done_after_kill += 1
                continue
            done_before_kill += 1
            if done_before_kill == 3:
                workers[0].send_signal(signal.SIGKILL)
                workers[0].wait()
                killed = True
        assert bake.wait(timeout=DEADLINE_SECONDS) == 0, bake.stdout.read()
        assert killed and total == cells
        # Mid-bake: most cells came back after the kill (the survivor ran
        # them, and any the dead worker held were run again).
        assert done_after_kill == total - done_before_kill
        assert done_after_kill > total // 2
        assert_same_as_reference(out, files)
    finally:
        for p in reversed(processes):
            if p.poll() is None:
                p.kill()
                p.wait()


def test_the_default_local_cluster_gives_the_same_covering(scene, tmp_path):
    path, files, cells = scene
    out = str(tmp_path / "local")
    run = subprocess.run(bake_command(path, out, "--workers", "2", "-q"), capture_output=True, text=True,
                         timeout=DEADLINE_SECONDS)
    assert run.returncode == 0, run.stderr
    assert f"{cells} cells on 2 workers" in run.stdout
    assert "peak memory: workers" in run.stdout
    assert_same_as_reference(out, files)
    # The temporary prepared scene file is gone.
    assert not [name for name in os.listdir(tmp_path) if name.endswith(".hcp")]


def test_a_kept_prepared_file_names_its_scene_and_a_worker_refuses_another(scene, tmp_path):
    path, files, cells = scene
    out = str(tmp_path / "kept")
    prepared = str(tmp_path / "terrain.hcp")
    run = subprocess.run(bake_command(path, out, "--workers", "2", "-q", "--prepared", prepared),
                         capture_output=True, text=True, timeout=DEADLINE_SECONDS)
    assert run.returncode == 0, run.stderr
    assert_same_as_reference(out, files)
    from hullcover import bake
    fingerprint = bake._fingerprint(prepared)
    assert len(fingerprint) == 16
    options = {"tol": None, "cell_size": CELL_SIZE, "agent_radius": None, "max_deviation": None, "threads": 1}
    batch = bake.merge_batch_task(prepared, fingerprint, options, [1, 0])
    assert [cell for cell, _ in batch] == [1, 0] and all(len(data) > 0 for _, data in batch)
    with pytest.raises(ValueError, match="not the client's prepared scene"):
        bake.merge_batch_task(prepared, "0" * 16, options, [0])
    # The terrain is one island: one seam cell, finished from every cell.
    every = bake.merge_batch_task(prepared, fingerprint, options, list(range(2, cells))) + batch
    seams = bake.finish_seams_task(prepared, fingerprint, options, [0], every[:5], every[5:])
    assert [seam for seam, _ in seams] == [0] and len(seams[0][1]) > 0
    with pytest.raises(KeyError):
        bake.finish_seams_task(prepared, fingerprint, options, [0], every[1:])


def test_tasks_are_planned_largest_first_and_hold_each_cell_once():
    from hullcover import bake
    # Seam cells of 1, 2, 40 and 3 cells; cell c has c + 1 faces.
    seam_cells = [[0], [1, 2], list(range(3, 43)), [43, 44, 45]]
    faces = [c + 1 for c in range(46)]
    plan = bake.plan_tasks(seam_cells, faces, workers=2)
    target = sum(faces) // (2 * bake.BATCHES_PER_WORKER)
    seen_seams = [s for group, _ in plan for s in group]
    assert sorted(seen_seams) == [0, 1, 2, 3]
    seen_cells = [c for _, batches in plan for batch in batches for c in batch]
    assert sorted(seen_cells) == list(range(46))
    for group, batches in plan:
        group_cells = {c for s in group for c in seam_cells[s]}
        for batch in batches:
            assert set(batch) <= group_cells
            assert len(batch) == 1 or sum(faces[c] for c in batch) <= target
    # Guided: a batch of several cells holds at most its share of the work
    # left from it on, so the plan's last batches are its smallest.
    divisor = 2 * bake.BATCHES_PER_WORKER
    costs = [sum(faces[c] for c in batch) for _, batches in plan for batch in batches]
    for i, batch in enumerate(batch for _, batches in plan for batch in batches):
        assert len(batch) == 1 or costs[i] <= max(1, sum(costs[i:]) // divisor)
    assert costs[-1] < costs[0] / 4
    # The largest seam cell's group first, its batches largest first.
    assert plan[0][0] == [2]
    costs = [sum(faces[c] for c in batch) for batch in plan[0][1]]
    assert costs[0] == max(costs)
    assert len(plan[0][1]) > 1


def test_bad_input_exits_2_with_a_message(tmp_path):
    run = subprocess.run([sys.executable, "-m", "hullcover.bake", str(tmp_path / "absent.obj"), "-o",
                          str(tmp_path / "x.obj")], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2
    assert "no such file" in run.stderr
    assert not os.path.exists(tmp_path / "x.obj")
