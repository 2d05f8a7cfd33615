#pragma once
/// \file audit_agent.h
/// The agent the movement audit judges for, its options resolved
/// (movement_audit.cpp resolves them; agent_lattice.h and walker_rest.h
/// read them).

#include <Eigen/Core>

namespace hullcover::validate::detail {

/// The agent with every default resolved.
struct AuditAgent {
  double radius = 0.0, slop = 0.0, height = 0.0, climb = 0.0;
  double min_up_cosine = 0.0;
  int up_axis = 1;
  double up_sign = 1.0;
  bool walking = true;
  double rise() const { return climb + height - radius; } ///< how high above a walkable point its axis may be
  double height_of(const Eigen::Vector3d& p) const { return up_sign * p[up_axis]; }
};

} // namespace hullcover::validate::detail
