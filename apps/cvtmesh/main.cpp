// The `cvtmesh` command-line program: parses arguments, runs one subcommand, and turns every
// error into one line on stderr and a documented exit code.
#include <fmt/core.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "cvtmesh/allocator.hpp"
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

// The exit code of a library error: each kind has its own (exit_codes.hpp).
int exit_code_for(const cvtmesh::Error& e) {
  if (dynamic_cast<const cvtmesh::ResourceError*>(&e)) return kNoMemory;
  if (dynamic_cast<const cvtmesh::InputError*>(&e)) return kInputError;
  if (dynamic_cast<const cvtmesh::OutputError*>(&e)) return kOutputError;
  if (dynamic_cast<const cvtmesh::InvalidArgument*>(&e)) return kUsage;
  return kInternalError;
}

}  // namespace cvtmesh::cli

int main(int argc, char** argv) {
  using namespace cvtmesh::cli;
  cvtmesh::keep_freed_memory();  // 12-14% faster remeshes (cvtmesh/allocator.hpp)
  CLI::App app{"cvtmesh: isotropic surface remeshing by exact restricted Voronoi CVT"};
  app.set_version_flag("--version", std::string("cvtmesh ") + cvtmesh::version());
  app.require_subcommand(1);
  Action run;
  add_quality_command(app, run);
  add_repair_command(app, run);
  add_rvd_command(app, run);
  add_remesh_command(app, run);
  add_lfs_command(app, run);
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
  } catch (const cvtmesh::Error& e) {
    const int code = exit_code_for(e);
    fmt::print(stderr, "cvtmesh: {}: {}\n", code == kInternalError ? "internal error" : "error",
               e.what());
    return code;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "cvtmesh: error: out of memory\n");
    return kInternalError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "cvtmesh: internal error: {}\n", e.what());
    return kInternalError;
  }
}
