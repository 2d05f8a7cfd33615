#pragma once
// What `hullcover bench` sweeps: the scenes (each with its scale) and the
// settings (agent radius x max deviation for the exact covering, agent
// radius x slop for the movement coverings), as the command line writes them
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

/// One point of the sweep: the exact covering with an agent radius and a
/// max deviation, either off; or a movement covering (`reach` walk or fly)
/// for agents of that radius, with a slop.
struct Setting {
  LengthSpec agent_radius, max_deviation;
  std::string reach; ///< "" (the exact covering), "walk" or "fly"
  LengthSpec slop;   ///< movement coverings: 0 = the decomposer's default (r / 15)

  /// "exact", "r=0.3m", "E=0.2%", "r=0.3m E=0.2%", "walk r=0.3m" or
  /// "fly r=0.3m slop=0.02m".
  std::string label() const;
  /// The same, fit for a file name ("exact", "r0.3m", "E0.2pct",
  /// "r0.3m_E0.2pct", "walk_r0.3m", "fly_r0.3m_slop0.02m").
  std::string file_label() const;
};

/// The modes `--agent-reach` names: the exact covering and the two
/// movement coverings.
inline constexpr const char* kExactReach = "exact";

/// For the exact covering (`reaches` holding "exact"): every agent radius
/// with every max deviation, agent radius outermost, in the order given;
/// then for each of "walk" and "fly" in `reaches`, in their order: every
/// agent radius above 0 with every slop (an empty list: the default slop
/// alone). Fails with `invalid_argument` for an unparsable value, a mode
/// that is none of the three, an empty list, or a movement mode with no
/// radius above 0 (a movement covering for agents of radius 0 is the exact
/// one).
[[nodiscard]] Result<std::vector<Setting>> sweep_settings(const std::vector<std::string>& agent_radii,
                                                          const std::vector<std::string>& max_deviations,
                                                          const std::vector<std::string>& reaches = {kExactReach},
                                                          const std::vector<std::string>& slops = {});

} // namespace hullcover::app::bench
