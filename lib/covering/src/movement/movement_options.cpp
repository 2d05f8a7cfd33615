#include "hullcover/covering/movement_options.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace hullcover {

Result<AgentShape> resolve_agent_shape(const MovementOptions& o, double tol) {
  AgentShape agent;
  agent.reach = o.reach;
  agent.radius = o.radius;
  if (!(std::isfinite(o.radius) && o.radius > 0.0))
    return Status{StatusCode::invalid_argument, "agent radius must be a positive length"};
  agent.slop = o.slop < 0.0 ? kDefaultSlopPerRadius * o.radius : o.slop;
  if (!(std::isfinite(agent.slop) && agent.slop >= 2.0 * tol && agent.slop < o.radius)) {
    char twice[32];
    std::snprintf(twice, sizeof twice, "%.6g", 2.0 * tol);
    return Status{StatusCode::invalid_argument, std::string("agent slop must be at least twice the tolerance (") +
                                                    twice + ") and less than the agent radius"};
  }
  agent.height = o.height < 0.0 ? kDefaultHeightInRadii * o.radius : o.height;
  if (!(std::isfinite(agent.height) && agent.height >= 2.0 * o.radius))
    return Status{StatusCode::invalid_argument, "agent height must be at least twice the agent radius"};
  agent.climb = o.climb < 0.0 ? kDefaultClimbInRadii * o.radius : o.climb;
  if (!std::isfinite(agent.climb)) return Status{StatusCode::invalid_argument, "agent climb must be a length >= 0"};
  if (!(std::isfinite(o.max_slope_degrees) && o.max_slope_degrees >= 0.0 && o.max_slope_degrees < 90.0))
    return Status{StatusCode::invalid_argument, "max slope must be at least 0 and less than 90 degrees"};
  agent.min_up_cosine = std::cos(o.max_slope_degrees * M_PI / 180.0);
  int axis = -1;
  for (int a = 0; a < 3; ++a)
    if (std::abs(o.up[a]) == 1.0) axis = a;
  if (axis < 0 || o.up.cwiseAbs().sum() != 1.0)
    return Status{StatusCode::invalid_argument, "up must be an axis direction (+x, -x, +y, -y, +z or -z)"};
  agent.up_axis = axis;
  agent.up_sign = o.up[axis];
  return agent;
}

} // namespace hullcover
