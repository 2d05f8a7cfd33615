#pragma once
// What `hullcover bench` sweeps: the scenes (each with its scale) and the
// settings (agent radius x max deviation), as the command line writes them
// and as they resolve to scene units for one scene.

#include "hullcover/geometry/status.h"

#include <optional>
#include <string>
#include <vector>

namespace hullcover::app::bench {

/// A length as written: "0.3m" (metres, times the scene's units per metre),
/// "0.2%" (percent of the scene's bounding-box diagonal) or "0.05" (scene
/// units). 0 in any form means "off".
struct LengthSpec {
  enum class Unit { scene, metres, diagonal_percent };
  double value = 0.0;
  Unit unit = Unit::scene;
  std::string text; ///< as written, for labels

  /// Scene units, given the scene's scale (units per metre) and diagonal.
  double resolve(double units_per_metre, double diagonal) const;
};

/// Parses one length. Fails with `invalid_argument` naming the text for
/// anything but a finite number >= 0 with an optional `m` or `%` suffix.
[[nodiscard]] Result<LengthSpec> parse_length(const std::string& text);

/// A scene to bench: "FILE" (an object) or "FILE@U" (a level at U scene
/// units per metre). An object has no metres of its own; 1 m stands for
/// kObjectDiagonalsPerMetre of its diagonal, so a setting in metres means
/// a size relative to the object, as a character is to a level.
struct SceneSpec {
  std::string path;
  std::optional<double> units_per_metre; ///< none: an object

  /// Scene units per metre, given the scene's diagonal.
  double metre(double diagonal) const;
};

/// An object's stand-in metre, as a fraction of its diagonal.
inline constexpr double kObjectDiagonalsPerMetre = 1.0 / 50.0;

/// Parses "FILE[@U]". Fails with `invalid_argument` for an empty file name
/// or a U that is not a finite number > 0.
[[nodiscard]] Result<SceneSpec> parse_scene(const std::string& text);

/// One point of the sweep: an agent radius and a max deviation, either off.
struct Setting {
  LengthSpec agent_radius, max_deviation;

  /// "exact", "r=0.3m", "E=0.2%" or "r=0.3m E=0.2%".
  std::string label() const;
  /// The same, fit for a file name ("exact", "r0.3m", "E0.2pct", "r0.3m_E0.2pct").
  std::string file_label() const;
};

/// Every agent radius with every max deviation, agent radius outermost, in
/// the order given. Fails with `invalid_argument` for an unparsable value
/// or an empty list.
[[nodiscard]] Result<std::vector<Setting>> sweep_settings(const std::vector<std::string>& agent_radii,
                                                          const std::vector<std::string>& max_deviations);

} // namespace hullcover::app::bench
