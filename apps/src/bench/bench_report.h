#pragma once
// The bench's rows as files people read: a CSV (every figure), a Markdown
// table (the ones that matter side by side) and a plot of speed against
// error (bench_plot.h).

#include "bench_run.h"

#include "hullcover/geometry/status.h"

#include <optional>
#include <string>
#include <vector>

namespace hullcover::app::bench {

/// The row of the same scene with no allowance (in `rows`), or null when
/// the sweep ran none.
const BenchRow* exact_row_of(const std::vector<BenchRow>& rows, const std::string& scene);

/// Hulls as a change against the scene's exact row, in percent (-40 = 40%
/// fewer); nothing without an exact row.
std::optional<double> hull_change_percent(const std::vector<BenchRow>& rows, const BenchRow& row);

/// Every figure of every row, one line each, with a header line. Fails with
/// `unwritable_file` naming `path`.
[[nodiscard]] Status write_bench_csv(const std::vector<BenchRow>& rows, const std::string& path);

/// A Markdown table of the main figures, and a line on how they were made.
std::string bench_markdown(const std::vector<BenchRow>& rows);

/// Writes bench_markdown(rows) to `path`. Fails with `unwritable_file`.
[[nodiscard]] Status write_bench_markdown(const std::vector<BenchRow>& rows, const std::string& path);

} // namespace hullcover::app::bench
