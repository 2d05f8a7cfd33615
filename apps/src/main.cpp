// The `hullcover` command line tool.

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app;
  int exit_status = hullcover::app::kExitSuccess;
  hullcover::app::register_all_commands(app, exit_status);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int cli_status = app.exit(e); // prints help or the usage error
    return cli_status == 0 ? hullcover::app::kExitSuccess : hullcover::app::kExitBadInput;
  }
  return exit_status;
}
