#pragma once
// What the module's binding files share: numpy array types, how a Status
// becomes a Python exception, the options every entry point takes, and the
// Decomposition object.

#include "hullcover/covering/covering.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <stdexcept>

namespace hullcover::python {

namespace py = pybind11;

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// ValueError for bad input, RuntimeError for anything else (internal_error).
[[noreturn]] inline void raise(const Status& status) {
  if (status.code() == StatusCode::internal_error) throw std::runtime_error(status.message());
  throw py::value_error(status.message());
}

/// The keyword options of decompose() and StagedBake.load().
inline DecomposeOptions options_of(int threads, std::optional<double> cell_size, std::optional<double> agent_radius,
                                   std::optional<double> max_deviation, std::optional<double> near_merge_distance,
                                   int max_hull_vertices, std::optional<int> max_hull_triangles) {
  DecomposeOptions options;
  options.threads = threads;
  options.cell_size = cell_size;
  options.agent_radius = agent_radius;
  options.max_deviation = max_deviation;
  options.near_merge_distance = near_merge_distance;
  options.max_hull_vertices = max_hull_vertices;
  options.max_hull_triangles = max_hull_triangles;
  return options;
}

/// A decomposition: the covering (which holds what its outputs need; the
/// scene is not kept).
struct Decomposition {
  Covering covering;
};

/// Adds StagedBake (staged_bake_binding.cpp) to the module.
void bind_staged_bake(py::module_& m);

} // namespace hullcover::python
