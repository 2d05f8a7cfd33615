#pragma once
/// \file hull_world.h
/// The runtime a game server links: a covering's hulls in a four-wide float
/// box tree with every hull's planes packed in floats (walked directly: no
/// callback or allocation per query; float tests only skip or confirm
/// beyond their rounding bounds), and hullcover's exact narrow phase for
/// every answer: yes/no, contacts, rays, distances and sweeps
/// (hull_contact.h); collector and filter forms (collectors.h) and batches
/// on threads (query_threads.h).
///
/// Every query takes a Request and fills a Result (as FCL does), returns a
/// [[nodiscard]] Status and never throws. Queries are const and safe to run
/// from many threads at once on one world.

#include "hullcover/bvh/hull_contact.h"
#include "hullcover/bvh/hull_queries.h"
#include "hullcover/bvh/query_shape.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <memory>
#include <optional>
#include <vector>

namespace hullcover::bvh {

namespace detail {
class HullTree;
class PackedPlanes;
struct TreeSource;
} // namespace detail

/// A covering's hulls, built once, then queried from any number of threads.
/// What a game server writes (tests/support/runtime_only_example.cpp runs
/// it):
///
///     using namespace hullcover;
///     Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file("level.hcw");
///     if (!hulls.ok()) return fail(hulls.status());  // message says what and where
///     Result<std::shared_ptr<const bvh::HullWorld>> built = bvh::HullWorld::build(std::move(hulls).value());
///     if (!built.ok()) return fail(built.status());
///     const std::shared_ptr<const bvh::HullWorld> world = built.value();
///
///     // Once per character per tick, from any thread:
///     bvh::ContactRequest request;
///     request.shape = bvh::QueryShape::capsule(0.4, 0.5);  // radius, half height (scene units)
///     request.pose.linear() = up_is_y;                     // the capsule's axis is its local z
///     request.pose.translation() = position;
///     bvh::ContactResult result;
///     if (Status s = world->contacts(request, result); !s.ok()) return fail(s);
///     if (!result.contacts.empty()) {                      // deepest first
///       const bvh::Contact& c = result.contacts.front();
///       position += c.depth * c.normal;                    // out of that hull, to touching
///     }
///
/// Every query leaves its result meaningful only when the Status is ok.
class HullWorld : public HullQueries<HullWorld> {
public:
  /// Builds from runtime hulls (index i is hull i in every result).
  /// Fails with `invalid_argument` for an empty list or a hull with no
  /// facets or non-finite data.
  static Result<std::shared_ptr<const HullWorld>> build(std::vector<RuntimeHull> hulls);

  ~HullWorld();
  HullWorld(const HullWorld&) = delete;
  HullWorld& operator=(const HullWorld&) = delete;

  /// The hulls, in the order given to build (hull i of every result).
  const std::vector<RuntimeHull>& hulls() const { return hulls_; }

private:
  HullWorld() = default;
  std::vector<RuntimeHull> hulls_;
  // The broad phase, kept out of this header: fcl headers are slow to compile.
  std::unique_ptr<detail::HullTree> tree_;
  // Every hull's planes in floats, for the yes/no and overlap queries'
  // first test of a hull, and in double for the ray clip.
  std::unique_ptr<detail::PackedPlanes> planes_;

  friend class HullQueries<HullWorld>;
  // The hulls and tree as a hull source for the queries (world_queries.h).
  detail::TreeSource source() const;
};

} // namespace hullcover::bvh
