// The `hullcover` command line tool.

#include "commands.h"
#include "help_numbers.h"

#include "hullcover/geometry/tolerances.h"

#include <cstdio>

int main(int argc, char** argv) {
  CLI::App app{
      "hullcover: turns a game scene's static triangles into a small set of convex hulls that collide\n"
      "exactly like the triangles, and checks them. Run 'hullcover COMMAND --help' for one command.\n"};
  app.name("hullcover");
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 a violation was found, 2 unreadable input or bad usage.\n"
      "Lengths are in the scene's own units; the tolerance defaults to " +
      hullcover::app::number_text(hullcover::kDefaultRelativeTolerance) +
      " of each place's diagonal (a map in a world keeps its own).");

  int exit_status = hullcover::app::kExitSuccess;
  hullcover::app::register_info_command(app, exit_status);
  hullcover::app::register_decompose_command(app, exit_status);
  hullcover::app::register_query_command(app, exit_status);
  hullcover::app::register_audit_command(app, exit_status);
  hullcover::app::register_bench_command(app, exit_status);
  hullcover::app::register_export_command(app, exit_status);
  hullcover::app::register_demo_command(app, exit_status);
  hullcover::app::register_render_command(app, exit_status);
  hullcover::app::register_world_command(app, exit_status);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int cli_status = app.exit(e); // prints help or the usage error
    return cli_status == 0 ? hullcover::app::kExitSuccess : hullcover::app::kExitBadInput;
  }
  return exit_status;
}
