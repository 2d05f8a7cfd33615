#include "hullcover/mesh/mesh_import.h"

#include "confined_io.h"
#include "scene_file_checks.h"
#include "obj_reader.h"
#include "stl_ascii_reader.h"
#include "ply_reader.h"
#include "ply_header.h"
#include "scene_file_rules.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>

#include <pthread.h>

#include <algorithm>
#include <fstream>
#include <filesystem>
#include <exception>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace hullcover {
namespace {

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return out;
}

/// Appends the meshes of `node` with its world transform applied in double
/// precision.
void append_meshes(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& world, ImportedMesh& out) {
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
}

/// Every node in depth-first order with its world transform, walked with an
/// explicit stack (a deep hierarchy must not run the call stack out), and
/// the faces and vertices they place. Fails with `limit_exceeded` past the
/// depth or triangle limit, before anything is placed.
struct PlacedNode {
  const aiNode* node;
  Eigen::Matrix4d world;
};
Result<std::vector<PlacedNode>> place_nodes(const aiScene& scene, const ImportLimits& limits,
                                            std::uint64_t triangle_limit) {
  std::vector<PlacedNode> placed;
  std::vector<std::pair<PlacedNode, int>> pending = {{{scene.mRootNode, Eigen::Matrix4d::Identity()}, 1}};
  std::uint64_t faces = 0;
  while (!pending.empty()) {
    auto [item, depth] = pending.back();
    pending.pop_back();
    if (depth > limits.max_node_depth) return detail::deeper_than_limit("node hierarchy", limits);
    item.world = item.world * to_eigen(item.node->mTransformation);
    for (unsigned i = 0; i < item.node->mNumMeshes; ++i) faces += scene.mMeshes[item.node->mMeshes[i]]->mNumFaces;
    if (faces > triangle_limit)
      return Status{StatusCode::limit_exceeded,
                    "more than the limit of " + std::to_string(triangle_limit) +
                        " triangles once every node places its meshes (" +
                        (limits.max_triangles ? std::string("--max-triangles")
                                              : "by default one per " + std::to_string(kInputBytesPerDefaultTriangle) +
                                                    " bytes of the files read; raise it with --max-triangles") +
                        ")"};
    for (unsigned c = item.node->mNumChildren; c-- > 0;)
      pending.push_back({{item.node->mChildren[c], item.world}, depth + 1});
    placed.push_back(item);
  }
  return placed;
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

// The refusal `confined` recorded (a reference out of the folder, or a file
// over the size limit) as the status the import fails with; none when
// every reference it judged was allowed.
std::optional<Status> refusal_of(const detail::ConfinedIOSystem& confined, const std::string& path) {
  if (confined.refusal().empty()) return std::nullopt;
  return Status{confined.refused_for_size() ? StatusCode::limit_exceeded : StatusCode::reference_outside_folder,
                path + ": " + confined.refusal()};
}

// Checks the mesh a reader made and records its reader's rounding: each
// coordinate carries at most `relative_rounding` of its magnitude.
Status finish_import(const std::string& path, double relative_rounding, ImportedMesh& out) {
  if (const Status valid = validate_mesh(out.mesh); !valid.ok())
    return Status{valid.code(), path + ": " + valid.message()};
  out.mesh.coordinate_error = relative_rounding * largest_coordinate_magnitude(out.mesh);
  out.mesh.coordinate_relative_error = relative_rounding;
  return Status::success();
}

Result<ImportedMesh> import_with_assimp(const std::string& path, const ImportLimits& limits) {
  Assimp::Importer importer;
  // The importer owns the IO system; `confined` stays valid while it lives.
  // Assimp is given the absolute path: its OBJ reader joins a relative
  // path's folder to it twice when it holds '..', sending the material
  // library's lookup out of the folder.
  std::error_code error;
  const std::string absolute = std::filesystem::absolute(path, error).lexically_normal().string();
  auto* confined = new detail::ConfinedIOSystem(absolute, limits.max_file_bytes);
  importer.SetIOHandler(confined);
  const auto refused = [&] { return refusal_of(*confined, path); };
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension.empty() || !importer.IsExtensionSupported(extension))
    return Status{StatusCode::unknown_format,
                  path + ": unknown format '" + extension +
                      "' (readable: .obj .ply .stl .gltf .glb .fbx and others Assimp knows)"};

  // Read without post-processing first: triangulation reads vertices by
  // index, so indices are checked before it runs.
  const aiScene* scene = importer.ReadFile(absolute, 0);
  if (std::optional<Status> refusal = refused()) return *refusal;
  if (scene == nullptr)
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + importer.GetErrorString()};
  if (scene->mRootNode == nullptr || scene->mNumMeshes == 0)
    return Status{StatusCode::empty_scene, path + ": the file holds no mesh"};
  if (Status indices = check_face_indices(*scene); !indices.ok())
    return Status{indices.code(), path + ": " + indices.message()};
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_ValidateDataStructure);
  if (scene == nullptr)
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + importer.GetErrorString()};

  const std::uint64_t triangle_limit =
      limits.max_triangles ? *limits.max_triangles : default_triangle_limit(confined->bytes_opened());
  Result<std::vector<PlacedNode>> placed = place_nodes(*scene, limits, triangle_limit);
  if (!placed.ok()) return Status{placed.status().code(), path + ": " + placed.status().message()};
  ImportedMesh out;
  for (const PlacedNode& p : placed.value()) append_meshes(*scene, *p.node, p.world, out);
  for (unsigned m = 0; m < scene->mNumMaterials; ++m)
    out.mesh.material_names.emplace_back(scene->mMaterials[m]->GetName().C_Str());
  if (out.mesh.material_names.empty()) out.mesh.material_names.emplace_back("default");

  if (out.mesh.triangles.empty()) return Status{StatusCode::empty_scene, path + ": the file holds no triangles"};
  // Half a float32 unit in the last place, relative to the magnitude.
  constexpr double kFloat32RelativeRounding = std::numeric_limits<float>::epsilon() / 2.0;
  if (Status finished = finish_import(path, kFloat32RelativeRounding, out); !finished.ok()) return finished;
  return out;
}

// Runs `work` on a thread with a stack of kImportStackBytes: the readers of
// formats without a pre-check (FBX, COLLADA, ...) recurse over the node
// hierarchy, which a hostile file can make as deep as it likes; the depth
// limit is applied after they return. Reserved address space only, touched
// as used. Runs on the caller's thread when no such thread can be made.
constexpr std::size_t kImportStackBytes = std::size_t{512} << 20;

void run_on_large_stack(const std::function<void()>& work) {
  pthread_attr_t attributes;
  pthread_t thread;
  const auto trampoline = [](void* f) -> void* {
    (*static_cast<const std::function<void()>*>(f))();
    return nullptr;
  };
  const bool made = pthread_attr_init(&attributes) == 0 &&
                    pthread_attr_setstacksize(&attributes, kImportStackBytes) == 0 &&
                    pthread_create(&thread, &attributes, trampoline, const_cast<std::function<void()>*>(&work)) == 0;
  pthread_attr_destroy(&attributes);
  if (made)
    pthread_join(thread, nullptr);
  else
    work();
}

// The triangles an import may make: the user's limit, or the default rule
// of the file's size.
std::uint64_t triangle_limit_for(const ImportLimits& limits, std::uint64_t file_bytes) {
  return limits.max_triangles ? *limits.max_triangles : default_triangle_limit(file_bytes);
}

// A reader's failure, named by the file.
Status of_file(const std::string& path, const Status& status) {
  return Status{status.code(), path + ": " + status.message()};
}

// A mesh one of the project's text readers read in double: a decimal
// coordinate carries only its rounding to the nearest double.
Result<ImportedMesh> imported_in_double(const std::string& path, Mesh mesh, int skipped_primitives) {
  ImportedMesh out;
  out.mesh = std::move(mesh);
  out.report.mesh_instances = 1;
  out.report.skipped_non_triangle_primitives = skipped_primitives;
  constexpr double kDoubleRelativeRounding = std::numeric_limits<double>::epsilon() / 2.0;
  if (Status finished = finish_import(path, kDoubleRelativeRounding, out); !finished.ok()) return finished;
  return out;
}

// The project's OBJ reader (obj_reader.h).
Result<ImportedMesh> import_obj(const std::string& path, const ImportLimits& limits, std::uint64_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status{StatusCode::unreadable_file, path + ": cannot open"};
  detail::ObjSideFacts facts;
  Result<Mesh> read = detail::read_obj(in, triangle_limit_for(limits, file_bytes), facts);
  if (!read.ok()) return of_file(path, read.status());
  // Material libraries are never read, but one that would lead out of the
  // folder (a symlink out, a FIFO) is refused as every other format's
  // references are: judged by the same confinement, opening nothing.
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error).lexically_normal();
  const detail::ConfinedIOSystem confined(absolute.string(), limits.max_file_bytes);
  for (const std::string& library : facts.material_libraries) {
    static_cast<void>(confined.Exists((absolute.parent_path() / library).string().c_str()));
    if (std::optional<Status> refusal = refusal_of(confined, path)) return *refusal;
  }
  return imported_in_double(path, std::move(read).value(), facts.skipped_primitives);
}

// The project's ASCII STL reader (stl_ascii_reader.h), in double.
Result<ImportedMesh> import_ascii_stl(const std::string& path, const ImportLimits& limits, std::uint64_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status{StatusCode::unreadable_file, path + ": cannot open"};
  Result<Mesh> read = detail::read_ascii_stl(in, triangle_limit_for(limits, file_bytes));
  if (!read.ok()) return of_file(path, read.status());
  return imported_in_double(path, std::move(read).value(), 0);
}

// A PLY file by the project's reader (ply_reader.h), ASCII or binary, in
// double.
Result<ImportedMesh> import_ply(const std::string& path, const ImportLimits& limits, std::uint64_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status{StatusCode::unreadable_file, path + ": cannot open"};
  detail::PlyHeader header;
  if (Status read = detail::read_ply_header(in, file_bytes, header); !read.ok()) return of_file(path, read);
  int skipped = 0;
  Result<Mesh> read = detail::read_ply_body(in, header, file_bytes, triangle_limit_for(limits, file_bytes), skipped);
  if (!read.ok()) return of_file(path, read.status());
  return imported_in_double(path, std::move(read).value(), skipped);
}

Result<ImportedMesh> import_checked(const std::string& path, const ImportLimits& limits) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return Status{StatusCode::file_not_found, path + ": no such file"};
  if (!std::filesystem::is_regular_file(path, error))
    return Status{StatusCode::file_not_found, path + ": not a regular file"};
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (bytes == 0) return Status{StatusCode::empty_scene, path + ": the file is empty"};
  if (bytes > limits.max_file_bytes)
    return Status{StatusCode::limit_exceeded, path + ": " + std::to_string(bytes) + " bytes, more than the limit of " +
                                                  std::to_string(limits.max_file_bytes) +
                                                  " (raise it with --max-file-size)"};
  if (Status checked = detail::check_scene_file(path, limits); !checked.ok()) return of_file(path, checked);
  const std::string extension = detail::lower_extension(path);
  if (extension == ".obj") return import_obj(path, limits, bytes);
  if (extension == ".stl" && detail::is_ascii_stl(path, bytes)) return import_ascii_stl(path, limits, bytes);
  if (extension == ".ply") return import_ply(path, limits, bytes);
  return import_with_assimp(path, limits);
}

} // namespace

std::uint64_t default_triangle_limit(std::uint64_t input_bytes) {
  return std::clamp(input_bytes / kInputBytesPerDefaultTriangle, kDefaultTriangleLimitFloor,
                    kDefaultTriangleLimitCeiling);
}

Result<ImportedMesh> import_mesh(const std::string& path, const ImportLimits& limits) {
  try {
    std::optional<Result<ImportedMesh>> result;
    std::exception_ptr failure;
    run_on_large_stack([&] {
      try {
        result = import_checked(path, limits);
      } catch (...) {
        failure = std::current_exception();
      }
    });
    if (failure) std::rethrow_exception(failure);
    return std::move(*result);
  } catch (const std::exception& e) {
    return Status{StatusCode::unreadable_file, path + ": cannot read: " + e.what()};
  } catch (...) {
    return Status{StatusCode::unreadable_file, path + ": cannot read: unknown importer failure"};
  }
}

} // namespace hullcover
