#include "merging/patch_merging.h"

#include "validity/flat_polygon_cover.h"

#include "hullcover/geometry/incremental_hull.h"
#include "hullcover/geometry/planar_hull.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::detail {
namespace {

// splitmix64: a fixed, portable pseudo-random function of the pair.
double pseudo_random_cost(std::uint64_t seed, int a, int b, int va, int vb) {
  std::uint64_t z = seed ^ (static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint32_t>(b)) ^
                    (static_cast<std::uint64_t>(va) * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(vb));
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / static_cast<double>(1ull << 53);
}

} // namespace

// Face planes within tolerances.h's same-plane gap across a patch's extent
// are kept once: a patch's faces can lie anywhere in its island.
double scene_same_plane_gap(const SceneIndex& index) {
  return same_plane_cosine_gap(index.tol(), index.patch_extent());
}

void add_plane(std::vector<Plane>& planes, const Plane& p, double cosine_gap, double tol) {
  for (const Plane& q : planes)
    if (q.normal.dot(p.normal) >= 1.0 - cosine_gap && std::abs(q.offset - p.offset) <= tol) return;
  planes.push_back(p);
}

std::vector<Eigen::Vector3d> positions_of(const MeshView& mesh, const std::vector<int>& ids) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(ids.size());
  for (int v : ids) out.push_back(mesh.positions[v]);
  return out;
}

std::vector<int> vertices_of_faces(const MeshView& mesh, const std::vector<int>& faces) {
  std::vector<int> out;
  out.reserve(3 * faces.size());
  for (int f : faces)
    for (int k = 0; k < 3; ++k) out.push_back(mesh.triangles[f][k]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double face_edge_length(const MeshView& mesh, int face, int corner) {
  const Eigen::Vector3i& t = mesh.triangles[face];
  return (mesh.positions[t[(corner + 1) % 3]] - mesh.positions[t[corner]]).norm();
}

bool patches_support_each_other(const SceneIndex& index, const Patch& a, const Patch& b) {
  if (index.has_allowance()) return true;
  const MeshView& mesh = index.mesh();
  const double tol = index.tol();
  return planes_support_points(a.face_planes, positions_of(mesh, b.hull_vertices), tol) &&
         planes_support_points(b.face_planes, positions_of(mesh, a.hull_vertices), tol);
}

double merged_patch_cost(const Patch& a, const Patch& b, double shared) {
  const double boundary = std::max(0.0, a.boundary_length + b.boundary_length - 2.0 * shared);
  return boundary / std::sqrt(a.area + b.area);
}

PatchMerger::PatchMerger(const SceneIndex& index, const DecomposeOptions& options, double near_merge_distance,
                         const CellLayout& cells, int cell, CoveringStatistics& statistics)
    : index_(index), options_(options), cells_(cells), cell_(cell), statistics_(statistics),
      near_merge_distance_(near_merge_distance) {
  const ConnectivityView& c = index.prepared->connectivity;
  const std::vector<int>& faces = cells.faces_of_cell[cell];
  const int face_count = static_cast<int>(faces.size());
  patches_.resize(face_count);
  face_patch_.resize(face_count);
  for (int slot = 0; slot < face_count; ++slot) {
    const int f = faces[slot];
    face_patch_[slot] = slot;
    if (c.zero_area[f]) {
      patches_[slot].alive = false;
      ++statistics_.zero_area_faces_skipped;
      continue;
    }
    patches_[slot] = single_face_patch(f);
  }
  recount_shared_edges();
  push_neighbour_pairs(-1);
}

Patch PatchMerger::single_face_patch(int f) const {
  const MeshView& mesh = index_.mesh();
  const Eigen::Vector3i& t = mesh.triangles[f];
  Patch p;
  p.faces = {f};
  p.hull_vertices = {t[0], t[1], t[2]};
  std::sort(p.hull_vertices.begin(), p.hull_vertices.end());
  p.face_planes = {{index_.face_normals[f], index_.face_normals[f].dot(mesh.positions[t[0]])}};
  p.area = index_.face_areas[f];
  p.area_vector = index_.face_normals[f] * p.area;
  for (int k = 0; k < 3; ++k) p.boundary_length += face_edge_length(mesh, f, k);
  p.material = mesh.material_ids[f];
  return p;
}

void PatchMerger::recount_shared_edges() {
  const MeshView& mesh = index_.mesh();
  const ConnectivityView& c = index_.prepared->connectivity;
  for (Patch& p : patches_) {
    p.shared_length.clear();
    p.boundary_length = 0.0;
  }
  for (int f : cells_.faces_of_cell[cell_]) {
    const int own = patch_of(f);
    Patch& p = patches_[own];
    if (!p.alive) continue;
    for (int k = 0; k < 3; ++k) {
      const int g = c.face_neighbours[f][k];
      // A face of another cell is a border: counted as boundary, no pair.
      const int q = g < 0 ? -1 : patch_of(g);
      if (q == own) continue;
      const double length = face_edge_length(mesh, f, k);
      p.boundary_length += length;
      if (q >= 0 && patches_[q].alive) p.shared_length[q] += length;
    }
  }
}

std::vector<Aabb> PatchMerger::near_boxes() const {
  std::vector<Aabb> boxes(patches_.size()); // empty for dead patches: they overlap nothing
  for (size_t p = 0; p < patches_.size(); ++p)
    if (patches_[p].alive)
      boxes[p] =
          grown(bounding_box_of(positions_of(index_.mesh(), patches_[p].hull_vertices)), 0.5 * near_merge_distance_);
  return boxes;
}

void PatchMerger::push_neighbour_pairs(long changed_after) {
  for (int p = 0; p < static_cast<int>(patches_.size()); ++p)
    for (const auto& [q, length] : patches_[p].shared_length)
      if (p < q && std::max(patches_[p].changed_at, patches_[q].changed_at) > changed_after) push_pair(p, q);
}

void PatchMerger::push_pair(int a, int b) {
  if (a > b) std::swap(a, b);
  const Patch& pa = patches_[a];
  const Patch& pb = patches_[b];
  const auto shared = pa.shared_length.find(b); // none for a near pair
  const double cost = options_.order == MergeOrder::compact
                          ? merged_patch_cost(pa, pb, shared == pa.shared_length.end() ? 0.0 : shared->second)
                          : pseudo_random_cost(options_.seed, a, b, pa.version, pb.version);
  queue_.push_back({cost, a, b, pa.version, pb.version});
  std::push_heap(queue_.begin(), queue_.end(), std::greater<>());
}

PatchMerger::Candidate PatchMerger::evaluate(int a, int b) {
  const Patch& pa = patches_[a];
  const Patch& pb = patches_[b];
  const MeshView& mesh = index_.mesh();
  const double tol = index_.tol();
  Candidate out;
  if (options_.keep_materials_apart && pa.material != pb.material) {
    out.validity = Validity::materials_differ;
    return out;
  }
  // Condition 2 first: it needs no hull and rejects every concave pair.
  if (!patches_support_each_other(index_, pa, pb)) {
    out.validity = Validity::face_not_on_hull;
    return out;
  }
  std::vector<int> ids;
  std::set_union(pa.hull_vertices.begin(), pa.hull_vertices.end(), pb.hull_vertices.begin(), pb.hull_vertices.end(),
                 std::back_inserter(ids));
  const std::vector<Eigen::Vector3d> points = positions_of(mesh, ids);

  if (pa.planar && pb.planar && pa.area_vector.dot(pb.area_vector) > 0.0) {
    // Every vertex of both patches, not only their polygons' corners: a
    // face's inner vertex must stay on the polygon too (coverage), though
    // the plane turns as patches join.
    std::vector<int> faces = pa.faces;
    faces.insert(faces.end(), pb.faces.begin(), pb.faces.end());
    const std::vector<int> all = vertices_of_faces(mesh, faces);
    const Eigen::Vector3d normal = (pa.area_vector + pb.area_vector).normalized();
    const auto [low, high] = extent_along(mesh.positions, all, normal);
    if (high - low <= kPlanarSlabInTolerances * tol) {
      const FlatPolygon polygon = make_flat_polygon(mesh.positions, all, normal, tol);
      out.planar = true;
      out.hull_vertices = polygon.corner_vertices;
      std::sort(out.hull_vertices.begin(), out.hull_vertices.end());
      if (2 * static_cast<int>(polygon.corners.size()) > options_.max_hull_vertices) {
        out.validity = Validity::too_many_vertices;
        return out;
      }
      if (options_.max_hull_triangles &&
          triangles_of_prism(static_cast<int>(polygon.corners.size())) > *options_.max_hull_triangles) {
        out.validity = Validity::too_many_triangles;
        return out;
      }
      // The paper's conditions alone let a polygon span a hole with nothing
      // below it (a window); exact mode does not.
      if (index_.mode == ValidityMode::exact) {
        out.validity = check_polygon_covered(index_, polygon, positions_of(mesh, pa.hull_vertices),
                                             positions_of(mesh, pb.hull_vertices), scratch_);
        if (out.validity != Validity::valid) return out;
      }
      out.validity = check_flat_polygon(
          index_, polygon,
          [&](int f) {
        const int p = patch_of(f);
        return p == a || p == b;
          },
          scratch_);
      return out;
    }
  }

  std::optional<ConvexPolytope> hull = grow_known_hull(pa, pb);
  if (!hull) hull = grow_known_hull(pb, pa);
  if (!hull) {
    Result<ConvexPolytope> built = hull_builder_.build(points, ids);
    ++statistics_.qhull_calls;
    if (!built.ok()) {
      out.validity = Validity::hull_failed;
      return out;
    }
    hull = std::move(built).value();
  }
  if (static_cast<int>(hull->vertices.size()) > options_.max_hull_vertices) {
    out.validity = Validity::too_many_vertices;
    return out;
  }
  if (options_.max_hull_triangles && triangles_of_facets(hull->facets) > *options_.max_hull_triangles) {
    out.validity = Validity::too_many_triangles;
    return out;
  }
  out.validity = check_solid_hull(index_, *hull, scratch_, &recent_rejections_);
  if (out.validity == Validity::valid) out.validity = check_thin_hull(a, b, *hull, ids);
  out.hull_vertices = hull->vertex_ids;
  std::sort(out.hull_vertices.begin(), out.hull_vertices.end());
  out.solid = std::move(hull);
  return out;
}

Validity PatchMerger::check_thin_hull(int a, int b, const ConvexPolytope& hull, const std::vector<int>& ids) {
  // A solid whose interior shrunk by tol is empty (its inradius is at most
  // tol) has no inside for rays to meet, yet it spans what its faces do not,
  // as a flat polygon does, and a character standing there touches it: a
  // floor's hull over a hole in it (nav_test's stairwells), a sheet from one
  // floor level to the next (dungeon). The ball inscribed in such a hull
  // touches at most four of its facet planes, whose tetrahedron holds the
  // hull and is at most 4 inradii high over one of them: across that facet
  // the hull is within kThinHullSlabInTolerances tol, and there it is held
  // to a flat polygon's condition 4.
  if (index_.mode != ValidityMode::exact) return Validity::valid;
  const double tol = index_.tol();
  Eigen::Vector3d across = Eigen::Vector3d::Zero();
  const double thinnest = thinnest_width(hull, &across);
  if (!(thinnest <= kThinHullSlabInTolerances * tol)) return Validity::valid;
  // Collinear corners: a needle under tol across, spanning nothing.
  const FlatPolygon polygon = make_flat_polygon(index_.mesh().positions, ids, across, tol);
  if (polygon.corners.empty()) return Validity::valid;
  const double half_width = 0.5 * thinnest + tol;
  auto in_patch = [&](int f) {
    const int p = patch_of(f);
    return p == a || p == b;
  };
  // "Below" is behind the patches' faces, as for a flat polygon (a pillar
  // standing on a floor is allowed). Where the faces point both ways (a
  // slab's top and bottom together) neither side is the back: both are held.
  const Eigen::Vector3d sum = patches_[a].area_vector + patches_[b].area_vector;
  const double agreement = across.dot(sum);
  const bool one_sided = std::abs(agreement) >= 0.5 * (patches_[a].area_vector.norm() + patches_[b].area_vector.norm());
  if (!one_sided || agreement >= 0.0) {
    const Validity front = check_faces_below_polygon(index_, polygon, half_width, in_patch, scratch_);
    if (front != Validity::valid || one_sided) return front;
  }
  FlatPolygon flipped = polygon;
  flipped.plane = polygon.plane.flipped();
  return check_faces_below_polygon(index_, flipped, half_width, in_patch, scratch_);
}

std::optional<ConvexPolytope> PatchMerger::grow_known_hull(const Patch& base, const Patch& other) {
  std::vector<int> added;
  std::set_difference(other.hull_vertices.begin(), other.hull_vertices.end(), base.hull_vertices.begin(),
                      base.hull_vertices.end(), std::back_inserter(added));
  if (static_cast<int>(added.size()) > kMostPointsToAddIncrementally) return std::nullopt;
  std::optional<ConvexPolytope> hull;
  if (base.solid) {
    hull = *base.solid;
  } else {
    // A planar base is a flat polytope, its front and back facets on the
    // same corners. Growing it only works off its plane: a point on the
    // plane but outside the polygon is beyond no facet.
    const FlatPolygon polygon = make_flat_polygon(index_.mesh().positions, vertices_of_faces(index_.mesh(), base.faces),
                                                  base.area_vector.normalized(), index_.tol());
    // No point off its plane (back-to-back sheets on the same corners): the
    // union is flat, no solid; Qhull refuses it.
    if (polygon.corners.size() < 3 || added.empty()) return std::nullopt;
    for (int v : added)
      if (std::abs(polygon.plane.signed_distance(index_.mesh().positions[v])) <= index_.tol()) return std::nullopt;
    hull = flat_polytope(polygon, false);
  }
  for (int v : added) {
    hull = add_point_to_hull(*hull, index_.mesh().positions[v], v, index_.tol());
    if (!hull) return std::nullopt;
  }
  ++statistics_.incremental_hulls;
  return hull;
}

void PatchMerger::merge(int a, int b, Candidate&& candidate) {
  // The larger patch absorbs the smaller one (ties: the lower id survives),
  // so each face moves O(log n) times.
  int keep = a, gone = b;
  if (patches_[b].faces.size() > patches_[a].faces.size()) std::swap(keep, gone);
  Patch& k = patches_[keep];
  Patch& g = patches_[gone];
  const double cosine_gap = scene_same_plane_gap(index_);

  const auto shared = k.shared_length.find(gone);
  const bool near_merge = shared == k.shared_length.end();
  const double shared_length = near_merge ? 0.0 : shared->second;
  k.boundary_length = std::max(0.0, k.boundary_length + g.boundary_length - 2.0 * shared_length);
  k.area += g.area;
  k.area_vector += g.area_vector;
  for (int f : g.faces) patch_entry(f) = keep;
  k.faces.insert(k.faces.end(), g.faces.begin(), g.faces.end());
  for (const Plane& p : g.face_planes) add_plane(k.face_planes, p, cosine_gap, index_.tol());
  k.hull_vertices = std::move(candidate.hull_vertices);
  k.planar = candidate.planar;
  k.solid = std::move(candidate.solid);
  k.material = std::min(k.material, g.material);

  k.shared_length.erase(gone);
  for (const auto& [neighbour, length] : g.shared_length) {
    if (neighbour == keep) continue;
    Patch& n = patches_[neighbour];
    n.shared_length.erase(gone);
    n.shared_length[keep] += length;
    k.shared_length[neighbour] += length;
  }
  g = Patch{};
  g.alive = false;
  ++k.version;
  k.changed_at = ++changes_;
  ++statistics_.merges;
  statistics_.near_merges += near_merge;
  for (const auto& [neighbour, length] : k.shared_length) push_pair(keep, neighbour);
}

void PatchMerger::run_pairs() {
  const int start_patches = static_cast<int>(patches_.size()) - statistics_.zero_area_faces_skipped;
  constexpr int kProgressEvery = 2048;
  while (!queue_.empty()) {
    std::pop_heap(queue_.begin(), queue_.end(), std::greater<>());
    const QueueEntry entry = queue_.back();
    queue_.pop_back();
    const Patch& pa = patches_[entry.a];
    const Patch& pb = patches_[entry.b];
    if (!pa.alive || !pb.alive || pa.version != entry.version_a || pb.version != entry.version_b) continue;
    ++statistics_.candidates_tested;
    Candidate candidate = evaluate(entry.a, entry.b);
    if (candidate.validity != Validity::valid) {
      ++statistics_.rejections[static_cast<int>(candidate.validity)];
      continue;
    }
    merge(entry.a, entry.b, std::move(candidate));
    if (options_.progress && statistics_.merges % kProgressEvery == 0 && start_patches > 1)
      options_.progress(static_cast<double>(statistics_.merges) / (start_patches - 1));
  }
}

void PatchMerger::run() {
  run_pairs();
  // Near merges and dissolving change hulls, which opens new pairs of both
  // kinds.
  for (;;) {
    if (near_merge_distance_ > 0.0) {
      for (;;) {
        const int merges = statistics_.merges;
        if (push_near_pairs() == 0) break;
        run_pairs();
        if (statistics_.merges == merges) break;
      }
    }
    const long before_dissolving = changes_;
    if (!options_.dissolve.value_or(false) || dissolve_patches() == 0) break;
    // Pairs of unchanged patches were all tried as they are, and failed.
    push_neighbour_pairs(before_dissolving);
    run_pairs();
  }
}

} // namespace hullcover::detail
