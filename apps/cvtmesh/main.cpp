// The `cvtmesh` command-line program: parses arguments, runs one subcommand, and turns every
// error into one line on stderr and a documented exit code.
#include <fmt/core.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/version.hpp"
#include "exit_codes.hpp"

namespace cvtmesh::cli {

CLI::Option* add_threads_option(CLI::App& command, int& threads) {
  return command.add_option("--threads", threads, "Worker threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber)
      ->default_val(0);
}

std::shared_ptr<tbb::global_control> limit_threads(int threads) {
  if (threads <= 0) return nullptr;
  return std::make_shared<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<std::size_t>(threads));
}

}  // namespace cvtmesh::cli

int main(int argc, char** argv) {
  using namespace cvtmesh::cli;
  CLI::App app{"cvtmesh: isotropic surface remeshing by exact restricted Voronoi CVT"};
  app.set_version_flag("--version", std::string("cvtmesh ") + cvtmesh::version());
  app.require_subcommand(1);
  Action run;
  add_quality_command(app, run);
  add_repair_command(app, run);
  add_rvd_command(app, run);
  add_remesh_command(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kUsage;
  }
  try {
    return run();
  } catch (const cvtmesh::Cancelled&) {
    fmt::print(stderr, "cvtmesh: interrupted; no output written\n");
    return kInterrupted;
  } catch (const cvtmesh::ResourceError& e) {
    fmt::print(stderr, "cvtmesh: error: {}\n", e.what());
    return kNoMemory;
  } catch (const cvtmesh::InputError& e) {
    fmt::print(stderr, "cvtmesh: error: {}\n", e.what());
    return kInputError;
  } catch (const cvtmesh::OutputError& e) {
    fmt::print(stderr, "cvtmesh: error: {}\n", e.what());
    return kOutputError;
  } catch (const cvtmesh::InvalidArgument& e) {
    fmt::print(stderr, "cvtmesh: error: {}\n", e.what());
    return kUsage;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "cvtmesh: error: out of memory\n");
    return kInternalError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "cvtmesh: internal error: {}\n", e.what());
    return kInternalError;
  }
}
