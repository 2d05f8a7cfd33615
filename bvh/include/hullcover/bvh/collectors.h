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
/// `add` may call `stop()` to end the walk, and a ray's collector may lower
/// `reach()` so that the walk skips hulls that begin beyond it.
template <typename Hit>
class HitCollector {
public:
  virtual ~HitCollector() = default;
  /// One hit. Called on the querying thread.
  virtual void add(const Hit& hit) = 0;
  /// Clears what was collected, ready for the next query (the query calls it).
  virtual void reset() {
    stopped_ = false;
    reach_ = std::numeric_limits<double>::infinity();
  }
  /// Whether the walk should end now.
  bool stopped() const { return stopped_; }
  /// Rays: hits farther along than this are not wanted.
  double reach() const { return reach_; }

protected:
  void stop() { stopped_ = true; }
  void set_reach(double reach) { reach_ = reach; }

private:
  bool stopped_ = false;
  double reach_ = std::numeric_limits<double>::infinity();
};

/// Keeps the first hit and stops: the yes/no query.
template <typename Hit>
class AnyHitCollector final : public HitCollector<Hit> {
public:
  void add(const Hit& hit) override {
    hit_ = hit;
    found_ = true;
    this->stop();
  }
  void reset() override {
    HitCollector<Hit>::reset();
    found_ = false;
  }
  bool found() const { return found_; }
  /// The hit kept; meaningful when found().
  const Hit& hit() const { return hit_; }

private:
  Hit hit_{};
  bool found_ = false;
};

/// Keeps every hit, in walk order, in a vector whose capacity survives
/// reset(): reused, it allocates only to grow.
template <typename Hit>
class AllHitsCollector final : public HitCollector<Hit> {
public:
  void add(const Hit& hit) override { hits_.push_back(hit); }
  void reset() override {
    HitCollector<Hit>::reset();
    hits_.clear();
  }
  const std::vector<Hit>& hits() const { return hits_; }
  /// The hits, to sort or move out (then reset() before the next query).
  std::vector<Hit>& hits() { return hits_; }

private:
  std::vector<Hit> hits_;
};

/// Keeps the best hit by `Better(a, b)` (a beats b). For rays it lowers
/// reach() to the best hit's t, so the walk skips everything beyond: see
/// ClosestRayHit and DeepestContact in hull_world.h.
template <typename Hit, typename Better>
class BestHitCollector final : public HitCollector<Hit> {
public:
  void add(const Hit& hit) override {
    if (found_ && !Better{}(hit, hit_)) return;
    hit_ = hit;
    found_ = true;
    const double r = Better::reach_after(hit);
    if (r < this->reach()) this->set_reach(r);
  }
  void reset() override {
    HitCollector<Hit>::reset();
    found_ = false;
  }
  bool found() const { return found_; }
  /// The best hit; meaningful when found().
  const Hit& hit() const { return hit_; }

private:
  Hit hit_{};
  bool found_ = false;
};

} // namespace hullcover::bvh
