// The Python module `hullcover._hullcover`: decompose, World and audit on
// numpy arrays, as CoACD and trimesh users expect. The Python side
// (apps/python/hullcover/__init__.py) turns options and JSON into keyword
// arguments and dicts. No exception of hullcover's reaches Python except as
// ValueError (bad input) or RuntimeError (anything else), with its message.

#include "audit_report_json.h"
#include "python_binding.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"
#include "hullcover/covering/covering.h"
#include "hullcover/covering/covering_export.h"
#include "hullcover/mesh/prepared_mesh.h"
#include "hullcover/validate/audit.h"
#include "hullcover/validate/hull_set.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace py = pybind11;

namespace hullcover::python {
namespace {

// An (n, 3) array's rows, checked.
std::vector<Eigen::Vector3d> rows_of(const Points& a, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 3) throw py::value_error(std::string(what) + " must be an (n, 3) array");
  std::vector<Eigen::Vector3d> out(static_cast<size_t>(a.shape(0)));
  auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) out[i] = {r(i, 0), r(i, 1), r(i, 2)};
  return out;
}

Points array_of(const std::vector<Eigen::Vector3d>& rows) {
  Points out({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(3)});
  auto w = out.mutable_unchecked<2>();
  for (size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) w(i, k) = rows[i][k];
  return out;
}

// The mesh of `vertices` (n, 3) and `faces` (m, 3), material 0; indices are
// checked by validate_mesh when it is prepared.
Mesh mesh_of(const Points& vertices, const Indices& faces) {
  Mesh mesh;
  mesh.positions = rows_of(vertices, "vertices");
  if (faces.ndim() != 2 || faces.shape(1) != 3)
    throw py::value_error("faces must be an (m, 3) array of vertex indices");
  auto f = faces.unchecked<2>();
  for (py::ssize_t i = 0; i < faces.shape(0); ++i) {
    Eigen::Vector3i t;
    for (int k = 0; k < 3; ++k) {
      const std::int64_t v = f(i, k);
      if (v < 0 || v >= static_cast<std::int64_t>(mesh.positions.size()))
        throw py::value_error("faces[" + std::to_string(i) +
                              "] names a vertex that does not exist: " + std::to_string(v));
      t[k] = static_cast<int>(v);
    }
    mesh.triangles.push_back(t);
  }
  mesh.material_ids.assign(mesh.triangles.size(), 0);
  return mesh;
}

PreparedMesh prepared_of(const Points& vertices, const Indices& faces, std::optional<double> tol) {
  Result<PreparedMesh> prepared = prepare_mesh(mesh_of(vertices, faces), tol);
  if (!prepared.ok()) raise(prepared.status());
  return std::move(prepared).value();
}

py::list hull_arrays(const Decomposition& d) {
  py::list out;
  for (const CoveringHull& hull : d.covering.hulls) {
    py::array_t<std::int32_t> fanned(
        {static_cast<py::ssize_t>(triangles_of_facets(hull.polytope.facets)), static_cast<py::ssize_t>(3)});
    auto w = fanned.mutable_unchecked<2>();
    py::ssize_t row = 0;
    for (const std::vector<int>& facet : hull.polytope.facets)
      for (size_t k = 1; k + 1 < facet.size(); ++k, ++row) {
        w(row, 0) = facet[0];
        w(row, 1) = facet[k];
        w(row, 2) = facet[k + 1];
      }
    py::dict h;
    h["vertices"] = array_of(hull.polytope.vertices);
    h["triangles"] = fanned;
    h["faces"] = py::array_t<std::int32_t>(static_cast<py::ssize_t>(hull.faces.size()), hull.faces.data());
    h["planar"] = hull.planar;
    h["thickness"] = hull.thickness;
    out.append(h);
  }
  return out;
}

std::shared_ptr<Decomposition> run_decompose(const Points& vertices, const Indices& faces, std::optional<double> tol,
                                             const DecomposeOptions& options) {
  auto d = std::make_shared<Decomposition>();
  const PreparedMesh prepared = prepared_of(vertices, faces, tol);
  Result<Covering> covering = [&] {
    py::gil_scoped_release unlocked; // every core while Python waits
    return decompose(prepared, options);
  }();
  if (!covering.ok()) raise(covering.status());
  d->covering = std::move(covering).value();
  return d;
}

using World = bvh::HullWorld;
// pybind11 holds objects by a non-const shared_ptr; the world is only ever
// used through const methods.
using WorldPtr = std::shared_ptr<World>;

WorldPtr world_of(std::vector<bvh::RuntimeHull> hulls) {
  Result<std::shared_ptr<const World>> built = World::build(std::move(hulls));
  if (!built.ok()) raise(built.status());
  return std::const_pointer_cast<World>(built.value());
}

// The rays of origins and directions (n, 3) and a max distance (scalar).
std::vector<bvh::RayRequest> rays_of(const Points& origins, const Points& directions, double max_distance) {
  const std::vector<Eigen::Vector3d> o = rows_of(origins, "origins"), d = rows_of(directions, "directions");
  if (o.size() != d.size()) throw py::value_error("origins and directions must have as many rows");
  std::vector<bvh::RayRequest> requests(o.size());
  for (size_t i = 0; i < o.size(); ++i) requests[i] = {o[i], d[i], max_distance};
  return requests;
}

// A ray batch (ray_cast_batch or ray_blocked_batch) without the GIL.
template <typename Batch>
std::vector<bvh::RayResult> ray_batch(const std::vector<bvh::RayRequest>& requests, Batch&& batch) {
  std::vector<bvh::RayResult> results;
  Status status;
  {
    py::gil_scoped_release unlocked;
    status = batch(requests, results);
  }
  if (!status.ok()) raise(status);
  return results;
}

// Rays: origins and directions (n, 3), max distance (scalar). Returns
// (hit bool (n,), t (n,), hull (n,), point (n, 3), normal (n, 3)).
py::tuple cast_rays(const World& world, const Points& origins, const Points& directions, double max_distance) {
  const std::vector<bvh::RayRequest> requests = rays_of(origins, directions, max_distance);
  const std::vector<bvh::RayResult> results =
      ray_batch(requests, [&](const auto& q, auto& r) { return world.ray_cast_batch(q, r); });
  const py::ssize_t n = static_cast<py::ssize_t>(requests.size());
  py::array_t<bool> hit(n);
  py::array_t<double> t(n);
  py::array_t<std::int32_t> hull(n);
  std::vector<Eigen::Vector3d> points(requests.size()), normals(requests.size());
  auto h = hit.mutable_unchecked<1>();
  auto tt = t.mutable_unchecked<1>();
  auto hh = hull.mutable_unchecked<1>();
  for (size_t i = 0; i < results.size(); ++i) {
    h(i) = results[i].hit;
    tt(i) = results[i].hit ? results[i].first.t : std::numeric_limits<double>::infinity();
    hh(i) = results[i].hit ? results[i].first.hull : -1;
    points[i] = results[i].first.point;
    normals[i] = results[i].first.normal;
  }
  return py::make_tuple(hit, t, hull, array_of(points), array_of(normals));
}

// Lines of sight: whether each ray meets any hull within max_distance
// (ray_blocked_batch: stops at the first hull found). Returns bool (n,).
py::array_t<bool> rays_blocked(const World& world, const Points& origins, const Points& directions,
                               double max_distance) {
  const std::vector<bvh::RayRequest> requests = rays_of(origins, directions, max_distance);
  const std::vector<bvh::RayResult> results =
      ray_batch(requests, [&](const auto& q, auto& r) { return world.ray_blocked_batch(q, r); });
  py::array_t<bool> blocked(static_cast<py::ssize_t>(results.size()));
  auto b = blocked.mutable_unchecked<1>();
  for (size_t i = 0; i < results.size(); ++i) b(static_cast<py::ssize_t>(i)) = results[i].hit;
  return blocked;
}

// The query shape of row i: spheres (radius), capsules along z (radius,
// half height) placed at centres, no rotation.
bvh::QueryShape shape_of(const std::string& kind, double radius, double half_height) {
  if (kind == "sphere") return bvh::QueryShape::sphere(radius);
  if (kind == "capsule") return bvh::QueryShape::capsule(radius, half_height);
  throw py::value_error("shape must be 'sphere' or 'capsule', not '" + kind + "'");
}

// Overlaps: does each shape touch any hull. Returns bool (n,).
py::array_t<bool> overlaps(const World& world, const std::string& kind, const Points& centres, double radius,
                           double half_height) {
  const std::vector<Eigen::Vector3d> c = rows_of(centres, "centres");
  const bvh::QueryShape shape = shape_of(kind, radius, half_height);
  py::array_t<bool> out(static_cast<py::ssize_t>(c.size()));
  auto w = out.mutable_unchecked<1>();
  std::vector<char> touching(c.size(), 0);
  Status failed;
  {
    py::gil_scoped_release unlocked;
    for (size_t i = 0; i < c.size() && failed.ok(); ++i) {
      bvh::OverlapRequest request;
      request.shape = shape;
      request.pose.translation() = c[i];
      bvh::TouchResult result;
      failed = world.touches(request, result);
      touching[i] = result.touching;
    }
  }
  if (!failed.ok()) raise(failed);
  for (size_t i = 0; i < c.size(); ++i) w(i) = touching[i] != 0;
  return out;
}

// Deepest contact per shape: (touching (n,), depth (n,), hull (n,),
// normal (n, 3), point (n, 3)); depth 0, hull -1 where none.
py::tuple deepest_contacts(const World& world, const std::string& kind, const Points& centres, double radius,
                           double half_height) {
  const std::vector<Eigen::Vector3d> c = rows_of(centres, "centres");
  const bvh::QueryShape shape = shape_of(kind, radius, half_height);
  std::vector<bvh::Contact> deepest(c.size());
  std::vector<char> touching(c.size(), 0);
  Status failed;
  {
    py::gil_scoped_release unlocked;
    for (size_t i = 0; i < c.size() && failed.ok(); ++i) {
      bvh::ContactRequest request;
      request.shape = shape;
      request.pose.translation() = c[i];
      request.max_contacts = 1;
      bvh::ContactResult result;
      failed = world.contacts(request, result);
      if (!result.contacts.empty()) deepest[i] = result.contacts.front(), touching[i] = 1;
    }
  }
  if (!failed.ok()) raise(failed);
  const py::ssize_t n = static_cast<py::ssize_t>(c.size());
  py::array_t<bool> touch(n);
  py::array_t<double> depth(n);
  py::array_t<std::int32_t> hull(n);
  std::vector<Eigen::Vector3d> normals(c.size()), points(c.size());
  auto tw = touch.mutable_unchecked<1>();
  auto dw = depth.mutable_unchecked<1>();
  auto hw = hull.mutable_unchecked<1>();
  for (size_t i = 0; i < c.size(); ++i) {
    tw(i) = touching[i] != 0;
    dw(i) = touching[i] ? deepest[i].depth : 0.0;
    hw(i) = touching[i] ? deepest[i].hull : -1;
    normals[i] = touching[i] ? deepest[i].normal : Eigen::Vector3d::Zero();
    points[i] = touching[i] ? deepest[i].point : Eigen::Vector3d::Zero();
  }
  return py::make_tuple(touch, depth, hull, array_of(normals), array_of(points));
}

std::string run_audit_json(const Points& vertices, const Indices& faces, const std::string& hulls_path,
                           const Decomposition* decomposition, std::optional<double> tol,
                           const validate::AuditOptions& options) {
  const PreparedMesh prepared = prepared_of(vertices, faces, tol);
  validate::HullSet set;
  if (decomposition) {
    set.hulls = bvh::runtime_hulls(decomposition->covering);
  } else {
    Result<validate::HullSet> loaded = validate::load_hull_set(hulls_path);
    if (!loaded.ok()) raise(loaded.status());
    set = std::move(loaded).value();
  }
  const Result<validate::AuditReport> report = [&] {
    py::gil_scoped_release unlocked;
    return validate::run_audit(prepared, set, options);
  }();
  if (!report.ok()) raise(report.status());
  return app::audit_report_json(prepared, report.value()).dump();
}

} // namespace
} // namespace hullcover::python

PYBIND11_MODULE(_hullcover, m) {
  using namespace hullcover;
  using namespace hullcover::python;
  m.doc() = "hullcover's C++ core; use the hullcover package, which wraps it";

  py::class_<Decomposition, std::shared_ptr<Decomposition>>(m, "Decomposition")
      .def("hulls", &hull_arrays)
      .def("report_json", [](const Decomposition& d) { return covering_json(d.covering).dump(); })
      .def("tolerance", [](const Decomposition& d) { return d.covering.tolerance.length; })
      .def("hull_count", [](const Decomposition& d) { return d.covering.hulls.size(); })
      .def("world", [](const Decomposition& d) { return world_of(bvh::runtime_hulls(d.covering)); })
      .def(
          "write_obj",
          [](const Decomposition& d, const std::string& path) {
    if (Status s = write_covering_obj(d.covering, path); !s.ok()) raise(s);
          })
      .def(
          "write_world",
          [](const Decomposition& d, const std::string& path) {
    if (Status s = bvh::write_covering_runtime_file(d.covering, path); !s.ok()) raise(s);
          })
      .def("write_json", [](const Decomposition& d, const std::string& path, const std::string& extra) {
        if (Status s = write_covering_json(d.covering, nlohmann::json::parse(extra), path); !s.ok()) raise(s);
      });

  m.def(
      "decompose",
      [](const Points& vertices, const Indices& faces, std::optional<double> tol, int threads,
         std::optional<double> cell_size, std::optional<double> agent_radius, std::optional<double> max_deviation,
         std::optional<double> near_merge_distance, int max_hull_vertices, std::optional<int> max_hull_triangles) {
    return run_decompose(vertices, faces, tol,
                         options_of(threads, cell_size, agent_radius, max_deviation, near_merge_distance,
                                    max_hull_vertices, max_hull_triangles));
      },
      py::arg("vertices"), py::arg("faces"), py::arg("tol") = py::none(), py::arg("threads") = 0,
      py::arg("cell_size") = py::none(), py::arg("agent_radius") = py::none(), py::arg("max_deviation") = py::none(),
      py::arg("near_merge_distance") = py::none(), py::arg("max_hull_vertices") = kDefaultMaxHullVertices,
      py::arg("max_hull_triangles") = py::none());

  py::class_<World, WorldPtr>(m, "World")
      .def_static(
          "load",
          [](const std::string& path) {
    Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(path);
    if (!hulls.ok()) raise(hulls.status());
    return world_of(std::move(hulls).value());
          })
      .def("__len__", [](const World& w) { return w.hulls().size(); })
      .def("cast_rays", &cast_rays, py::arg("origins"), py::arg("directions"),
           py::arg("max_distance") = std::numeric_limits<double>::infinity())
      .def("rays_blocked", &rays_blocked, py::arg("origins"), py::arg("directions"),
           py::arg("max_distance") = std::numeric_limits<double>::infinity())
      .def("overlaps", &overlaps, py::arg("shape"), py::arg("centres"), py::arg("radius"), py::arg("half_height") = 0.0)
      .def("contacts", &deepest_contacts, py::arg("shape"), py::arg("centres"), py::arg("radius"),
           py::arg("half_height") = 0.0);

  m.def(
      "audit",
      [](const Points& vertices, const Indices& faces, const py::object& hulls, std::optional<double> tol,
         std::optional<double> agent_radius, std::optional<double> max_deviation, int proxies, std::uint64_t seed) {
    validate::AuditOptions options;
    options.behaviour.proxies = proxies;
    options.behaviour.seed = seed;
    options.probe.allowance.agent_radius = agent_radius;
    options.probe.allowance.max_deviation = max_deviation;
    if (py::isinstance<Decomposition>(hulls))
      return run_audit_json(vertices, faces, "", hulls.cast<const Decomposition*>(), tol, options);
    return run_audit_json(vertices, faces, hulls.cast<std::string>(), nullptr, tol, options);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("hulls"), py::arg("tol") = py::none(),
      py::arg("agent_radius") = py::none(), py::arg("max_deviation") = py::none(), py::arg("proxies") = 3000,
      py::arg("seed") = 1);

  bind_staged_bake(m);
}
