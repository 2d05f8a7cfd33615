// Dissolving, the pass after merging (patch_merging.h): a patch whose every
// face can join some other patch, under the same conditions, is emptied into
// them: one hull fewer. Greedy merging cannot find these moves, it only ever
// unites whole patches; a patch that took two faces early may be what keeps
// both from the two larger patches around them.

#include "merging/patch_merging.h"

#include <algorithm>

namespace hullcover::detail {

std::vector<int> PatchMerger::receivers_of(int f, int h, const AabbTree& near_tree) const {
  const ConnectivityView& c = index_.prepared->connectivity;
  std::vector<std::pair<double, int>> by_shared; // (-shared length, patch): most shared first
  for (int k = 0; k < 3; ++k) {
    const int g = c.face_neighbours[f][k];
    if (g < 0) continue;
    const int q = patch_of(g);
    if (q < 0 || q == h || !patches_[q].alive) continue;
    const double length = face_edge_length(index_.mesh(), f, k);
    auto same = std::find_if(by_shared.begin(), by_shared.end(), [q](const auto& e) { return e.second == q; });
    if (same != by_shared.end())
      same->first -= length;
    else
      by_shared.push_back({-length, q});
  }
  std::sort(by_shared.begin(), by_shared.end());
  std::vector<int> out;
  for (const auto& e : by_shared) out.push_back(e.second);
  if (near_merge_distance_ > 0.0) {
    const MeshView& mesh = index_.mesh();
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Aabb box = grown(bounding_box_of({mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]}),
                           0.5 * near_merge_distance_);
    std::vector<int> near;
    near_tree.overlapping(box, near);
    std::sort(near.begin(), near.end());
    const auto not_a_receiver = [&](int q) {
      return q == h || !patches_[q].alive || std::find(out.begin(), out.end(), q) != out.end();
    };
    near.erase(std::remove_if(near.begin(), near.end(), not_a_receiver), near.end());
    keep_patches_near_face(f, near);
    out.insert(out.end(), near.begin(), near.end());
  }
  return out;
}

std::optional<PatchMerger::Candidate> PatchMerger::face_fits(int f, int q, int lone) {
  const int home = patch_entry(f);
  patch_entry(f) = lone;
  ++statistics_.candidates_tested;
  Candidate candidate = evaluate(q, lone);
  patch_entry(f) = home;
  if (candidate.validity == Validity::valid) return candidate;
  ++statistics_.rejections[static_cast<int>(candidate.validity)];
  return std::nullopt;
}

void PatchMerger::move_face(int f, int q, int lone_id, Candidate&& candidate) {
  const Patch& lone = patches_[lone_id];
  Patch& r = patches_[q];
  r.faces.push_back(f);
  patch_entry(f) = q;
  add_plane(r.face_planes, lone.face_planes.front(), scene_same_plane_gap(index_), index_.tol());
  r.hull_vertices = std::move(candidate.hull_vertices);
  r.planar = candidate.planar;
  r.solid = std::move(candidate.solid);
  r.area += lone.area;
  r.area_vector += lone.area_vector;
  r.material = std::min(r.material, lone.material);
  ++r.version;
  r.changed_at = ++changes_;
}

bool PatchMerger::dissolve(int h, const AabbTree& near_tree, int lone) {
  Patch& patch = patches_[h];
  // Tried before, unchanged since: only a patch that changed since can take
  // the face that was stuck (the others gave their verdict on it already).
  if (patch.dissolve_failed_face >= 0 && patch.changed_at <= patch.dissolve_failed_at) {
    patches_[lone] = single_face_patch(patch.dissolve_failed_face);
    bool unstuck = false;
    for (int q : receivers_of(patch.dissolve_failed_face, h, near_tree))
      if (patches_[q].changed_at > patch.dissolve_failed_at && face_fits(patch.dissolve_failed_face, q, lone)) {
        unstuck = true;
        break;
      }
    if (!unstuck) {
      patch.dissolve_failed_at = changes_;
      return false;
    }
  }
  // Only patches passing condition 2 with a face (cheap) can take it: a
  // face with none fails the patch before any hull is built.
  const std::vector<int> faces = patch.faces;
  std::vector<std::vector<int>> receivers;
  std::vector<std::size_t> places; // receivers of each face before that filter
  for (int f : faces) {
    const Patch& alone = patches_[lone] = single_face_patch(f);
    receivers.push_back(receivers_of(f, h, near_tree));
    std::vector<int>& r = receivers.back();
    places.push_back(r.size());
    r.erase(std::remove_if(r.begin(), r.end(),
                           [&](int q) { return !patches_support_each_other(index_, patches_[q], alone); }),
            r.end());
    if (r.empty()) return false;
  }
  // The face with the fewest places to go first: most failures come early.
  std::vector<int> by_choice(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) by_choice[i] = static_cast<int>(i);
  std::stable_sort(by_choice.begin(), by_choice.end(), [&](int x, int y) { return places[x] < places[y]; });
  std::map<int, Patch> before; // receivers as they were, to put back
  for (int i : by_choice) {
    const int f = faces[i];
    patches_[lone] = single_face_patch(f);
    bool moved = false;
    for (int q : receivers[i]) {
      std::optional<Candidate> candidate = face_fits(f, q, lone);
      if (!candidate) continue;
      before.emplace(q, patches_[q]);
      move_face(f, q, lone, std::move(*candidate));
      moved = true;
      break;
    }
    if (!moved) {
      for (auto& [q, receiver] : before) patches_[q] = std::move(receiver);
      for (int g : faces) patch_entry(g) = h;
      patches_[h].dissolve_failed_at = changes_;
      patches_[h].dissolve_failed_face = f;
      return false;
    }
  }
  patches_[h] = Patch{};
  patches_[h].alive = false;
  ++changes_;
  return true;
}

int PatchMerger::dissolve_patches() {
  std::vector<int> order;
  for (int p = 0; p < static_cast<int>(patches_.size()); ++p)
    // A one-face patch has been tried with every neighbour already.
    if (patches_[p].alive && patches_[p].faces.size() >= 2) order.push_back(p);
  const AabbTree near_tree(near_boxes());
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return patches_[a].faces.size() < patches_[b].faces.size(); });
  const int lone = static_cast<int>(patches_.size()); // where a face is tried alone
  patches_.emplace_back();
  int dissolved = 0;
  for (int h : order)
    if (patches_[h].alive && dissolve(h, near_tree, lone)) ++dissolved;
  patches_.pop_back();
  if (dissolved > 0) recount_shared_edges();
  statistics_.dissolved_patches += dissolved;
  return dissolved;
}

} // namespace hullcover::detail
