// What a game server writes: load a runtime file, build the world, query it.
// Linked against hullcover::bvh alone (tests/CMakeLists.txt), which proves the
// runtime needs no part of the decomposer. Usage: hullcover_runtime_only WORLD.hcw

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"

#include <cstdio>

int main(int argc, char** argv) {
  using namespace hullcover;
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s WORLD.hcw\n", argv[0]);
    return 2;
  }
  Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(argv[1]);
  if (!hulls.ok()) {
    std::fprintf(stderr, "%s\n", hulls.status().message().c_str());
    return 2;
  }
  Result<std::shared_ptr<const bvh::HullWorld>> world = bvh::HullWorld::build(std::move(hulls).value());
  if (!world.ok()) {
    std::fprintf(stderr, "%s\n", world.status().message().c_str());
    return 2;
  }
  bvh::ContactRequest request;
  request.shape = bvh::QueryShape::capsule(0.4, 0.5);
  bvh::ContactResult result;
  if (Status s = world.value()->contacts(request, result); !s.ok()) {
    std::fprintf(stderr, "%s\n", s.message().c_str());
    return 2;
  }
  std::printf("%zu hulls; a capsule at the origin has %zu contacts\n", world.value()->hulls().size(),
              result.contacts.size());
  return 0;
}
