#include "hullcover/mesh/mesh_import.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>

#include <filesystem>
#include <limits>

namespace hullcover {
namespace {

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return out;
}

/// Appends every mesh under `node` with the accumulated transform applied
/// in double precision.
void append_node(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent, ImportedMesh& out) {
  const Eigen::Matrix4d world = parent * to_eigen(node.mTransformation);
  const Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
  // A mirroring transform turns counter-clockwise into clockwise; flip the
  // winding back so the front stays where the file put it.
  const bool mirrored = linear.determinant() < 0.0;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& source = *scene.mMeshes[node.mMeshes[i]];
    ++out.report.mesh_instances;
    const int base = static_cast<int>(out.mesh.positions.size());
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D& p = source.mVertices[v];
      out.mesh.positions.push_back(linear * Eigen::Vector3d(p.x, p.y, p.z) + world.topRightCorner<3, 1>());
    }
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
      const aiFace& face = source.mFaces[f];
      if (face.mNumIndices != 3) {
        ++out.report.skipped_non_triangle_primitives;
        continue;
      }
      Eigen::Vector3i tri(base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                          base + static_cast<int>(face.mIndices[2]));
      if (mirrored) std::swap(tri[1], tri[2]);
      out.mesh.triangles.push_back(tri);
      out.mesh.material_ids.push_back(static_cast<int>(source.mMaterialIndex));
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) append_node(scene, *node.mChildren[c], world, out);
}

Status check_face_indices(const aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f)
      for (unsigned k = 0; k < mesh.mFaces[f].mNumIndices; ++k)
        if (mesh.mFaces[f].mIndices[k] >= mesh.mNumVertices)
          return {StatusCode::index_out_of_range, "face " + std::to_string(f) + " of mesh " + std::to_string(m) +
                                                      " names vertex " + std::to_string(mesh.mFaces[f].mIndices[k]) +
                                                      " but the mesh has " + std::to_string(mesh.mNumVertices)};
  }
  return Status::success();
}

Result<ImportedMesh> import_with_assimp(const std::string& path) {
  Assimp::Importer importer;
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension.empty() || !importer.IsExtensionSupported(extension))
    return Status{StatusCode::unknown_format,
                  path + ": unknown format '" + extension + "' (readable: .obj .ply .stl .gltf .glb .fbx and others Assimp knows)"};

  // Read without post-processing first: triangulation reads vertices by
  // index, so indices are checked before it runs.
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene == nullptr)
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + importer.GetErrorString()};
  if (scene->mRootNode == nullptr || scene->mNumMeshes == 0)
    return Status{StatusCode::empty_scene, path + ": the file holds no mesh"};
  if (Status indices = check_face_indices(*scene); !indices.ok())
    return Status{indices.code(), path + ": " + indices.message()};
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_ValidateDataStructure);
  if (scene == nullptr)
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + importer.GetErrorString()};

  ImportedMesh out;
  append_node(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), out);
  for (unsigned m = 0; m < scene->mNumMaterials; ++m)
    out.mesh.material_names.emplace_back(scene->mMaterials[m]->GetName().C_Str());
  if (out.mesh.material_names.empty()) out.mesh.material_names.emplace_back("default");

  if (out.mesh.triangles.empty())
    return Status{StatusCode::empty_scene, path + ": the file holds no triangles"};
  if (const Status valid = validate_mesh(out.mesh); !valid.ok()) return Status{valid.code(), path + ": " + valid.message()};

  // Half a float32 unit in the last place, relative to the magnitude.
  constexpr double kFloat32RelativeRounding = std::numeric_limits<float>::epsilon() / 2.0;
  out.mesh.coordinate_error = kFloat32RelativeRounding * largest_coordinate_magnitude(out.mesh);
  return out;
}

} // namespace

Result<ImportedMesh> import_mesh(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return Status{StatusCode::file_not_found, path + ": no such file"};
  if (!std::filesystem::is_regular_file(path, error))
    return Status{StatusCode::file_not_found, path + ": not a regular file"};
  if (std::filesystem::file_size(path, error) == 0) return Status{StatusCode::empty_scene, path + ": the file is empty"};
  try {
    return import_with_assimp(path);
  } catch (const std::exception& e) {
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + e.what()};
  } catch (...) {
    return Status{StatusCode::unreadable_file, path + ": cannot read: unknown importer failure"};
  }
}

} // namespace hullcover
