#include "hullcover/covering/covering_export.h"

#include "hullcover/geometry/atomic_file.h"
#include "hullcover/geometry/parallel_for.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace hullcover {

namespace {

// Appends printf-formatted text to `text`.
template <class... Values>
void append(std::string& text, const char* format, Values... values) {
  char line[128];
  const int n = std::snprintf(line, sizeof line, format, values...);
  if (n <= 0) return;
  if (n < static_cast<int>(sizeof line)) {
    text.append(line, static_cast<size_t>(n));
    return;
  }
  std::string longer(static_cast<size_t>(n) + 1, '\0');
  std::snprintf(longer.data(), longer.size(), format, values...);
  text.append(longer.data(), static_cast<size_t>(n));
}

// The OBJ text of hulls [first, last), whose first vertex is number `base`.
std::string covering_obj_text(const Covering& covering, size_t first, size_t last, long base) {
  std::string text;
  for (size_t h = first; h < last; ++h) {
    const CoveringHull& hull = covering.hulls[h];
    append(text, "o hull_%zu\n", h);
    for (const Eigen::Vector3d& p : hull.polytope.vertices) append(text, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    const bool flat = hull.planar && hull.thickness == 0.0;
    const size_t facet_count = flat ? 1 : hull.polytope.facets.size();
    for (size_t f = 0; f < facet_count; ++f) {
      text.push_back('f');
      for (int v : hull.polytope.facets[f]) append(text, " %ld", base + v);
      text.push_back('\n');
    }
    base += static_cast<long>(hull.polytope.vertices.size());
  }
  return text;
}

// Hulls a thread formats at a time: text of a few MB per thread, so the
// memory held stays bounded whatever the covering's size.
constexpr size_t kHullsPerTextBlock = 4096;

// The OBJ text; the stream's error flag tells whether it was all written.
// Formatting (the %.17g of every coordinate) is most of the cost: blocks
// of hulls are formatted on the covering's threads, each from its first
// vertex number (the vertex counts before it), and written in order, so
// the file is the same for any thread count.
void print_covering_obj(const Covering& covering, std::FILE* out) {
  std::fprintf(out, "# hullcover covering: %zu hulls of %d faces, tolerance %.17g\n", covering.hulls.size(),
               covering.statistics.faces, covering.tolerance.length);
  const size_t hull_count = covering.hulls.size();
  const size_t block_count = (hull_count + kHullsPerTextBlock - 1) / kHullsPerTextBlock;
  std::vector<long> block_base(block_count + 1, 1);
  for (size_t b = 0; b < block_count; ++b) {
    long vertices = 0;
    for (size_t h = b * kHullsPerTextBlock; h < std::min(hull_count, (b + 1) * kHullsPerTextBlock); ++h)
      vertices += static_cast<long>(covering.hulls[h].polytope.vertices.size());
    block_base[b + 1] = block_base[b] + vertices;
  }
  const int threads = threads_to_use(covering.options.threads);
  std::vector<std::string> texts(static_cast<size_t>(threads));
  for (size_t round = 0; round < block_count; round += static_cast<size_t>(threads)) {
    const int blocks = static_cast<int>(std::min(static_cast<size_t>(threads), block_count - round));
    parallel_for(blocks, threads, [&](int i) {
      const size_t b = round + static_cast<size_t>(i);
      texts[i] = covering_obj_text(covering, b * kHullsPerTextBlock, std::min(hull_count, (b + 1) * kHullsPerTextBlock),
                                   block_base[b]);
    });
    for (int i = 0; i < blocks; ++i) std::fwrite(texts[i].data(), 1, texts[i].size(), out);
  }
}

} // namespace

Status write_covering_obj(const Covering& covering, const std::string& path) {
  return write_file_atomically(path, [&covering](std::FILE* out) {
    print_covering_obj(covering, out);
    return true;
  });
}

nlohmann::json covering_json(const Covering& covering) {
  const CoveringStatistics& s = covering.statistics;
  nlohmann::json hulls = nlohmann::json::array();
  long vertices = 0, facets = 0;
  int planar = 0;
  for (const CoveringHull& hull : covering.hulls) {
    vertices += static_cast<long>(hull.polytope.vertices.size());
    facets += static_cast<long>(hull.polytope.facets.size());
    planar += hull.planar;
    hulls.push_back({{"faces", hull.faces},
                     {"vertices", hull.polytope.vertices.size()},
                     {"facets", hull.polytope.facets.size()},
                     {"volume", hull.volume},
                     {"planar", hull.planar},
                     {"prism_thickness", hull.thickness},
                     {"material", hull.material}});
  }
  nlohmann::json rejections;
  for (int v = 1; v < kValidityCount; ++v) rejections[validity_name(static_cast<Validity>(v))] = s.rejections[v];
  const DecomposeOptions& o = covering.options;
  return {
      {"hulls", hulls},
      {"totals",
       {{"faces", s.faces},
        {"hulls", covering.hulls.size()},
        {"hulls_per_face", s.faces > 0 ? static_cast<double>(covering.hulls.size()) / s.faces : 0.0},
        {"planar_hulls", planar},
        {"flat_hulls", s.prisms_made_flat},
        {"vertices", vertices},
        {"facets", facets},
        {"zero_area_faces_skipped", s.zero_area_faces_skipped},
        {"faces_given_flat_hulls", s.faces_given_flat_hulls},
        {"thin_faces_given_flat_hulls", s.thin_faces_given_flat_hulls},
        {"faces_left_uncovered", s.faces_left_uncovered}}},
      {"options",
       {{"tolerance", covering.tolerance.length},
        {"tolerance_user_given", covering.tolerance.user_given},
        {"bar_half_length", covering.bar_half_length},
        {"prism_thickness_cap", covering.prism_thickness_cap},
        {"near_merge_distance", covering.near_merge_distance},
        {"agent_radius", covering.options.agent_radius.value_or(0.0)},
        {"max_deviation", covering.options.max_deviation.value_or(0.0)},
        {"dissolve", covering.dissolve},
        {"order", o.order == MergeOrder::compact ? "compact" : "random"},
        {"conditions", o.conditions == ValidityMode::exact ? "exact" : "paper"},
        {"seed", o.seed},
        {"order_tries", o.order_tries},
        {"keep_materials_apart", o.keep_materials_apart},
        {"max_hull_vertices", o.max_hull_vertices},
        {"max_hull_triangles", o.max_hull_triangles ? nlohmann::json(*o.max_hull_triangles) : nlohmann::json()},
        {"local_extent", covering.tolerance.local_extent},
        {"tolerance_per_island", covering.tolerance.island_lengths},
        {"cell_size", o.cell_size ? nlohmann::json(*o.cell_size) : nlohmann::json("automatic")},
        {"cell_size_per_island", covering.cell_sizes}}},
      {"merging",
       {{"merges", s.merges},
        {"near_merges", s.near_merges},
        {"dissolved_patches", s.dissolved_patches},
        {"kept_try", s.kept_try},
        {"islands", s.islands},
        {"cells", s.cells},
        {"seam_merges", s.seam_merges},
        {"candidates_tested", s.candidates_tested},
        {"qhull_calls", s.qhull_calls},
        {"incremental_hulls", s.incremental_hulls},
        {"solids_kept_as_grown", s.solids_kept_as_grown},
        {"rejections", rejections}}},
      {"seconds",
       {{"index", s.seconds_index},
        {"merging", s.seconds_merging},
        {"seams", s.seconds_seams},
        {"output", s.seconds_output},
        {"total", s.seconds_index + s.seconds_merging + s.seconds_output}}},
  };
}

Status write_covering_json(const Covering& covering, const nlohmann::json& extra, const std::string& path) {
  nlohmann::json j = covering_json(covering);
  for (const auto& [key, value] : extra.items()) j[key] = value;
  // A path in the JSON need not be UTF-8: such bytes are replaced, not thrown on.
  return write_file_atomically(path, j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

} // namespace hullcover
