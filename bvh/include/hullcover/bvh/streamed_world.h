#pragma once
/// \file streamed_world.h
/// A world whose cells (sections of a runtime file, runtime_file.h) stream
/// in and out while a server runs. Each published snapshot holds a
/// four-wide tree over the loaded sections' boxes, rebuilt as sections come
/// and go; each section's hulls sit in a packed tree and plane store of
/// their own, built once when it loads, as HullWorld builds its one.
/// Queries answer with the file's global hull indices and run the same code
/// as HullWorld's: whenever every section a query reaches is loaded, the
/// answer is the answer of a HullWorld built from the whole file, hull for
/// hull and number for number (TouchResult::hull excepted: which touching
/// hull comes first depends on the trees).
///
/// Threading contract:
///  - Queries are const and may run from any number of threads at once,
///    also while add_section or remove_section runs on other threads.
///  - Each query call (a whole ray batch included) answers on one snapshot
///    of the loaded sections, taken when it starts: a section loaded or
///    unloaded meanwhile is wholly in or wholly out of its answer, never
///    half. A later call sees every add or remove that returned before it
///    started.
///  - add_section does its heavy work (the section's tree) with no lock
///    held; add and remove calls then take turns, briefly, to publish a new
///    snapshot (FCL's tree updated, packed, swapped in with std::atomic_store;
///    queries take it with std::atomic_load and never wait for a build).
///  - A section's memory is freed when the last query still using an older
///    snapshot returns.
///  - The world itself must outlive every call on it (as any object).
///
/// Every call returns a [[nodiscard]] Status or Result and never throws.

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_file.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace hullcover::bvh {

namespace detail {
struct StreamSnapshot;
struct SnapshotSource;
class SectionIndex;
} // namespace detail

/// Sections of one world, loaded and unloaded at run time, queried like a
/// HullWorld (HullQueries) over the sections loaded when each call starts,
/// with global hull indices. Where a query's answer reaches beyond them:
///  - touches: TouchResult::hull may name another touching hull than a
///    HullWorld's would (the first its trees meet);
///  - distance: the nearest loaded hull; the search stops four diagonals of
///    the loaded sections' box out; nothing loaded: `hull` -1, distance
///    infinite. It equals the whole world's answer when every section within
///    that answer's distance of the shape is loaded;
///  - ray_cast, ray_cast_batch: sections are walked nearer boxes first and
///    pruned at the best hit, as hulls are; a batch answers every ray on one
///    snapshot;
///  - sweep: against the loaded hulls whose boxes meet the swept box.
///
/// What a server streaming cells writes:
///
///     using namespace hullcover;
///     bvh::StreamedWorld world;  // empty: every query finds nothing
///     Result<bvh::SectionHulls> cell = bvh::read_runtime_section("level.hcw", 12);
///     if (!cell.ok()) return fail(cell.status());
///     if (Status s = world.add_section(std::move(cell).value()); !s.ok()) return fail(s);
///     // ... from any thread, meanwhile and after:
///     bvh::ContactResult result;
///     if (Status s = world.contacts(request, result); !s.ok()) return fail(s);  // global hull indices
///     // ... when the players leave the cell:
///     if (Status s = world.remove_section(12); !s.ok()) return fail(s);
class StreamedWorld : public HullQueries<StreamedWorld> {
public:
  /// An empty world: no section loaded. Allocates nothing.
  StreamedWorld() noexcept;
  ~StreamedWorld();
  StreamedWorld(const StreamedWorld&) = delete;
  StreamedWorld& operator=(const StreamedWorld&) = delete;

  /// Loads a section (read_runtime_section gives one): builds its tree with
  /// no lock held, then publishes it. Its hulls answer by
  /// `section.indices`. Fails with `invalid_argument`, loading nothing,
  /// when it has no hull, its indices are not one per hull, ascending and
  /// >= 0, a hull has no facets or non-finite data (as HullWorld::build),
  /// section `section.id` is already loaded, or one of its indices belongs
  /// to a loaded section; with `internal_error` when memory runs out.
  [[nodiscard]] Status add_section(SectionHulls section);

  /// Unloads section `id`: later queries no longer see its hulls; queries
  /// already running finish on the snapshot they took. Fails with
  /// `invalid_argument` when it is not loaded.
  [[nodiscard]] Status remove_section(std::uint32_t id);

  /// The ids of the loaded sections, ascending, as of this call.
  [[nodiscard]] Result<std::vector<std::uint32_t>> loaded_sections() const;

  // The queries (touches, overlap, contacts, ray_cast, ray_cast_batch,
  // distance, sweep) are HullQueries', documented there.

private:
  // Serialises add_section's and remove_section's publishing (and index_).
  std::mutex writer_;
  // The writer's side: FCL's dynamic tree of the loaded sections' boxes and
  // who holds which hull. Made by the first add_section.
  std::unique_ptr<detail::SectionIndex> index_;
  // What queries read: replaced whole, never changed, through
  // std::atomic_load / std::atomic_store. Null until the first section.
  std::shared_ptr<const detail::StreamSnapshot> current_;

  friend class HullQueries<StreamedWorld>;
  // The snapshot loaded now, as a hull source for one query (world_queries.h).
  detail::SnapshotSource source() const;
  // Packs index_ into a new snapshot and swaps it in (writer_ held).
  void publish();
};

} // namespace hullcover::bvh
