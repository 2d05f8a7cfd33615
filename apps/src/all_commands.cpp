#include "commands.h"
#include "help_numbers.h"

#include "hullcover/geometry/tolerances.h"

namespace hullcover::app {

void register_all_commands(CLI::App& app, int& exit_status) {
  app.description(
      "hullcover: turns a game scene's static triangles into a small set of convex hulls that collide\n"
      "exactly like the triangles, and checks them. Run 'hullcover COMMAND --help' for one command.\n");
  app.name("hullcover");
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 a violation was found, 2 unreadable input or bad usage.\n"
      "Lengths are in the scene's own units; the tolerance defaults to " +
      number_text(kDefaultRelativeTolerance) + " of each place's diagonal (a map in a world keeps its own).");
  register_info_command(app, exit_status);
  register_decompose_command(app, exit_status);
  register_query_command(app, exit_status);
  register_audit_command(app, exit_status);
  register_bench_command(app, exit_status);
  register_export_command(app, exit_status);
  register_demo_command(app, exit_status);
  register_render_command(app, exit_status);
  register_world_command(app, exit_status);
}

} // namespace hullcover::app
