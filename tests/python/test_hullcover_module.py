"""The Python module on scenes built here: decompose, World queries, audit.

Run by ctest (python_module, unit tier) with PYTHONPATH at the build's
python/ folder, under the python3 the module was built for.
"""

import math

import numpy as np
import pytest

import hullcover


def cube(offset=(0.0, 0.0, 0.0), size=1.0):
    """A closed cube [0, size]^3 + offset, faces outward (counter-clockwise seen from outside)."""
    v = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float) * size
    v += np.asarray(offset, dtype=float)
    # Vertex index = 4x + 2y + z.
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    f = []
    for a, b, c, d in quads:
        f += [(a, b, c), (a, c, d)]
    return v, np.array(f, dtype=np.int64)


def two_cubes(gap=100.0):
    v1, f1 = cube()
    v2, f2 = cube(offset=(gap, 0.0, 0.0))
    return np.vstack([v1, v2]), np.vstack([f1, f2 + len(v1)])


def test_a_closed_cube_is_one_hull_covering_every_face():
    v, f = cube()
    d = hullcover.decompose(v, f)
    assert len(d) == 1
    hull = d.hulls[0]
    assert hull["vertices"].shape == (8, 3)
    assert sorted(hull["faces"].tolist()) == list(range(12))
    assert hull["triangles"].shape[1] == 3 and hull["triangles"].max() < 8
    assert d.report["totals"]["hulls"] == 1
    assert d.report["totals"]["faces"] == 12
    # Every hull vertex is a cube corner.
    for p in hull["vertices"]:
        assert np.min(np.abs(v - p).sum(axis=1)) < 1e-12


def test_far_apart_cubes_give_the_same_hulls_for_any_thread_count():
    v, f = two_cubes()
    one = hullcover.decompose(v, f, threads=1)
    two = hullcover.decompose(v, f, threads=2)
    assert len(one) == 2 and len(two) == 2
    assert one.report["merging"]["islands"] == 2
    for a, b in zip(one.hulls, two.hulls):
        assert np.array_equal(a["vertices"], b["vertices"])
        assert np.array_equal(a["faces"], b["faces"])
    # Each cube keeps the tolerance it has alone.
    assert one.tolerance == hullcover.decompose(*cube()).tolerance


def test_rays_overlaps_and_contacts_answer_in_arrays():
    v, f = cube()
    w = hullcover.decompose(v, f).world()
    assert len(w) == 1
    origins = np.array([[0.5, 0.5, 5.0], [3.0, 3.0, 5.0]])
    directions = np.array([[0.0, 0.0, -1.0], [0.0, 0.0, -1.0]])
    hit, t, hull, point, normal = w.cast_rays(origins, directions)
    assert hit.tolist() == [True, False]
    assert t[0] == pytest.approx(4.0, abs=1e-12) and math.isinf(t[1])
    assert hull.tolist() == [0, -1]
    assert np.allclose(point[0], [0.5, 0.5, 1.0]) and np.allclose(normal[0], [0.0, 0.0, 1.0])
    # Lines of sight: blocked exactly where a ray hits, and not by a hull
    # beyond max_distance (the cube's top is 4 below the first origin).
    assert w.rays_blocked(origins, directions).tolist() == [True, False]
    assert w.rays_blocked(origins, directions, max_distance=3.9).tolist() == [False, False]

    centres = np.array([[0.5, 0.5, 1.2], [0.5, 0.5, 2.0]])
    assert w.overlaps("sphere", centres, radius=0.3).tolist() == [True, False]
    touching, depth, which, normals, _ = w.contacts("sphere", centres, radius=0.3)
    assert touching.tolist() == [True, False]
    assert depth[0] == pytest.approx(0.1, abs=1e-9) and depth[1] == 0.0
    assert which.tolist() == [0, -1]
    assert np.allclose(normals[0], [0.0, 0.0, 1.0])
    # A capsule along z standing 0.25 clear of the top still misses; 0.05 into it touches.
    assert w.overlaps("capsule", np.array([[0.5, 0.5, 1.75], [0.5, 0.5, 1.45]]), radius=0.2,
                      half_height=0.3).tolist() == [False, True]


def test_the_runtime_file_round_trips(tmp_path):
    v, f = two_cubes()
    d = hullcover.decompose(v, f)
    path = tmp_path / "cubes.hcw"
    d.write_world(path)
    loaded = hullcover.World.load(str(path))
    origins = np.array([[0.5, 0.5, 3.0], [100.5, 0.5, 3.0], [50.0, 0.5, 3.0]])
    directions = np.tile([0.0, 0.0, -1.0], (3, 1))
    a = d.world().cast_rays(origins, directions)
    b = loaded.cast_rays(origins, directions)
    for x, y in zip(a, b):
        assert np.array_equal(x, y)
    assert a[0].tolist() == [True, True, False]


def test_the_audit_says_clean_for_hullcovers_hulls_and_names_lost_space_in_others(tmp_path):
    # An open floor, facing up: a box standing on it takes its front space.
    floor_v = np.array([[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]], dtype=float)
    floor_f = np.array([[0, 1, 2], [0, 2, 3]])
    d = hullcover.decompose(floor_v, floor_f)
    verdict = hullcover.audit(floor_v, floor_f, d, proxies=300)
    assert verdict["clean"] is True
    assert verdict["front"]["rays"] > 0 and verdict["front"]["lost"] == 0

    box = tmp_path / "box.obj"
    corners = [(x, y, z) for x in (1, 3) for y in (1, 3) for z in (-1, 1)]
    lines = ["o box"] + ["v %g %g %g" % c for c in corners]
    for a, b, c, e in [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]:
        lines.append("f %d %d %d %d" % (a, b, c, e))
    box.write_text("\n".join(lines) + "\n")
    bad = hullcover.audit(floor_v, floor_f, str(box), proxies=300)
    assert bad["clean"] is False
    assert "front_space_lost" in bad["findings"]
    assert bad["front"]["lost"] > 0


def test_bad_input_raises_value_error_with_the_reason():
    v, f = cube()
    with pytest.raises(ValueError, match="does not exist"):
        hullcover.decompose(v, np.vstack([f, [[0, 1, 99]]]))
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        hullcover.decompose(v[:, :2], f)
    bad = v.copy()
    bad[0, 0] = np.nan
    with pytest.raises(ValueError):
        hullcover.decompose(bad, f)
    with pytest.raises(ValueError):
        hullcover.decompose(v, f, threads=-1)
    w = hullcover.decompose(v, f).world()
    with pytest.raises(ValueError):
        w.cast_rays(np.zeros((1, 3)), np.zeros((1, 3)))
    with pytest.raises(ValueError, match="shape"):
        w.overlaps("cone", np.zeros((1, 3)), radius=1.0)
