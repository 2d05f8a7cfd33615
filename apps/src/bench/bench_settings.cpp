#include "bench_settings.h"

#include "number_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace hullcover::app::bench {
namespace {

Status bad(const std::string& what, const std::string& text) {
  return {StatusCode::invalid_argument, what + " '" + text + "'"};
}

// The whole of `text` as a finite number of magnitude at most
// kLargestOptionValue (the bound of every number option), or nothing.
std::optional<double> whole_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(x) || std::abs(x) > kLargestOptionValue) return std::nullopt;
  return x;
}

// "0.2%" -> "0.2pct": '%' is awkward in file names and shells.
std::string for_file(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '%' ? std::string("pct") : std::string(1, c);
  return out;
}

} // namespace

double LengthSpec::resolve(double units_per_metre, double diagonal) const {
  switch (unit) {
    case Unit::metres: return value * units_per_metre;
    case Unit::diagonal_percent: return value / 100.0 * diagonal;
    case Unit::scene: break;
  }
  return value;
}

Result<LengthSpec> parse_length(const std::string& text) {
  LengthSpec spec;
  spec.text = text;
  std::string number = text;
  if (!number.empty() && number.back() == 'm') {
    spec.unit = LengthSpec::Unit::metres;
    number.pop_back();
  } else if (!number.empty() && number.back() == '%') {
    spec.unit = LengthSpec::Unit::diagonal_percent;
    number.pop_back();
  }
  const std::optional<double> x = whole_number(number);
  if (!x || *x < 0.0)
    return bad("a length is a number from 0 to 1e15 in scene units, or with 'm' (metres) or '%' (of the diagonal), not",
               text);
  spec.value = *x;
  return spec;
}

double SceneSpec::metre(double diagonal) const {
  return units_per_metre ? *units_per_metre : kObjectDiagonalsPerMetre * diagonal;
}

Result<SceneSpec> parse_scene(const std::string& text) {
  SceneSpec spec;
  const size_t at = text.rfind('@');
  spec.path = text.substr(0, at);
  if (spec.path.empty()) return bad("a scene is FILE or FILE@UNITS_PER_METRE, not", text);
  if (at != std::string::npos) {
    const std::optional<double> u = whole_number(text.substr(at + 1));
    if (!u || !(*u > 0.0)) return bad("units per metre after '@' must be a number > 0 in", text);
    spec.units_per_metre = *u;
  }
  return spec;
}

std::string Setting::label() const {
  if (!reach.empty())
    return reach + " r=" + agent_radius.text + (slop.value > 0.0 ? " slop=" + slop.text : std::string());
  std::string out;
  if (agent_radius.value > 0.0) out = "r=" + agent_radius.text;
  if (max_deviation.value > 0.0) out += (out.empty() ? "" : " ") + std::string("E=") + max_deviation.text;
  return out.empty() ? "exact" : out;
}

std::string Setting::file_label() const {
  if (!reach.empty())
    return reach + "_r" + for_file(agent_radius.text) +
           (slop.value > 0.0 ? "_slop" + for_file(slop.text) : std::string());
  std::string out;
  if (agent_radius.value > 0.0) out = "r" + for_file(agent_radius.text);
  if (max_deviation.value > 0.0) out += (out.empty() ? "" : "_") + std::string("E") + for_file(max_deviation.text);
  return out.empty() ? "exact" : out;
}

Result<std::vector<Setting>> sweep_settings(const std::vector<std::string>& agent_radii,
                                            const std::vector<std::string>& max_deviations,
                                            const std::vector<std::string>& reaches,
                                            const std::vector<std::string>& slops) {
  if (agent_radii.empty() || max_deviations.empty() || reaches.empty())
    return Status(StatusCode::invalid_argument,
                  "the sweep needs at least one agent radius, one max deviation (0 = off) and one agent reach");
  const auto lengths = [](const std::vector<std::string>& texts) -> Result<std::vector<LengthSpec>> {
    std::vector<LengthSpec> out;
    for (const std::string& text : texts) {
      Result<LengthSpec> x = parse_length(text);
      if (!x.ok()) return x.status();
      out.push_back(x.value());
    }
    return out;
  };
  const Result<std::vector<LengthSpec>> radii = lengths(agent_radii);
  if (!radii.ok()) return radii.status();
  const Result<std::vector<LengthSpec>> deviations = lengths(max_deviations);
  if (!deviations.ok()) return deviations.status();
  Result<std::vector<LengthSpec>> slop_lengths = lengths(slops);
  if (!slop_lengths.ok()) return slop_lengths.status();
  std::vector<LengthSpec> slop_list = slop_lengths.value();
  for (const LengthSpec& e : slop_list)
    if (!(e.value > 0.0)) return bad("a slop must be above 0, not", e.text);
  if (slop_list.empty()) slop_list.push_back(LengthSpec{});
  const bool moving =
      std::any_of(reaches.begin(), reaches.end(), [](const std::string& m) { return m != kExactReach; });
  if (!slops.empty() && !moving)
    return bad("--agent-slop needs --agent-reach walk or fly in the sweep, not", reaches[0]);
  std::vector<Setting> settings;
  for (const std::string& reach : reaches) {
    if (reach == kExactReach) {
      for (const LengthSpec& r : radii.value())
        for (const LengthSpec& e : deviations.value()) settings.push_back({r, e, "", LengthSpec{}});
      continue;
    }
    if (reach != "walk" && reach != "fly") return bad("an agent reach is exact, walk or fly, not", reach);
    const size_t before = settings.size();
    for (const LengthSpec& r : radii.value())
      for (const LengthSpec& e : slop_list)
        if (r.value > 0.0) settings.push_back({r, LengthSpec{}, reach, e});
    if (settings.size() == before)
      return bad("a movement covering needs an agent radius above 0 in the sweep, for", reach);
  }
  // Each setting writes its own runtime file: a value given twice would
  // overwrite one row's file with another's.
  for (size_t i = 0; i < settings.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (settings[i].file_label() == settings[j].file_label())
        return bad("the sweep holds a setting twice", settings[i].label());
  return settings;
}

} // namespace hullcover::app::bench
