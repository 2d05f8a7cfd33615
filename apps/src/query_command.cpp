// `hullcover query WORLD.hcw --sphere ... | --capsule ... | --box ... | --ray ...`:
// one query against a runtime file, for trying the runtime by hand.

#include "number_checks.h"
#include "commands.h"

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"

#include <cstdio>
#include <memory>

namespace hullcover::app {
namespace {

struct QueryOptions {
  std::string world;
  std::vector<double> sphere, capsule, box, ray;
  int max_contacts = 8;
};

void print_vector(const char* name, const Eigen::Vector3d& v) {
  std::printf("%s (%.9g, %.9g, %.9g)", name, v.x(), v.y(), v.z());
}

int run_query(const QueryOptions& o) {
  const int given = !o.sphere.empty() + !o.capsule.empty() + !o.box.empty() + !o.ray.empty();
  if (given != 1) {
    std::fprintf(stderr, "hullcover: error: give exactly one of --sphere, --capsule, --box, --ray\n");
    return kExitBadInput;
  }
  Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(o.world);
  if (!hulls.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", hulls.status().message().c_str());
    return kExitBadInput;
  }
  Result<std::shared_ptr<const bvh::HullWorld>> world = bvh::HullWorld::build(std::move(hulls).value());
  if (!world.ok()) {
    std::fprintf(stderr, "hullcover: error: %s: %s\n", o.world.c_str(), world.status().message().c_str());
    return kExitBadInput;
  }
  const bvh::HullWorld& w = *world.value();

  if (!o.ray.empty()) {
    bvh::RayResult hit;
    const bvh::RayRequest request{
        {o.ray[0], o.ray[1], o.ray[2]}, {o.ray[3], o.ray[4], o.ray[5]}, o.ray.size() > 6 ? o.ray[6] : 1e30};
    if (Status s = w.ray_cast(request, hit); !s.ok()) {
      std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
      return kExitBadInput;
    }
    if (!hit.hit) {
      std::printf("ray: no hit\n");
      return kExitSuccess;
    }
    std::printf("ray: hull %d at t %.9g ", hit.first.hull, hit.first.t);
    print_vector("point", hit.first.point);
    print_vector(" normal", hit.first.normal);
    std::printf("\n");
    return kExitSuccess;
  }

  bvh::QueryShape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (!o.sphere.empty()) {
    shape = bvh::QueryShape::sphere(o.sphere[3]);
    pose.translation() = Eigen::Vector3d(o.sphere[0], o.sphere[1], o.sphere[2]);
  } else if (!o.capsule.empty()) {
    shape = bvh::QueryShape::capsule(o.capsule[3], o.capsule[4]);
    pose.translation() = Eigen::Vector3d(o.capsule[0], o.capsule[1], o.capsule[2]);
    const Eigen::Vector3d axis =
        o.capsule.size() == 8 ? Eigen::Vector3d(o.capsule[5], o.capsule[6], o.capsule[7]) : Eigen::Vector3d::UnitY();
    pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis.normalized()).toRotationMatrix();
  } else {
    shape = bvh::QueryShape::box({o.box[3], o.box[4], o.box[5]});
    pose.translation() = Eigen::Vector3d(o.box[0], o.box[1], o.box[2]);
  }
  bvh::ContactResult contacts;
  if (Status s = w.contacts({shape, pose, o.max_contacts}, contacts); !s.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", s.message().c_str());
    return kExitBadInput;
  }
  std::printf("%zu contact(s)\n", contacts.contacts.size());
  for (const bvh::Contact& c : contacts.contacts) {
    std::printf("  hull %d depth %.9g ", c.hull, c.depth);
    print_vector("normal", c.normal);
    print_vector(" point", c.point);
    std::printf("\n");
  }
  if (contacts.contacts.empty() && shape.kind != bvh::ShapeKind::box) {
    bvh::DistanceResult d;
    if (w.distance({shape, pose}, d).ok() && d.hull >= 0) {
      std::printf("nearest: hull %d at distance %.9g ", d.hull, d.distance);
      print_vector("point", d.on_world);
      std::printf("\n");
    }
  }
  return kExitSuccess;
}

} // namespace

void register_query_command(CLI::App& app, int& exit_status) {
  auto o = std::make_shared<QueryOptions>();
  CLI::App* cmd = app.add_subcommand(
      "query",
      "Ask a runtime file (from 'decompose --world') one question: the contacts of a sphere, capsule\n"
      "or box (with the nearest hull when there are none), or the first hit of a ray. Normals point\n"
      "out of the world hull, towards the shape; depth is how far to move along it to separate.");
  cmd->add_option("WORLD", o->world, "Runtime file (.hcw)")->required();
  cmd->add_option("--sphere", o->sphere, "x,y,z,radius")
      ->delimiter(',')
      ->expected(4)
      ->check(coordinate())
      ->check(positive_number().application_index(3));
  cmd->add_option("--capsule", o->capsule,
                  "x,y,z,radius,half_height[,ax,ay,az]: centre, end-sphere radius, half the axis length,\n"
                  "axis direction (default 0,1,0: upright in a y-up scene)")
      ->delimiter(',')
      ->expected(5, 8)
      ->check(coordinate())
      ->check(positive_number().application_index(3))
      ->check(non_negative_number().application_index(4));
  cmd->add_option("--box", o->box, "x,y,z,hx,hy,hz: centre and half extents (axis-aligned)")
      ->delimiter(',')
      ->expected(6)
      ->check(coordinate())
      ->check(positive_number().application_index(3))
      ->check(positive_number().application_index(4))
      ->check(positive_number().application_index(5));
  cmd->add_option("--ray", o->ray, "ox,oy,oz,dx,dy,dz[,max_distance]")
      ->delimiter(',')
      ->expected(6, 7)
      ->check(coordinate())
      ->check(positive_number().application_index(6));
  cmd->add_option("--max-contacts", o->max_contacts, "Most contacts to report")->check(count_from(1, kMostContacts));
  cmd->callback([o, &exit_status] { exit_status = run_query(*o); });
}

} // namespace hullcover::app
