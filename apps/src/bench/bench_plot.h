#pragma once
// The bench's plot: speed against error. Four panels share the x axis, the
// settings of the sweep in order (exact first when swept): the yes/no,
// contacts and ray speed-ups of the hulls over the triangles, and the hull
// count as a percentage of the scene's exact covering (of its first setting
// when exact was not swept). One line per scene. Drawn with cairo.

#include "bench_run.h"

#include "hullcover/geometry/status.h"

#include <string>
#include <vector>

namespace hullcover::app::bench {

/// Writes the plot of `rows` to `path`: SVG when it ends in ".svg", else
/// PNG. Fails with `invalid_argument` when there is no row, and with
/// `unwritable_file` naming `path` when cairo cannot write it.
[[nodiscard]] Status write_bench_plot(const std::vector<BenchRow>& rows, const std::string& path);

} // namespace hullcover::app::bench
