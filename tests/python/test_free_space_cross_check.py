"""The independent, sampled cross-check (scripts/cross_check_free_space.py):
first that it sees what the strict definition says on scenes built here
(a hull in a room's air, one beside an open edge, enclosed space under a
one-sided table top), then that hullcover's coverings of shared scenes lose
none of its rays.

Run by ctest with PYTHONPATH at the build's python/ folder and
HULLCOVER_SOURCE_DIR (for scripts/); the shared-scene tests (names with
"shared") are the scene tier and skip when HULLCOVER_SHARED_DIR has no scenes.
"""

import os
import sys

import numpy as np
import pytest

import hullcover

sys.path.insert(0, os.path.join(os.environ.get("HULLCOVER_SOURCE_DIR", ""), "scripts"))
import cross_check_free_space as cross_check  # noqa: E402


def quad(corners):
    """Two triangles of a quad given counter-clockwise seen from its front."""
    return [(corners[0], corners[1], corners[2]), (corners[0], corners[2], corners[3])]


def box(low, high, outward=True):
    """Vertices and triangles of an axis-aligned box, faces outward or inward."""
    v = np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])])
    # Vertex index = 4x + 2y + z; each quad counter-clockwise seen from outside.
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    f = [t for q in quads for t in quad(q)]
    f = np.array(f, dtype=np.int64)
    return v.astype(float), (f if outward else f[:, ::-1].copy())


def plate(z, low=(0.0, 0.0), high=(1.0, 1.0), up=True):
    v = np.array([[low[0], low[1], z], [high[0], low[1], z], [high[0], high[1], z], [low[0], high[1], z]])
    f = np.array(quad((0, 1, 2, 3)), dtype=np.int64)
    return v, (f if up else f[:, ::-1].copy())


def joined(*parts):
    vertices, faces, groups = [], [], []
    for g, (v, f) in enumerate(parts):
        faces.append(f + sum(len(p) for p in vertices))
        vertices.append(v)
        groups.append(np.full(len(f), g))
    return np.vstack(vertices), np.vstack(faces), np.concatenate(groups)


def covering_arrays(decomposition):
    parts = [(h["vertices"], h["triangles"]) for h in decomposition.hulls]
    return joined(*parts)


def test_a_hull_in_a_rooms_air_loses_front_rays_and_the_covering_alone_none():
    room_v, room_f = box((0, 0, 0), (4, 4, 3), outward=False)
    d = hullcover.decompose(room_v, room_f)
    hv, hf, hg = covering_arrays(d)
    clean = cross_check.check_covering(room_v, room_f, hv, hf, hg, d.tolerance, rays=2000)
    assert clean.lost == [] and clean.edges_inside == [] and clean.uncovered == []
    assert clean.edges == 18 and clean.surface_points == 2000 + 12 + 8  # ray origins, centroids, corners
    assert clean.enclosed == 0  # every ray of a closed room ends on a wall's front

    # Without its first hull, the faces that hull covered are on no hull.
    rest = hg != hg.min()
    missing = cross_check.check_covering(room_v, room_f, hv, hf[rest], hg[rest], d.tolerance, rays=2000)
    assert missing.lost == [] and len(missing.uncovered) > 0

    crate_v, crate_f = box((1.5, 1.5, 1.0), (2.5, 2.5, 2.0))
    hv2, hf2, _ = joined((hv, hf), (crate_v, crate_f))
    hg2 = np.concatenate([hg, np.full(len(crate_f), 1000)])  # the crate's hull is group 1000
    lost = cross_check.check_covering(room_v, room_f, hv2, hf2, hg2, d.tolerance, rays=2000).lost
    assert len(lost) > 0
    assert {kind for kind, *_ in lost} == {"front"}
    assert {group for _, _, _, _, group, *_ in lost} == {1000}


def test_a_hull_beside_an_open_edge_loses_only_opening_rays():
    v, f = plate(0.0)
    hull_v, hull_f = box((1.1, 0.2, -0.05), (1.5, 0.8, 0.05))  # in the plate's plane, past its edge x = 1
    result = cross_check.check_covering(v, f, hull_v, hull_f, np.zeros(len(hull_f), dtype=np.int64), 1e-5,
                                        rays=2000)
    assert result.opening_rays == 2000
    assert len(result.lost) > 0
    assert {kind for kind, *_ in result.lost} == {"opening"}
    # Each leaves through the edge at x = 1, outward.
    for _, _, origin, direction, *_ in result.lost:
        assert origin[0] == pytest.approx(1.0)
        assert direction[0] > 0.99


def test_a_hull_round_a_plates_edge_holds_that_edge():
    v, f = plate(0.0)
    hull_v, hull_f = box((0.9, 0.2, -0.05), (1.2, 0.8, 0.05))  # across the edge x = 1
    result = cross_check.check_covering(v, f, hull_v, hull_f, np.zeros(len(hull_f), dtype=np.int64), 1e-5,
                                        rays=500)
    assert result.edges == 5
    assert len(result.edges_inside) == 1
    (p0, p1), _ = result.edges_inside[0]
    assert p0[0] == 1.0 and p1[0] == 1.0


def test_space_under_a_one_sided_table_top_is_enclosed_and_under_a_downward_face_open():
    floor = plate(0.0, (-2.0, -2.0), (3.0, 3.0))
    under = box((0.3, 0.3, 0.5), (0.7, 0.7, 0.99))  # a hull below the top, above the floor
    group = np.zeros(len(under[1]), dtype=np.int64)
    for up, expect_lost in ((True, False), (False, True)):
        v, f, _ = joined(floor, plate(1.0, (0.25, 0.25), (0.75, 0.75), up=up))
        result = cross_check.check_covering(v, f, under[0], under[1], group, 1e-4, rays=4000)
        assert (len(result.lost) > 0) == expect_lost, up
        if up:
            assert result.enclosed > 0  # the floor's rays under the top end on its back


def test_the_rim_of_a_double_sided_sheet_is_open_and_a_flipped_neighbours_edge_is_not():
    v = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0]])
    normals = lambda f: np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])  # noqa: E731
    # Back to back: the same triangle both ways; every edge is a rim.
    sheet = np.array([[0, 1, 2], [1, 0, 2]])
    n = normals(sheet)
    assert len(cross_check.open_edge_uses(v, sheet, np.arange(2), n / np.linalg.norm(n, axis=1)[:, None])) == 6
    # Side by side in one plane, the second listing the shared edge 0-1 the
    # same way (so it faces down): that edge is closed, the four others open.
    flipped = np.array([[0, 1, 2], [0, 1, 3]])
    n = normals(flipped)
    uses = cross_check.open_edge_uses(v, flipped, np.arange(2), n / np.linalg.norm(n, axis=1)[:, None])
    assert len(uses) == 4 and (0, 0) not in uses and (1, 0) not in uses


def test_a_point_past_a_thin_hulls_sharp_edge_is_far_from_it_though_near_every_plane():
    # A prism on a sliver 10 long and 0.2 wide at its far end: its tip at the
    # origin is 0.01 radians sharp either side.
    v = np.array([[0, 0, 0], [10, 0.1, 0], [10, -0.1, 0], [0, 0, 1], [10, 0.1, 1], [10, -0.1, 1]], dtype=float)
    f = np.array([[0, 1, 2], [3, 5, 4], [0, 4, 1], [0, 3, 4], [1, 5, 2], [1, 4, 5], [2, 3, 0], [2, 5, 3]])
    tol = 0.01
    [hull] = cross_check.hulls_of(v, f, np.zeros(len(f), dtype=np.int64), tol)
    past_the_tip = np.array([-0.5, 0.0, 0.5])  # 0.5 from the hull
    assert 0.0 < np.max(hull.normals @ past_the_tip - hull.offsets) < tol  # yet within tol of every plane
    assert not cross_check.within_tol_of_surface(hull, past_the_tip, tol)
    assert cross_check.within_tol_of_surface(hull, np.array([5.0, 0.0, 1.005]), tol)  # just above the top
    assert cross_check.within_tol_of_surface(hull, np.array([5.0, 0.0, 0.995]), tol)  # just under it
    assert not cross_check.within_tol_of_surface(hull, np.array([5.0, 0.0, 0.5]), tol)  # deep inside


def test_a_concave_polygon_is_cut_into_ears_that_keep_its_winding(tmp_path):
    # An L, counter-clockwise seen from +z; a fan from its first corner
    # would fold a triangle over the notch.
    path = tmp_path / "l.obj"
    corners = [(2, 2), (0, 2), (0, 0), (1, 0), (1, 1), (2, 1)]
    path.write_text("".join(f"v {x} {y} 0\n" for x, y in corners) + "f 1 2 3 4 5 6\n")
    positions, triangles, _ = cross_check.read_obj(str(path))
    assert len(triangles) == 4
    a = positions[triangles[:, 0]]
    normals = np.cross(positions[triangles[:, 1]] - a, positions[triangles[:, 2]] - a)
    assert np.all(normals[:, 2] > 0)
    assert np.sum(normals[:, 2]) / 2 == pytest.approx(3.0)


def shared_scene(name):
    folder = os.path.join(os.environ.get("HULLCOVER_SHARED_DIR", ""), "data", "scenes")
    path = os.path.join(folder, name)
    if not os.path.isfile(path):
        pytest.skip(f"no shared scene {path} (a clone without ../shared): cross-check on shared scenes skipped")
    return path


@pytest.mark.parametrize("name", ["recast-nav_test.obj", "recast-undulating.obj"])
def test_shared_scene_covering_loses_no_drawn_ray(name):
    positions, triangles, _ = cross_check.read_obj(shared_scene(name))
    d = hullcover.decompose(positions, triangles)
    hv, hf, hg = covering_arrays(d)
    result = cross_check.check_covering(positions, triangles, hv, hf, hg, d.tolerance, rays=6000, seed=3)
    assert result.front_rays == 6000
    assert result.lost == [], result.lost[:3]
