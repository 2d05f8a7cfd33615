#include "prepared_scene_view.h"

namespace hullcover {
namespace {

template <class T>
MappableArray<T> view_of_vector(const std::vector<T>& elements) {
  return MappableArray<T>::view(elements.data(), elements.size());
}

template <class T>
std::vector<T> copy_of_array(const MappableArray<T>& elements) {
  return std::vector<T>(elements.begin(), elements.end());
}

} // namespace

IslandsView view_of(const MeshIslands& islands) {
  return {view_of_vector(islands.island_of_face), view_of_vector(islands.boxes), view_of_vector(islands.face_counts)};
}

PreparedSceneView view_of(const PreparedMesh& prepared) {
  PreparedSceneView view;
  const Mesh& mesh = prepared.mesh;
  view.mesh = {view_of_vector(mesh.positions),
               view_of_vector(mesh.triangles),
               view_of_vector(mesh.material_ids),
               mesh.material_names,
               mesh.coordinate_error,
               mesh.coordinate_relative_error};
  view.tolerance = prepared.tolerance;
  view.islands = view_of(prepared.islands);
  const MeshConnectivity& c = prepared.connectivity;
  view.connectivity = {view_of_vector(c.edges),
                       view_of_vector(c.edge_uses),
                       view_of_vector(c.face_edges),
                       view_of_vector(c.face_neighbours),
                       view_of_vector(c.zero_area),
                       view_of_vector(c.face_component),
                       c.component_count};
  view.vertices_before_weld = prepared.vertices_before_weld;
  view.unreferenced_dropped = prepared.unreferenced_dropped;
  return view;
}

PreparedMesh copy_of(const PreparedSceneView& view) {
  PreparedMesh prepared;
  Mesh& mesh = prepared.mesh;
  mesh.positions = copy_of_array(view.mesh.positions);
  mesh.triangles = copy_of_array(view.mesh.triangles);
  mesh.material_ids = copy_of_array(view.mesh.material_ids);
  mesh.material_names = view.mesh.material_names;
  mesh.coordinate_error = view.mesh.coordinate_error;
  mesh.coordinate_relative_error = view.mesh.coordinate_relative_error;
  prepared.tolerance = view.tolerance;
  prepared.islands.island_of_face = copy_of_array(view.islands.island_of_face);
  prepared.islands.boxes = copy_of_array(view.islands.boxes);
  prepared.islands.face_counts = copy_of_array(view.islands.face_counts);
  MeshConnectivity& c = prepared.connectivity;
  c.edges = copy_of_array(view.connectivity.edges);
  c.edge_uses = copy_of_array(view.connectivity.edge_uses);
  c.face_edges = copy_of_array(view.connectivity.face_edges);
  c.face_neighbours = copy_of_array(view.connectivity.face_neighbours);
  c.zero_area = copy_of_array(view.connectivity.zero_area);
  c.face_component = copy_of_array(view.connectivity.face_component);
  c.component_count = view.connectivity.component_count;
  prepared.vertices_before_weld = view.vertices_before_weld;
  prepared.unreferenced_dropped = view.unreferenced_dropped;
  return prepared;
}

} // namespace hullcover
