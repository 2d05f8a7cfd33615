"""hullcover: convex hulls that collide exactly like a scene's triangles.

    import numpy as np, hullcover
    d = hullcover.decompose(vertices, faces)          # (n, 3) float, (m, 3) int
    d.hulls          # list of dicts: vertices (k, 3), triangles (t, 3), faces (mesh faces covered)
    d.report         # the figures `hullcover decompose --json` writes, as a dict
    w = d.world()    # or hullcover.World.load("level.hcw")
    hit, t, hull, point, normal = w.cast_rays(origins, directions)
    touching = w.overlaps("capsule", centres, radius=0.4, half_height=0.5)
    verdict = hullcover.audit(vertices, faces, d)     # or a hull file's path
    verdict["clean"], verdict["front"]["lost"]

Every length is in scene units. Bad input raises ValueError with the
library's message; anything else RuntimeError. The decomposition and the
queries release the GIL, and decompose uses every core unless told
`threads=N` (its result is the same for any N).
"""

import json as _json

from ._hullcover import World  # noqa: F401  (re-exported)
from . import _hullcover

__all__ = ["decompose", "audit", "Decomposition", "World"]


class Decomposition:
    """The result of decompose(): hulls as numpy arrays and the report."""

    def __init__(self, core):
        self._core = core
        self._hulls = None
        self._report = None

    @property
    def hulls(self):
        """One dict per hull: 'vertices' (k, 3) float64, 'triangles' (t, 3)
        int32 (its facets fanned, indices into vertices), 'faces' (mesh faces
        it covers), 'planar', 'thickness'."""
        if self._hulls is None:
            self._hulls = self._core.hulls()
        return self._hulls

    @property
    def report(self):
        """Totals, options, merging counts and timings (dict)."""
        if self._report is None:
            self._report = _json.loads(self._core.report_json())
        return self._report

    @property
    def tolerance(self):
        return self._core.tolerance()

    def world(self):
        """A World of these hulls, in their order (hull i answers as i)."""
        return self._core.world()

    def write_obj(self, path):
        """The hull OBJ `hullcover decompose -o` writes (atomically)."""
        self._core.write_obj(str(path))

    def write_world(self, path):
        """The runtime file (.hcw) a game server loads (atomically)."""
        self._core.write_world(str(path))

    def __len__(self):
        return len(self.hulls)


def decompose(vertices, faces, *, tol=None, threads=0, cell_size=None, agent_radius=None,
              max_deviation=None, near_merge_distance=None, max_hull_vertices=255,
              max_hull_triangles=None):
    """Decompose a triangle mesh: vertices (n, 3), faces (m, 3) vertex
    indices, counter-clockwise seen from the front. Options as on the
    command line (`hullcover decompose --help`), lengths in scene units."""
    core = _hullcover.decompose(vertices, faces, tol=tol, threads=threads, cell_size=cell_size,
                                agent_radius=agent_radius, max_deviation=max_deviation,
                                near_merge_distance=near_merge_distance,
                                max_hull_vertices=max_hull_vertices,
                                max_hull_triangles=max_hull_triangles)
    return Decomposition(core)


def audit(vertices, faces, hulls, *, tol=None, agent_radius=None, max_deviation=None, proxies=3000,
          seed=1):
    """Audit hulls against the mesh (the strict definition (docs/definitions-and-proofs.md)): `hulls`
    is a Decomposition or the path of a hull file (OBJ, .hcw, .glb). Returns
    the figures `hullcover audit --json` writes, as a dict; 'clean' is the
    verdict."""
    target = hulls._core if isinstance(hulls, Decomposition) else str(hulls)
    return _json.loads(_hullcover.audit(vertices, faces, target, tol=tol, agent_radius=agent_radius,
                                        max_deviation=max_deviation, proxies=proxies, seed=seed))
