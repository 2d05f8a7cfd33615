#!/usr/bin/env python3
"""An independent, sampled cross-check of a covering against the strict
free-space definition (docs/definitions-and-proofs.md).

It shares no code with hullcover: numpy only, its own OBJ reading and
triangulation, its own ray-triangle and ray-hull tests. Ray origins are drawn
at random (seeded) on every face and every open edge, so it can find space
lost between the audit's own rays. It can never prove a covering clean: that
is the audit's job (`hullcover audit`), which judges every face and edge.
Each drawn ray is decided exactly:

- front rays: from a point of a face along its normal (every face gets one,
  the rest go by area);
- opening rays: from a point of an open edge (used by one face, or the rim
  of two faces back to back), outward in the face's plane and tilted by
  OPENING_TILT_SINE to either side;
- a ray runs from `stand_off` tol off its start (default a thousandth of
  tol) to its first mesh hit, or forever: it meets faces from there (the
  audit from 2 tol, judging hulls from the surface). Faces it runs along are
  not met. It is enclosed, and skipped, when every face it meets within tol
  of the first hit is met from behind;
- an open ray is lost where its segment enters a hull shrunk by tol (its
  planes moved in by tol); a hull thinner than 2 tol has no inside.

Usage: cross_check_free_space.py SCENE.obj HULLS.obj [--tol T] [--rays N]
Exit 0 when nothing is found, 1 when a ray is lost, an edge lies in a hull or a
point of a face on no hull, 2 on bad input.
"""

import argparse
import sys
from dataclasses import dataclass, field

import numpy as np

OPENING_TILT_SINE = 0.1  # the definition's opening tilt: hullcover's kOpeningTiltSine
DEFAULT_STAND_OFF_IN_TOLERANCES = 1e-3
PARALLEL_SINE = 1e-9  # |normal . direction| at or below this: the ray runs along the face
TRIANGLES_PER_BLOCK = 4096  # keeps the rays x triangles arrays to a few MB
RAYS_PER_BLOCK = 64


def newell_normal(points):
    """The area-weighted normal of a polygon, however it bends."""
    following = np.roll(points, -1, axis=0)
    return np.array([
        np.sum((points[:, 1] - following[:, 1]) * (points[:, 2] + following[:, 2])),
        np.sum((points[:, 2] - following[:, 2]) * (points[:, 0] + following[:, 0])),
        np.sum((points[:, 0] - following[:, 0]) * (points[:, 1] + following[:, 1])),
    ])


def triangulate(positions, polygon):
    """Triangles of a polygon (vertex indices), winding kept: a fan for a
    convex one, ears clipped for a concave one, as Assimp (which hullcover
    reads files with) does, so a concave polygon gives no folded triangles."""
    if len(polygon) == 3:
        return [list(polygon)]
    points = np.array([positions[i] for i in polygon])
    normal = newell_normal(points)
    axis = int(np.argmax(np.abs(normal)))
    flat = points[:, [k for k in range(3) if k != axis]]
    if (normal[axis] < 0) != (axis == 1):  # dropping y swaps the handedness of (z, x) into (x, z)
        flat = flat[:, ::-1]

    def turn(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    def inside(q, i, j, m):
        return turn(flat[i], flat[j], flat[q]) >= 0 and turn(flat[j], flat[m], flat[q]) >= 0 and \
            turn(flat[m], flat[i], flat[q]) >= 0

    left = list(range(len(polygon)))
    out = []
    while len(left) > 3:
        for k in range(1, len(left) + 1):
            i, j, m = left[k - 1], left[k % len(left)], left[(k + 1) % len(left)]
            if turn(flat[i], flat[j], flat[m]) <= 0 or any(inside(q, i, j, m) for q in left if q not in (i, j, m)):
                continue
            out.append([polygon[i], polygon[j], polygon[m]])
            left.remove(j)
            break
        else:  # no ear (a degenerate or self-crossing polygon): a fan of what is left
            out.extend([polygon[left[0]], polygon[left[k]], polygon[left[k + 1]]] for k in range(1, len(left) - 1))
            return out
    out.append([polygon[q] for q in left])
    return out


def read_obj(path):
    """Positions, triangles and, per triangle, the index of its `o`/`g` group (-1 before any)."""
    positions, triangles, groups = [], [], []
    group = -1
    with open(path, "r", encoding="utf-8", errors="replace") as stream:
        for line in stream:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                positions.append([float(c) for c in parts[1:4]])
            elif parts[0] in ("o", "g"):
                group += 1
            elif parts[0] == "f":
                polygon = []
                for token in parts[1:]:
                    i = int(token.split("/")[0])
                    polygon.append(i - 1 if i > 0 else len(positions) + i)
                for triangle in triangulate(positions, polygon):
                    triangles.append(triangle)
                    groups.append(group)
    return (np.array(positions, dtype=np.float64).reshape(-1, 3), np.array(triangles, dtype=np.int64).reshape(-1, 3),
            np.array(groups, dtype=np.int64))


def tolerance_in_header(hull_path):
    """The tolerance hullcover writes in a covering's first line, if there."""
    with open(hull_path, "r", encoding="utf-8", errors="replace") as stream:
        first = stream.readline()
    if "tolerance" not in first:
        return None
    return float(first.rsplit("tolerance", 1)[1].split()[0])


@dataclass
class Hull:
    normals: np.ndarray  # outward unit normals of its planes
    offsets: np.ndarray  # the hull is every x with normals @ x <= offsets
    low: np.ndarray  # box corners
    high: np.ndarray
    group: int  # the hull's group in its file (hull_N is group N)
    corners: np.ndarray = None  # its triangles' corners, (k, 3, 3): its surface


def hulls_of(positions, triangles, groups, tol):
    """Each hull as planes: a solid's are its triangles' (outward whatever
    their winding: its centre lies behind each); a flat polygon's are its
    plane both ways and a side plane on each outline edge (shrunk by tol it
    is empty: a flat hull has no inside)."""
    hulls = []
    for group in np.unique(groups):
        tris = triangles[groups == group]
        points = positions[np.unique(tris)]
        centre = points.mean(axis=0)
        a = positions[tris[:, 0]]
        areas = np.cross(positions[tris[:, 1]] - a, positions[tris[:, 2]] - a)
        lengths = np.linalg.norm(areas, axis=1)
        kept = lengths > 0
        if not kept.any():
            continue
        normals = areas[kept] / lengths[kept, None]
        offsets = np.einsum("ij,ij->i", normals, a[kept])
        flip = normals @ centre > offsets
        normals[flip] *= -1
        offsets[flip] *= -1
        if np.all(np.abs(normals @ normals[0]) > 1 - 1e-9):
            # A flat polygon (every triangle in one plane, either way): that
            # plane both ways, and the outline of its triangles facing the
            # way its largest does.
            widest = int(np.argmax(lengths))
            plane = areas[widest] / lengths[widest]
            edges = {(t[k], t[(k + 1) % 3]) for t in tris[areas @ plane > 0] for k in range(3)}
            sides, side_offsets = [], []
            for i, j in edges:
                side = np.cross(positions[j] - positions[i], plane)
                if (j, i) not in edges and np.linalg.norm(side) > 0:  # on the outline, and not a point
                    sides.append(side / np.linalg.norm(side))
                    side_offsets.append(sides[-1] @ positions[i])
            normals = np.array([plane, -plane] + sides)
            offsets = np.array([plane @ centre, -plane @ centre] + side_offsets)
        hulls.append(Hull(normals, offsets, points.min(axis=0), points.max(axis=0), int(group), positions[tris]))
    return hulls


def distance_to_triangles(p, corners):
    """Distance from point p to the nearest of the triangles `corners`
    ((k, 3, 3) array): to the plane where p projects inside a triangle, else
    to its nearest side. Exact up to rounding."""
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]

    def to_segments(s0, s1):
        d = s1 - s0
        length2 = np.einsum("ij,ij->i", d, d)
        s = np.clip(np.einsum("ij,ij->i", p - s0, d) / np.where(length2 > 0, length2, 1.0), 0.0, 1.0)
        return np.linalg.norm(p - (s0 + s[:, None] * d), axis=1)

    nearest = np.minimum(np.minimum(to_segments(a, b), to_segments(b, c)), to_segments(c, a))
    ab, ac, ap = b - a, c - a, p - a
    d00, d01, d11 = (np.einsum("ij,ij->i", x, y) for x, y in ((ab, ab), (ab, ac), (ac, ac)))
    d20, d21 = np.einsum("ij,ij->i", ap, ab), np.einsum("ij,ij->i", ap, ac)
    denominator = d00 * d11 - d01 * d01
    flat = denominator > 0
    safe = np.where(flat, denominator, 1.0)
    v, w = (d11 * d20 - d01 * d21) / safe, (d00 * d21 - d01 * d20) / safe
    inside = flat & (v >= 0) & (w >= 0) & (v + w <= 1)
    normal = np.cross(ab, ac)
    norm = np.linalg.norm(normal, axis=1)
    to_plane = np.abs(np.einsum("ij,ij->i", ap, normal)) / np.where(norm > 0, norm, 1.0)
    return float(np.min(np.where(inside, np.minimum(to_plane, nearest), nearest)))


def within_tol_of_surface(hull, p, tol):
    """Whether p lies within tol of the hull's boundary: inside, no deeper
    than tol (the nearest plane is the nearest facet); outside, by the
    distance to its triangles (not its planes alone, which past a sharp
    edge pass a point far from the hull)."""
    outside = np.max(hull.normals @ p - hull.offsets)
    if outside <= 0.0:
        return -outside <= tol
    return outside <= tol and distance_to_triangles(p, hull.corners) <= tol


def first_hits(origins, dirs, a, e1, e2, normals, t_min, tol):
    """Per ray: the first hit distance (inf for none) and whether every face
    met within tol of it is met from behind (Moller-Trumbore; random rays
    meet edges with probability zero)."""
    blocks = []
    for start in range(0, len(a), TRIANGLES_PER_BLOCK):
        end = start + TRIANGLES_PER_BLOCK
        sa, s1, s2 = a[start:end], e1[start:end], e2[start:end]
        p = np.cross(dirs[:, None, :], s2[None, :, :])
        det = np.einsum("rfk,fk->rf", p, s1)
        along = np.abs(dirs @ normals[start:end].T) <= PARALLEL_SINE
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = 1.0 / det
            s = origins[:, None, :] - sa[None, :, :]
            u = np.einsum("rfk,rfk->rf", s, p) * inv
            q = np.cross(s, s1[None, :, :])
            v = np.einsum("rk,rfk->rf", dirs, q) * inv
            t = np.einsum("fk,rfk->rf", s2, q) * inv
            met = ~along & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > t_min)
        blocks.append(np.where(met, t, np.inf))
    t_all = np.concatenate(blocks, axis=1)
    first = t_all.min(axis=1)
    met_from_front = (t_all <= (first + tol)[:, None]) & (dirs @ normals.T <= 0)
    return first, np.isfinite(first) & ~met_from_front.any(axis=1)


def segment_inside(hull, origin, direction, enter, leave, tol):
    """The stretch [enter, leave] of the ray inside the hull shrunk by tol, if any."""
    start = hull.offsets - tol - hull.normals @ origin  # > 0: behind the plane moved in
    rate = hull.normals @ direction
    if np.any((rate == 0) & (start <= 0)):
        return None
    with np.errstate(divide="ignore", invalid="ignore"):
        t = start / rate
    if np.any(rate < 0):
        enter = max(enter, float(np.max(t[rate < 0])))
    if np.any(rate > 0):
        leave = min(leave, float(np.min(t[rate > 0])))
    return (enter, leave) if enter < leave else None


@dataclass
class CheckResult:
    front_rays: int = 0
    opening_rays: int = 0
    enclosed: int = 0
    hulls: int = 0
    lost: list = field(default_factory=list)  # (kind, face, origin, direction, hull group, enter, leave, first hit)
    edges: int = 0
    edges_inside: list = field(default_factory=list)  # (edge's two positions, hull group)
    surface_points: int = 0
    uncovered: list = field(default_factory=list)  # (face, point)


def open_edge_uses(positions, triangles, faces, normals):
    """(face, corner) of each open edge: used by one face, or by two faces
    back to back (the rim of a double-sided sheet: opposite normals, and
    each face's far corner on the same side of the edge). Two faces side by
    side in one plane facing opposite ways (a flipped triangle) close their
    edge."""
    uses = []
    for edge_uses in edge_uses_by_ends(positions, triangles, faces).values():
        if len(edge_uses) == 1:
            uses.append(edge_uses[0])
        elif len(edge_uses) == 2 and np.dot(normals[edge_uses[0][0]], normals[edge_uses[1][0]]) < -1 + 1e-9 \
                and np.dot(edge_inward(positions, triangles, *edge_uses[0]),
                           edge_inward(positions, triangles, *edge_uses[1])) > 0:
            uses.extend(edge_uses)
    return uses


def edge_inward(positions, triangles, f, k):
    """Across edge k of face f (from corner k), in the face's plane, toward
    its far corner: the way into the face (not of unit length)."""
    p0, p1 = positions[triangles[f, k]], positions[triangles[f, (k + 1) % 3]]
    along = (p1 - p0) / np.linalg.norm(p1 - p0)
    inner = positions[triangles[f, (k + 2) % 3]] - p0
    return inner - (inner @ along) * along


def edge_uses_by_ends(positions, triangles, faces):
    """Each edge's (face, corner) uses, keyed by its two ends welded as
    float32, the files' own precision (an exporter may write one corner twice
    with digits differing in the 16th place)."""
    welded = [tuple(p) for p in positions.astype(np.float32)]
    uses_of = {}
    for f in faces:
        for k in range(3):
            ends = (welded[triangles[f, k]], welded[triangles[f, (k + 1) % 3]])
            uses_of.setdefault((min(ends), max(ends)), []).append((f, k))
    return uses_of


class BoxIndex:
    """Hull boxes, for the hulls a segment may meet."""

    def __init__(self, hulls, grow):
        self.low = np.array([h.low for h in hulls]) - grow
        self.high = np.array([h.high for h in hulls]) + grow

    def along(self, origin, direction, enter, leave):
        with np.errstate(divide="ignore", invalid="ignore"):
            near_side, far_side = (self.low - origin) / direction, (self.high - origin) / direction
        box_enter = np.nanmax(np.minimum(near_side, far_side), axis=1)
        box_leave = np.nanmin(np.maximum(near_side, far_side), axis=1)
        return np.nonzero(np.maximum(box_enter, enter) <= np.minimum(box_leave, leave))[0]

    def holding(self, point):
        return np.nonzero(np.all((self.low <= point) & (point <= self.high), axis=1))[0]


def draw_rays(rng, positions, triangles, faces, normals, area2, rays):
    """Origins, directions and source faces of `rays` front rays (every face
    one, the rest by area) followed by as many opening rays (every open edge
    one first), and the number of front rays."""
    a = positions[triangles[:, 0]]
    e1, e2 = positions[triangles[:, 1]] - a, positions[triangles[:, 2]] - a
    picks = np.concatenate([faces, rng.choice(faces, size=max(0, rays - len(faces)),
                                              p=area2[faces] / area2[faces].sum())])
    u, v = rng.random(len(picks)), rng.random(len(picks))
    folded = u + v > 1
    u[folded], v[folded] = 1 - u[folded], 1 - v[folded]
    origins = [a[picks] + u[:, None] * e1[picks] + v[:, None] * e2[picks]]
    dirs = [normals[picks]]
    sources = [picks]
    uses = open_edge_uses(positions, triangles, faces, normals)
    if uses:
        chosen = rng.integers(0, len(uses), size=rays)
        chosen[:min(len(uses), rays)] = np.arange(min(len(uses), rays))
        edge_origins, edge_dirs = [], []
        for c in chosen:
            f, k = uses[c]
            p0, p1 = positions[triangles[f, k]], positions[triangles[f, (k + 1) % 3]]
            out = -edge_inward(positions, triangles, f, k)
            out /= np.linalg.norm(out)
            side = rng.integers(-1, 2)
            d = np.sqrt(1 - OPENING_TILT_SINE**2) * out + side * OPENING_TILT_SINE * normals[f] if side else out
            edge_origins.append(p0 + rng.random() * (p1 - p0))
            edge_dirs.append(d / np.linalg.norm(d))
        origins.append(np.array(edge_origins))
        dirs.append(np.array(edge_dirs))
        sources.append(np.array([uses[c][0] for c in chosen]))
    return np.vstack(origins), np.vstack(dirs), np.concatenate(sources), len(picks)


def check_covering(positions, triangles, hull_positions, hull_triangles, hull_groups, tol, rays=20000, seed=1,
                   stand_off=DEFAULT_STAND_OFF_IN_TOLERANCES):
    """Draws `rays` front rays and as many opening rays (when there are open
    edges) and decides each against the covering; checks every mesh edge
    (accessibility: no point of it deeper than tol inside a hull) and every
    front ray's origin, face centroid and mesh vertex (coverage: within tol
    of some hull's boundary, by distance, within_tol_of_surface)."""
    rng = np.random.default_rng(seed)
    hulls = hulls_of(hull_positions, hull_triangles, hull_groups, tol)
    # Every hull is tested shrunk by tol, exactly: one with no inside (flat,
    # or thinner than 2 tol) then meets no segment.
    a = positions[triangles[:, 0]]
    e1, e2 = positions[triangles[:, 1]] - a, positions[triangles[:, 2]] - a
    cross = np.cross(e1, e2)
    area2 = np.linalg.norm(cross, axis=1)
    faces = np.nonzero(area2 > 0)[0]
    normals = np.zeros_like(cross)
    normals[faces] = cross[faces] / area2[faces, None]
    origins, dirs, sources, front_count = draw_rays(rng, positions, triangles, faces, normals, area2, rays)

    result = CheckResult(front_rays=front_count, opening_rays=len(origins) - front_count,
                         hulls=len(hulls))
    first = np.empty(len(origins))
    enclosed = np.empty(len(origins), dtype=bool)
    for s in range(0, len(origins), RAYS_PER_BLOCK):
        block = slice(s, s + RAYS_PER_BLOCK)
        # A face met within a thousandth of tol of the start is the start's own.
        first[block], enclosed[block] = first_hits(origins[block], dirs[block], a[faces], e1[faces], e2[faces],
                                                   normals[faces], 1e-3 * tol, tol)
    result.enclosed = int(enclosed.sum())
    if not hulls:
        return result

    boxes = BoxIndex(hulls, 0.0)
    t0 = stand_off * tol
    for r in np.nonzero(~enclosed)[0]:
        o, d = origins[r], dirs[r]
        end = first[r] if np.isfinite(first[r]) else np.inf
        for h in boxes.along(o, d, t0, end):
            stretch = segment_inside(hulls[h], o, d, t0, end, tol)
            if stretch:
                kind = "front" if r < front_count else "opening"
                result.lost.append((kind, int(sources[r]), o, d, hulls[h].group, stretch[0], stretch[1], first[r]))
                break

    for f, k in (uses[0] for uses in edge_uses_by_ends(positions, triangles, faces).values()):
        p0, p1 = positions[triangles[f, k]], positions[triangles[f, (k + 1) % 3]]
        length = np.linalg.norm(p1 - p0)
        result.edges += 1
        for h in boxes.along(p0, (p1 - p0) / length, 0.0, length):
            if segment_inside(hulls[h], p0, (p1 - p0) / length, 0.0, length, tol):
                result.edges_inside.append(((p0, p1), hulls[h].group))
                break

    all_boxes = BoxIndex(hulls, tol)
    centroids = a[faces] + (e1[faces] + e2[faces]) / 3
    # Each corner of a face with area, once, with one face it is a corner of.
    corner_ids, first_use = np.unique(triangles[faces].ravel(), return_index=True)
    points = np.vstack([origins[:front_count], centroids, positions[corner_ids]])
    owners = np.concatenate([sources[:front_count], faces, faces[first_use // 3]])
    result.surface_points = len(points)
    for p, f in zip(points, owners):
        if not any(within_tol_of_surface(hulls[h], p, tol) for h in all_boxes.holding(p)):
            result.uncovered.append((int(f), p))
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", help="the scene, OBJ")
    parser.add_argument("hulls", help="the covering, OBJ with one o or g group per hull")
    parser.add_argument("--tol", type=float, help="tolerance, scene units (default: the hull file's header)")
    parser.add_argument("--rays", type=int, default=20000, help="front rays to draw; opening rays as many again")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--stand-off", type=float, default=DEFAULT_STAND_OFF_IN_TOLERANCES,
                        help="where rays start, in tolerances off their surface (default %(default)s)")
    args = parser.parse_args()
    try:
        tol = args.tol if args.tol is not None else tolerance_in_header(args.hulls)
        if tol is None or not tol > 0:
            print(f"error: {args.hulls}: no tolerance in its first line; give --tol", file=sys.stderr)
            return 2
        positions, triangles, _ = read_obj(args.scene)
        hull_positions, hull_triangles, hull_groups = read_obj(args.hulls)
    except (OSError, ValueError, IndexError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    if len(triangles) == 0 or args.rays < 1:
        print("error: the scene has no faces" if len(triangles) == 0 else "error: --rays must be >= 1",
              file=sys.stderr)
        return 2
    result = check_covering(positions, triangles, hull_positions, hull_triangles, hull_groups, tol, args.rays,
                            args.seed, args.stand_off)
    print(f"{result.front_rays} front and {result.opening_rays} opening rays, {result.enclosed} enclosed; "
          f"{result.hulls} hulls; tol {tol:g}: {len(result.lost)} lost")
    for kind, face, o, d, group, enter, leave, hit in result.lost[:20]:
        print(f"  {kind} ray of face {face} from {o.tolist()} along {d.tolist()}: inside hull {group} "
              f"for t in [{enter:.6g}, {leave:.6g}] (first hit {hit:.6g})")
    print(f"{result.edges} mesh edges: {len(result.edges_inside)} reach deeper than tol into a hull")
    for (p0, p1), group in result.edges_inside[:20]:
        print(f"  edge {p0.tolist()} - {p1.tolist()}: inside hull {group}")
    print(f"{result.surface_points} points of faces: {len(result.uncovered)} on no hull's boundary (within tol)")
    for face, p in result.uncovered[:20]:
        print(f"  face {face} at {p.tolist()}")
    return 1 if result.lost or result.edges_inside or result.uncovered else 0


if __name__ == "__main__":
    sys.exit(main())
