#include "export/collider_obj_writer.h"

#include "hullcover/geometry/atomic_file.h"

#include <cstdio>

namespace hullcover::app {

Status write_collider_obj(const std::vector<ConvexPolytope>& hulls, const std::vector<std::string>& names,
                          const RenderMesh& render, const std::string& path) {
  if (names.size() != hulls.size()) return {StatusCode::invalid_argument, "one name per hull is needed"};
  return write_file_atomically(path, [&](std::FILE* out) {
    std::fprintf(out, "# hullcover collider export: %zu hulls\n", hulls.size());
    long base = 1; // OBJ indices are 1-based and count every vertex so far
    if (render.mesh && !render.mesh->triangles.empty()) {
      std::fprintf(out, "o %s\n", render.name.c_str());
      for (const Eigen::Vector3d& v : render.mesh->positions)
        std::fprintf(out, "v %.17g %.17g %.17g\n", v.x(), v.y(), v.z());
      for (const Eigen::Vector3i& t : render.mesh->triangles)
        std::fprintf(out, "f %ld %ld %ld\n", base + t[0], base + t[1], base + t[2]);
      base += static_cast<long>(render.mesh->positions.size());
    }
    for (size_t h = 0; h < hulls.size(); ++h) {
      std::fprintf(out, "o %s\n", names[h].c_str());
      for (const Eigen::Vector3d& v : hulls[h].vertices)
        std::fprintf(out, "v %.17g %.17g %.17g\n", v.x(), v.y(), v.z());
      for (const std::vector<int>& facet : hulls[h].facets) {
        std::fputc('f', out);
        for (int v : facet) std::fprintf(out, " %ld", base + v);
        std::fputc('\n', out);
      }
      base += static_cast<long>(hulls[h].vertices.size());
    }
    return true;
  });
}

} // namespace hullcover::app
