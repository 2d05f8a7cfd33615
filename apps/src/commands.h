#pragma once
// Each `hullcover` subcommand registers its options on the CLI11 app and, when
// chosen, runs and stores the process exit status: 0 success, 1 a finding
// (e.g. an audit violation), 2 unreadable input or bad usage.

#include <CLI/CLI.hpp>

namespace hullcover::app {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFinding = 1; // e.g. an audit violation
inline constexpr int kExitBadInput = 2;

void register_info_command(CLI::App& app, int& exit_status);
void register_demo_command(CLI::App& app, int& exit_status);
void register_decompose_command(CLI::App& app, int& exit_status);
void register_query_command(CLI::App& app, int& exit_status);
void register_audit_command(CLI::App& app, int& exit_status);
void register_bench_command(CLI::App& app, int& exit_status);
void register_render_command(CLI::App& app, int& exit_status);
void register_export_command(CLI::App& app, int& exit_status);
void register_world_command(CLI::App& app, int& exit_status);

/// Sets up `app` as the `hullcover` tool: its description, footer and every
/// command above. The tests walk the options it makes.
void register_all_commands(CLI::App& app, int& exit_status);

} // namespace hullcover::app
