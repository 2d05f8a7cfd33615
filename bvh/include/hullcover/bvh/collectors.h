#pragma once
/// \file collectors.h
/// What a query hands its hits to, and which hulls it considers: the
/// collector and filter form of every HullWorld query (hull_world.h),
/// after Jolt's NarrowPhaseQuery. A collector receives each hit as the tree
/// walk finds it and may stop the walk; a filter skips hulls before any
/// exact test. The collectors here keep their storage between queries, so
/// a server that reuses one allocates nothing per query once it has grown.

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace hullcover::bvh {

/// Which hulls a query considers. Plain data: copy it freely.
struct HullFilter {
  /// Bit m set: hulls of material m are considered (materials 63 and up
  /// share bit 63; negative materials bit 0). Default: every material.
  std::uint64_t material_mask = ~std::uint64_t{0};
  /// When set, called with `context` and a hull's index after the material
  /// test; false skips the hull. It runs on the querying thread and must
  /// not query the same world's collectors.
  bool (*accept)(const void* context, int hull) = nullptr;
  const void* context = nullptr;

  /// Whether every hull is considered (the default): queries then skip
  /// the test, and never read a hull's material for it.
  bool admits_all() const { return material_mask == ~std::uint64_t{0} && accept == nullptr; }

  /// Whether hull `hull`, of material `material`, is considered.
  bool admits(int hull, int material) const {
    const int bit = material < 0 ? 0 : material > 63 ? 63 : material;
    if (!(material_mask >> bit & 1u)) return false;
    return accept == nullptr || accept(context, hull);
  }
};

/// Receives a query's hits (`Hit`: a hull index, a Contact or a RayHit) in
/// the order the walk finds them. Derive from it for a callback collector:
/// `add` may call `stop()` to end the walk, a ray's collector may lower its
/// reach with `set_reach()` so that the walk skips hulls that begin beyond
/// it, and `on_reset()` clears what it keeps.
template <typename Hit>
class HitCollector {
public:
  virtual ~HitCollector() = default;
  /// One hit. Called on the querying thread.
  virtual void add(const Hit& hit) = 0;
  /// Ready for the next query (every query calls it first): the walk's
  /// state cleared, then on_reset() for what the collector keeps.
  void reset() {
    stopped_ = false;
    reach_ = std::numeric_limits<double>::infinity();
    on_reset();
  }
  /// Whether the walk should end now.
  bool stopped() const { return stopped_; }
  /// Rays: hits farther along than this are not wanted.
  double reach() const { return reach_; }

protected:
  /// Clears what the collector keeps (its hits). Default: nothing.
  virtual void on_reset() {}
  void stop() { stopped_ = true; }
  void set_reach(double reach) { reach_ = reach; }

private:
  bool stopped_ = false;
  double reach_ = std::numeric_limits<double>::infinity();
};

/// One hit kept: what AnyHitCollector and BestHitCollector share.
template <typename Hit>
class OneHitCollector : public HitCollector<Hit> {
public:
  /// Whether a hit was kept since the last reset().
  bool found() const { return found_; }
  /// The hit kept; meaningful when found().
  const Hit& hit() const { return hit_; }

protected:
  void keep(const Hit& hit) {
    hit_ = hit;
    found_ = true;
  }

private:
  void on_reset() override { found_ = false; }
  Hit hit_{};
  bool found_ = false;
};

/// Keeps the first hit and stops: the yes/no query.
template <typename Hit>
class AnyHitCollector final : public OneHitCollector<Hit> {
public:
  /// Keeps `hit` and stops the walk.
  void add(const Hit& hit) override {
    this->keep(hit);
    this->stop();
  }
};

/// Keeps every hit, in walk order, in a vector whose capacity survives
/// reset(): reused, it allocates only to grow.
template <typename Hit>
class AllHitsCollector final : public HitCollector<Hit> {
public:
  /// Appends `hit`.
  void add(const Hit& hit) override { hits_.push_back(hit); }
  /// The hits since the last reset(), in walk order.
  const std::vector<Hit>& hits() const { return hits_; }
  /// The hits, to sort or move out (then reset() before the next query).
  std::vector<Hit>& hits() { return hits_; }

private:
  void on_reset() override { hits_.clear(); }
  std::vector<Hit> hits_;
};

/// Keeps the best hit by `Better`, a default-constructible type with
/// `bool operator()(const Hit& a, const Hit& b)` (a beats b) and
/// `static double reach_after(const Hit& best)`: the reach() the collector
/// lowers itself to once it holds `best` (for rays, best.t, so the walk skips
/// every hull that begins beyond; infinity when hits do not shorten the walk).
/// For the closest ray hit with ray_cast's tie rule: at equal t the lower
/// hull index wins.
template <typename Hit, typename Better>
class BestHitCollector final : public OneHitCollector<Hit> {
public:
  /// Keeps `hit` when it beats the one kept, and lowers reach().
  void add(const Hit& hit) override {
    if (this->found() && !Better{}(hit, this->hit())) return;
    this->keep(hit);
    const double r = Better::reach_after(hit);
    if (r < this->reach()) this->set_reach(r);
  }
};

} // namespace hullcover::bvh
