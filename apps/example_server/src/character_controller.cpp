#include "character_controller.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace example_server {
namespace {

using hullcover::Status;
using hullcover::StatusCode;
namespace bvh = hullcover::bvh;

/// A surface whose normal is within about 50 degrees of `up` can be stood
/// on: hitting it ends a fall. Steeper ones are walls the character slides
/// down.
constexpr double kWalkableSlopeCosine = 0.64;
/// How many times one step may stop at a hull and slide on: two walls and
/// a floor meeting in a corner take three; more would only grind.
constexpr int kMaxSlideIterations = 4;
/// A leftover motion shorter than this fraction of the skin is not worth a
/// sweep: it could not move the capsule visibly.
constexpr double kNegligibleMotionPerSkin = 1e-3;
/// The sweep reports a hit when the capsule comes this fraction of the skin
/// from a hull: well inside the skin, so backing off by the skin always
/// leaves a gap, and loose enough that conservative advancement converges
/// in few steps.
constexpr double kSweepTouchPerSkin = 0.25;
/// Standard deviation of the random walk's turn per step, radians: about
/// a right angle's worth of wandering over a second at 60 steps.
constexpr double kTurnPerStepRadians = 0.2;
/// find_start_positions gives up after this many tries per character.
constexpr int kStartTriesPerCharacter = 500;
/// Most contacts asked for in the penetration check: the deepest decides.
constexpr int kPenetrationContacts = 4;

} // namespace

void QueryCounts::add(const QueryCounts& other) {
  sweeps += other.sweeps;
  contacts += other.contacts;
  overlaps += other.overlaps;
  sweep_hits += other.sweep_hits;
  recoveries += other.recoveries;
  respawns += other.respawns;
  steps += other.steps;
}

CharacterController::CharacterController(const bvh::HullWorld& world, const ControllerSettings& settings)
    : world_(world), settings_(settings), upright_(Eigen::Isometry3d::Identity()) {
  settings_.up.normalize();
  upright_.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), settings_.up).toRotationMatrix();
  // Any two unit vectors perpendicular to up and each other span the ground.
  ground_x_ = settings_.up.unitOrthogonal();
  ground_y_ = settings_.up.cross(ground_x_);
}

Eigen::Isometry3d CharacterController::pose_at(const Eigen::Vector3d& position) const {
  Eigen::Isometry3d pose = upright_;
  pose.translation() = position;
  return pose;
}

Status CharacterController::move_and_slide(Character& character, Eigen::Vector3d motion, bool& grounded,
                                           QueryCounts& counts) const {
  const double negligible = kNegligibleMotionPerSkin * settings_.skin;
  bvh::SweepRequest request;
  request.shape = bvh::QueryShape::capsule(settings_.radius, settings_.half_height);
  bvh::SweepResult result;
  for (int slide = 0; slide < kMaxSlideIterations; ++slide) {
    const double length = motion.norm();
    if (length < negligible) break;
    request.start = pose_at(character.position);
    request.end = pose_at(character.position + motion);
    ++counts.sweeps;
    if (Status s = world_.sweep(request, result, kSweepTouchPerSkin * settings_.skin); !s.ok()) return s;
    if (!result.hit) {
      character.position += motion;
      break;
    }
    ++counts.sweep_hits;
    // Every pose before the hit is clear (conservative advancement), so
    // backing off along the path keeps the capsule out of every hull.
    const double safe_fraction = std::max(0.0, result.fraction - settings_.skin / length);
    character.position += safe_fraction * motion;
    motion *= 1.0 - safe_fraction;
    const Eigen::Vector3d& normal = result.normal;
    if (normal.dot(settings_.up) >= kWalkableSlopeCosine) grounded = true;
    // Slide: keep only the part of the motion along the surface met.
    const double into_surface = motion.dot(normal);
    if (into_surface < 0.0) motion -= into_surface * normal;
  }
  return Status::success();
}

Status CharacterController::step(Character& character, QueryCounts& counts) const {
  ++counts.steps;
  std::normal_distribution<double> turn(0.0, kTurnPerStepRadians);
  character.heading += turn(character.random);
  const double dt = settings_.time_step;
  character.fall_speed = std::min(character.fall_speed + settings_.gravity * dt, settings_.terminal_fall_speed);
  const Eigen::Vector3d walk =
      settings_.walk_speed * dt * (std::cos(character.heading) * ground_x_ + std::sin(character.heading) * ground_y_);
  const Eigen::Vector3d fall = -character.fall_speed * dt * settings_.up;

  const Eigen::Vector3d before = character.position;
  bool grounded = false;
  if (Status s = move_and_slide(character, walk + fall, grounded, counts); !s.ok()) return s;
  if (grounded) character.fall_speed = 0.0;

  // A real server checks for penetration every step: whatever moved the
  // character (a teleport, a moving platform) might have left it inside.
  bvh::ContactRequest contact_request;
  contact_request.shape = bvh::QueryShape::capsule(settings_.radius, settings_.half_height);
  contact_request.pose = pose_at(character.position);
  contact_request.max_contacts = kPenetrationContacts;
  bvh::ContactResult contact_result;
  ++counts.contacts;
  if (Status s = world_.contacts(contact_request, contact_result); !s.ok()) return s;
  if (!contact_result.contacts.empty()) {
    const bvh::Contact& deepest = contact_result.contacts.front();
    character.position += (deepest.depth + settings_.skin) * deepest.normal;
    ++counts.recoveries;
  }
  character.path_length += (character.position - before).norm();

  if (character.position.dot(settings_.up) < settings_.respawn_below) {
    character.position = character.start;
    character.fall_speed = 0.0;
    ++counts.respawns;
  }
  return Status::success();
}

Status CharacterController::hulls_inside(const Character& character, std::vector<int>& hulls,
                                         QueryCounts& counts) const {
  bvh::OverlapRequest request;
  request.shape = bvh::QueryShape::capsule(settings_.radius - settings_.skin, settings_.half_height);
  request.pose = pose_at(character.position);
  bvh::OverlapResult result;
  ++counts.overlaps;
  if (Status s = world_.overlap(request, result); !s.ok()) return s;
  hulls = std::move(result.hulls);
  return Status::success();
}

Status CharacterController::is_free(const Eigen::Vector3d& position, bool& free) const {
  bvh::OverlapRequest request;
  request.shape = bvh::QueryShape::capsule(settings_.radius + settings_.skin, settings_.half_height);
  request.pose = pose_at(position);
  bvh::TouchResult result;
  if (Status s = world_.touches(request, result); !s.ok()) return s;
  free = !result.touching;
  return Status::success();
}

hullcover::Aabb world_bounds(const bvh::HullWorld& world) {
  hullcover::Aabb box;
  for (const bvh::RuntimeHull& hull : world.hulls()) {
    box.extend(hull.box.min);
    box.extend(hull.box.max);
  }
  return box;
}

Status find_start_positions(const bvh::HullWorld& world, const CharacterController& controller, int count,
                            std::uint64_t seed, std::vector<Eigen::Vector3d>& positions) {
  const ControllerSettings& settings = controller.settings();
  const hullcover::Aabb box = world_bounds(world);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Standing on the surface hit: the capsule's lowest point two skins above it.
  const double lift = settings.half_height + settings.radius + 2.0 * settings.skin;
  const std::int64_t tries = static_cast<std::int64_t>(count) * kStartTriesPerCharacter;
  positions.clear();
  for (std::int64_t attempt = 0; attempt < tries && static_cast<int>(positions.size()) < count; ++attempt) {
    Eigen::Vector3d origin;
    for (int axis = 0; axis < 3; ++axis) origin[axis] = box.min[axis] + unit(random) * (box.max[axis] - box.min[axis]);
    bvh::RayRequest ray;
    ray.origin = origin;
    ray.direction = -settings.up;
    ray.max_distance = box.diagonal();
    bvh::RayResult hit;
    if (Status s = world.ray_cast(ray, hit); !s.ok()) return s;
    // t = 0: the point was inside a hull. A steep hit: no place to stand.
    if (!hit.hit || hit.first.t <= 0.0 || hit.first.normal.dot(settings.up) < kWalkableSlopeCosine) continue;
    const Eigen::Vector3d centre = hit.first.point + lift * settings.up;
    bool free = false;
    if (Status s = controller.is_free(centre, free); !s.ok()) return s;
    if (free) positions.push_back(centre);
  }
  if (static_cast<int>(positions.size()) < count)
    return {StatusCode::invalid_argument,
            "found only " + std::to_string(positions.size()) + " free start positions of " + std::to_string(count) +
                " in " + std::to_string(tries) + " tries: is the capsule larger than the level's rooms?"};
  return Status::success();
}

} // namespace example_server
