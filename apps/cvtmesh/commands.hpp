// The subcommands of the `cvtmesh` program. Each adds itself to the parser and, when chosen,
// sets `run` to the action to perform once all arguments are parsed.
#pragma once

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include <functional>
#include <memory>

namespace cvtmesh::cli {

using Action = std::function<int()>;

void add_quality_command(CLI::App& app, Action& run);
void add_repair_command(CLI::App& app, Action& run);
void add_rvd_command(CLI::App& app, Action& run);
void add_remesh_command(CLI::App& app, Action& run);
void add_lfs_command(CLI::App& app, Action& run);

// --threads T on a subcommand; 0 means all cores. Returns the option for chaining.
CLI::Option* add_threads_option(CLI::App& command, int& threads);
// Caps oneTBB's worker count while the returned object lives (threads = 0: no cap).
std::shared_ptr<tbb::global_control> limit_threads(int threads);

}  // namespace cvtmesh::cli
