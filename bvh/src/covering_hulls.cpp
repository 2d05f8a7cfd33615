#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/runtime_file.h"

#include "query_guard.h"

namespace hullcover::bvh {

std::vector<RuntimeHull> runtime_hulls(const Covering& covering) {
  std::vector<RuntimeHull> hulls;
  hulls.reserve(covering.hulls.size());
  for (const CoveringHull& h : covering.hulls) {
    hulls.push_back(make_runtime_hull(h.polytope, h.material));
    if (h.surface_planes.size() == h.polytope.planes.size()) hulls.back().surface_planes = h.surface_planes;
  }
  return hulls;
}

Result<std::shared_ptr<const HullWorld>> build_hull_world(const Covering& covering) {
  // Guarded too: converting the hulls allocates before HullWorld::build runs.
  return detail::guarded("building the hull world", [&] { return HullWorld::build(runtime_hulls(covering)); });
}

std::vector<std::uint32_t> runtime_sections(const Covering& covering) {
  std::vector<std::uint32_t> sections;
  sections.reserve(covering.hulls.size());
  for (const CoveringHull& h : covering.hulls) sections.push_back(static_cast<std::uint32_t>(h.cell));
  return sections;
}

Status write_covering_runtime_file(const Covering& covering, const std::string& path) {
  const std::vector<std::uint32_t> sections = runtime_sections(covering);
  return write_runtime_file(runtime_hulls(covering), path, &sections);
}

} // namespace hullcover::bvh
