#include "hullcover/mesh/mesh_export.h"

#include "hullcover/geometry/atomic_file.h"

#include <cstdio>

namespace hullcover {

namespace {

// The OBJ text; the stream's error flag tells whether it was all written.
void print_mesh_obj(const Mesh& mesh, std::FILE* out) {
  std::fprintf(out, "# written by hullcover: %zu vertices, %zu triangles\n", mesh.positions.size(),
               mesh.triangles.size());
  for (const Eigen::Vector3d& p : mesh.positions) std::fprintf(out, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  int current_material = -1;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int material = t < mesh.material_ids.size() ? mesh.material_ids[t] : 0;
    if (material != current_material) {
      current_material = material;
      const bool named = material >= 0 && static_cast<size_t>(material) < mesh.material_names.size();
      std::fprintf(out, "usemtl %s\n",
                   named ? mesh.material_names[material].c_str() : ("material_" + std::to_string(material)).c_str());
    }
    const Eigen::Vector3i& tri = mesh.triangles[t];
    std::fprintf(out, "f %d %d %d\n", tri[0] + 1, tri[1] + 1, tri[2] + 1);
  }
}

} // namespace

Status write_mesh_obj(const Mesh& mesh, const std::string& path) {
  return write_file_atomically(path, [&mesh](std::FILE* out) {
    print_mesh_obj(mesh, out);
    return true;
  });
}

} // namespace hullcover
