// Near merges, the pass that follows the paper's greedy merging
// (patch_merging.h): once the paper's pass has stopped, patches that share
// no edge but lie close are tried as pairs too, under the same conditions
// (the validity conditions never asked for a shared edge: the paper merges
// across edges only to keep its search local).

#include "merging/patch_merging.h"

#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>

namespace hullcover::detail {
namespace {

void corners_of_face(const MeshView& mesh, int f, Eigen::Vector3d (&corners)[3]) {
  const Eigen::Vector3i& t = mesh.triangles[f];
  for (int k = 0; k < 3; ++k) corners[k] = mesh.positions[t[k]];
}

Aabb box_of_face(const Eigen::Vector3d (&corners)[3]) {
  Aabb box;
  for (const Eigen::Vector3d& p : corners) box.extend(p);
  return box;
}

// Patches of up to this many faces are searched face by face: a tree query
// costs about as much as that many box tests.
constexpr size_t kFacesReadDirectly = 32;

} // namespace

bool PatchMerger::face_near_patch(int f, int q) const {
  const MeshView& mesh = index_.mesh();
  Eigen::Vector3d face[3], other[3];
  corners_of_face(mesh, f, face);
  const Aabb reach = grown(box_of_face(face), near_merge_distance_);
  const std::vector<int>& faces = patches_[q].faces;
  // A small patch is read face by face; a large one through the scene's
  // face tree, which finds only the faces near this one.
  std::vector<int> candidates;
  if (faces.size() > kFacesReadDirectly) {
    index_.face_tree.overlapping(reach, candidates);
    candidates.erase(std::remove_if(candidates.begin(), candidates.end(), [&](int g) { return patch_of(g) != q; }),
                     candidates.end());
  }
  for (int g : faces.size() > kFacesReadDirectly ? candidates : faces) {
    corners_of_face(mesh, g, other);
    if (boxes_overlap(reach, box_of_face(other)) && triangles_within(face, other, near_merge_distance_)) return true;
  }
  return false;
}

void PatchMerger::keep_patches_near_face(int f, std::vector<int>& patches) const {
  if (patches.empty()) return;
  const MeshView& mesh = index_.mesh();
  Eigen::Vector3d face[3], other[3];
  corners_of_face(mesh, f, face);
  const Aabb reach = grown(box_of_face(face), near_merge_distance_);
  // face_near_patch for each, from one look-up of the faces around f: a
  // large face among many patches would otherwise look them up once per
  // patch.
  std::vector<int> around;
  index_.face_tree.overlapping(reach, around);
  std::vector<char> near(patches.size(), 0);
  for (int g : around) {
    const int q = patch_of(g);
    const auto at = std::lower_bound(patches.begin(), patches.end(), q);
    if (at == patches.end() || *at != q || near[at - patches.begin()]) continue;
    corners_of_face(mesh, g, other);
    if (boxes_overlap(reach, box_of_face(other)) && triangles_within(face, other, near_merge_distance_))
      near[at - patches.begin()] = 1;
  }
  size_t kept = 0;
  for (size_t i = 0; i < patches.size(); ++i)
    if (near[i]) patches[kept++] = patches[i];
  patches.resize(kept);
}

bool PatchMerger::patches_near(int a, int b) const {
  const Aabb reach =
      grown(bounding_box_of(positions_of(index_.mesh(), patches_[b].hull_vertices)), near_merge_distance_);
  Eigen::Vector3d face[3];
  for (int f : patches_[a].faces) {
    corners_of_face(index_.mesh(), f, face);
    if (!boxes_overlap(reach, box_of_face(face))) continue;
    if (face_near_patch(f, b)) return true;
  }
  return false;
}

int PatchMerger::push_near_pairs() {
  const int patch_count = static_cast<int>(patches_.size());
  const std::vector<Aabb> boxes = near_boxes();
  const AabbTree tree(boxes);
  int pushed = 0;
  // A pair of patches both unchanged since the last listing was listed then
  // as it is now (the same boxes, the same shared edges), and tried: passed
  // over. Any other pair was never listed as it is now: a patch that changed
  // since has a version no listing saw (versions only rise between
  // listings; dissolving puts back a patch it changed before any listing
  // can see it), so it is listed now, once (b > a).
  const long listed_at = near_pairs_listed_at_;
  near_pairs_listed_at_ = changes_;
  std::vector<int> near;
  for (int a = 0; a < patch_count; ++a) {
    const Patch& pa = patches_[a];
    if (!pa.alive) continue;
    const bool a_unchanged = pa.changed_at <= listed_at;
    near.clear();
    tree.overlapping(boxes[a], near);
    for (int b : near) {
      const Patch& pb = patches_[b];
      if (b <= a || (a_unchanged && pb.changed_at <= listed_at) || pa.shared_length.count(b)) continue;
      if (!patches_support_each_other(index_, pa, pb) || !patches_near(a, b)) continue;
      push_pair(a, b);
      ++pushed;
    }
  }
  return pushed;
}

} // namespace hullcover::detail
