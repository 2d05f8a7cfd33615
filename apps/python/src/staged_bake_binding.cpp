// StagedBake: the staged decomposition (staged_decomposition.h) for
// `python3 -m hullcover.bake`: a worker loads a scene file once, merges the
// cells it is given into bytes; the client finishes from every cell's bytes.

#include "python_binding.h"

#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/mesh/mesh_import.h"

#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

namespace hullcover::python {
namespace {

struct StagedBake {
  std::unique_ptr<StagedDecomposition> staged;
};

// A scene file imported and prepared (called with the GIL released).
Result<PreparedMesh> prepared_from_file(const std::string& path, std::optional<double> tol) {
  Result<ImportedMesh> imported = import_mesh(path);
  if (!imported.ok()) return imported.status();
  Result<PreparedMesh> prepared = prepare_mesh(imported.value().mesh, tol);
  if (!prepared.ok()) return Status{prepared.status().code(), path + ": " + prepared.status().message()};
  return prepared;
}

std::shared_ptr<StagedBake> load_staged(const std::string& path, std::optional<double> tol,
                                        const DecomposeOptions& options) {
  auto bake = std::make_shared<StagedBake>();
  Result<std::unique_ptr<StagedDecomposition>> staged = [&]() -> Result<std::unique_ptr<StagedDecomposition>> {
    py::gil_scoped_release unlocked;
    Result<PreparedMesh> prepared = prepared_from_file(path, tol);
    if (!prepared.ok()) return prepared.status();
    return StagedDecomposition::prepare(std::move(prepared).value(), options);
  }();
  if (!staged.ok()) raise(staged.status());
  bake->staged = std::move(staged).value();
  return bake;
}

std::shared_ptr<StagedBake> map_staged(const std::string& path, const DecomposeOptions& options) {
  auto bake = std::make_shared<StagedBake>();
  Result<std::unique_ptr<StagedDecomposition>> staged = [&] {
    py::gil_scoped_release unlocked;
    return StagedDecomposition::map_prepared(path, options);
  }();
  if (!staged.ok()) raise(staged.status());
  bake->staged = std::move(staged).value();
  return bake;
}

void check_cell(const StagedBake& bake, int cell) {
  if (cell < 0 || cell >= bake.staged->cell_count())
    throw py::index_error("no cell " + std::to_string(cell) + " (the scene has " +
                          std::to_string(bake.staged->cell_count()) + ")");
}

void check_seam(const StagedBake& bake, int seam) {
  if (seam < 0 || seam >= bake.staged->seam_count())
    throw py::index_error("no seam cell " + std::to_string(seam) + " (the scene has " +
                          std::to_string(bake.staged->seam_count()) + ")");
}

// The Decomposition `finish` makes of the given bytes (with the GIL
// released while it runs).
template <class Finish>
std::shared_ptr<Decomposition> finished(const Finish& finish, const std::vector<py::bytes>& parts) {
  std::vector<std::string> contents(parts.begin(), parts.end());
  auto d = std::make_shared<Decomposition>();
  Result<Covering> covering = [&] {
    py::gil_scoped_release unlocked;
    return finish(contents);
  }();
  if (!covering.ok()) raise(covering.status());
  d->covering = std::move(covering).value();
  return d;
}

} // namespace

void bind_staged_bake(py::module_& m) {
  // The one-machine reference a distributed bake must equal: the scene file
  // decomposed in one call, as `hullcover decompose` does.
  m.def(
      "decompose_file",
      [](const std::string& path, std::optional<double> tol, int threads, std::optional<double> cell_size,
         std::optional<double> agent_radius, std::optional<double> max_deviation) {
    auto d = std::make_shared<Decomposition>();
    Result<Covering> covering = [&]() -> Result<Covering> {
      py::gil_scoped_release unlocked;
      Result<PreparedMesh> prepared = prepared_from_file(path, tol);
      if (!prepared.ok()) return prepared.status();
      return decompose(prepared.value(), options_of(threads, cell_size, agent_radius, max_deviation, std::nullopt,
                                                    kDefaultMaxHullVertices, std::nullopt));
    }();
    if (!covering.ok()) raise(covering.status());
    d->covering = std::move(covering).value();
    return d;
      },
      py::arg("path"), py::arg("tol") = py::none(), py::arg("threads") = 0, py::arg("cell_size") = py::none(),
      py::arg("agent_radius") = py::none(), py::arg("max_deviation") = py::none());

  py::class_<StagedBake, std::shared_ptr<StagedBake>>(m, "StagedBake")
      .def_static(
          "load",
          [](const std::string& path, std::optional<double> tol, int threads, std::optional<double> cell_size,
             std::optional<double> agent_radius, std::optional<double> max_deviation,
             std::optional<double> near_merge_distance, int max_hull_vertices, std::optional<int> max_hull_triangles) {
    return load_staged(path, tol,
                       options_of(threads, cell_size, agent_radius, max_deviation, near_merge_distance,
                                  max_hull_vertices, max_hull_triangles));
          },
          py::arg("path"), py::arg("tol") = py::none(), py::arg("threads") = 0, py::arg("cell_size") = py::none(),
          py::arg("agent_radius") = py::none(), py::arg("max_deviation") = py::none(),
          py::arg("near_merge_distance") = py::none(), py::arg("max_hull_vertices") = kDefaultMaxHullVertices,
          py::arg("max_hull_triangles") = py::none())
      .def_static(
          "map",
          [](const std::string& path, int threads, std::optional<double> cell_size, std::optional<double> agent_radius,
             std::optional<double> max_deviation, std::optional<double> near_merge_distance, int max_hull_vertices,
             std::optional<int> max_hull_triangles) {
    return map_staged(path, options_of(threads, cell_size, agent_radius, max_deviation, near_merge_distance,
                                       max_hull_vertices, max_hull_triangles));
          },
          py::arg("path"), py::arg("threads") = 0, py::arg("cell_size") = py::none(),
          py::arg("agent_radius") = py::none(), py::arg("max_deviation") = py::none(),
          py::arg("near_merge_distance") = py::none(), py::arg("max_hull_vertices") = kDefaultMaxHullVertices,
          py::arg("max_hull_triangles") = py::none())
      .def(
          "write_prepared",
          [](const StagedBake& b, const std::string& path) {
    Status written = [&] {
      py::gil_scoped_release unlocked;
      return b.staged->write_prepared(path);
    }();
    if (!written.ok()) raise(written);
          })
      .def("release_pages", [](const StagedBake& b) { b.staged->release_mapped_pages(); })
      .def("cell_count", [](const StagedBake& b) { return b.staged->cell_count(); })
      .def(
          "cell_face_count",
          [](const StagedBake& b, int cell) {
    check_cell(b, cell);
    return b.staged->cell_faces(cell).size();
          })
      .def(
          "cell_key",
          [](const StagedBake& b, int cell) {
    check_cell(b, cell);
    return b.staged->cell_key(cell);
          })
      .def(
          "merge_cell",
          [](const StagedBake& b, int cell) {
    check_cell(b, cell);
    Result<std::string> bytes = [&] {
      py::gil_scoped_release unlocked;
      return b.staged->merge_cell(cell);
    }();
    if (!bytes.ok()) raise(bytes.status());
    return py::bytes(bytes.value());
          })
      .def(
          "still_valid",
          [](const StagedBake& b, int cell, const py::bytes& bytes) {
    check_cell(b, cell);
    const std::string content = bytes;
    std::string why;
    bool valid = false;
    {
      py::gil_scoped_release unlocked;
      valid = b.staged->still_valid(cell, content, &why);
    }
    return py::make_tuple(valid, why);
          })
      .def("seam_count", [](const StagedBake& b) { return b.staged->seam_count(); })
      .def(
          "seam_cells",
          [](const StagedBake& b, int seam) {
    check_seam(b, seam);
    return b.staged->seam_cells(seam);
          })
      .def(
          "finish_seam",
          [](const StagedBake& b, int seam, const std::vector<py::bytes>& cells) {
    check_seam(b, seam);
    std::vector<std::string> contents(cells.begin(), cells.end());
    Result<std::string> bytes = [&] {
      py::gil_scoped_release unlocked;
      return b.staged->finish_seam(seam, contents);
    }();
    if (!bytes.ok()) raise(bytes.status());
    return py::bytes(bytes.value());
          })
      .def(
          "finish_seams",
          [](const StagedBake& b, const std::vector<py::bytes>& seams) {
    return finished([&](const std::vector<std::string>& contents) { return b.staged->finish_seams(contents); }, seams);
          })
      .def("finish", [](const StagedBake& b, const std::vector<py::bytes>& cells) {
        return finished([&](const std::vector<std::string>& contents) { return b.staged->finish(contents); }, cells);
      });
}

} // namespace hullcover::python
