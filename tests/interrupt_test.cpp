// Stopping a remesh early (issue 22): the caller's cancel throws Cancelled from wherever the
// work is, promptly; the time limit returns a valid output of the seeds as they are; Ctrl-C
// stops the program with nothing written.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"

extern char** environ;

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// A cancel that says "stop" from its `after`-th poll on, counting the polls after that one.
struct CancelAfter {
  explicit CancelAfter(long after) : after(after) {}
  long after;
  std::atomic<long> polls{0};
  bool operator()() { return polls.fetch_add(1) + 1 >= after; }
  long polls_after_stop() const { return polls.load() - after; }
};

TEST(Interrupt, CancelThrowsFromEveryStageAndStopsPromptly) {
  const TriangleMesh input = torus(1, 0.4, 160, 64);
  RemeshSettings s;
  s.vertices = 3000;
  long total = 0;  // polls in a whole run
  {
    std::atomic<long> polls{0};
    s.cancel = [&] { return ++polls, false; };
    remesh(input, s);
    total = polls.load();
  }
  // An RVD pass polls every few hundred polygons: a whole run polls thousands of times.
  ASSERT_GT(total, 1000);
  // Stops at the first poll, in the middle (during the optimization) and at the last one
  // (during the extraction or the report); each time within a few polls of being asked, on
  // every thread.
  for (const long after : {1L, total / 2, total - 1}) {
    CancelAfter cancel(after);
    s.cancel = [&] { return cancel(); };
    EXPECT_THROW(remesh(input, s), Cancelled) << "after " << after << " of " << total;
    EXPECT_LE(cancel.polls_after_stop(), 2 * static_cast<long>(std::thread::hardware_concurrency()))
        << "after " << after;
  }
}

// Parts remeshed side by side (remesh/by_component): a cancel stops every part, each throws on
// its own, and the remesh throws Cancelled once all have stopped; none is left running with loops
// that an exception from another cut short (the sanitized build checks what they would read).
TEST(Interrupt, CancelStopsPartsRemeshedSideBySide) {
  TriangleMesh input = icosphere(3);
  for (int k = 1; k <= 3; ++k)
    input = concatenate(input, transformed(torus(1, 0.4, 64, 24), 1, {4.0 * k, 0, 0}));
  RemeshSettings s;
  s.vertices = 1200;
  long total = 0;
  {
    std::atomic<long> polls{0};
    s.cancel = [&] { return ++polls, false; };
    remesh(input, s);
    total = polls.load();
  }
  ASSERT_GT(total, 100);
  for (const long after : {1L, total / 4, total / 2, total - 1}) {
    CancelAfter cancel(after);
    s.cancel = [&] { return cancel(); };
    EXPECT_THROW(remesh(input, s), Cancelled) << "after " << after << " of " << total;
  }
}

TEST(Interrupt, TimeLimitGivesAValidOutputOfTheSeedsAsTheyAre) {
  const TriangleMesh input = torus(1, 0.4, 160, 64);
  RemeshSettings s;
  s.vertices = 1500;
  s.time_limit = 1e-9;  // passed before the first iteration
  const RemeshResult r = remesh(input, s);
  EXPECT_TRUE(r.time_limit_reached);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.polish_rounds, 0);
  const TopologyReport t = analyze_topology(r.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.consistently_oriented);
  // Topology control still runs out of time: validity comes first.
  EXPECT_TRUE(same_topology(t, analyze_topology(input)));

  s.time_limit = 0;
  const RemeshResult full = remesh(input, s);
  EXPECT_FALSE(full.time_limit_reached);
  EXPECT_GT(full.iterations, 0);
  s.time_limit = -1;
  EXPECT_THROW(remesh(input, s), InvalidArgument);
}

// The CLI, in a child process that gets SIGINT once it is optimizing.
TEST(Interrupt, CtrlCStopsTheCliWithNothingWritten) {
  TempDir dir;
  const auto in = dir / "torus.off", out = dir / "out.off", err = dir / "stderr.txt";
  write_mesh(in, torus(1, 0.4, 200, 80));
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
  const std::string cli = CVTMESH_CLI;
  std::vector<std::string> args = {cli,          "remesh", in.string(),    out.string(),
                                   "--vertices", "100000", "--iterations", "1000"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, cli.c_str(), &files, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&files);
  // Wait for the first progress line of the optimization (at most 60 s).
  const auto optimizing = [&] {
    std::ifstream f(err);
    const std::string text((std::istreambuf_iterator<char>(f)), {});
    return text.find("rcvt ") != std::string::npos;
  };
  for (int k = 0; k < 600 && !optimizing(); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(optimizing());
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = 0;
  // The run would take minutes; it stops within a second of the signal (10 s allowed here, on
  // a loaded machine).
  pid_t done = 0;
  for (int k = 0; k < 100 && (done = waitpid(pid, &status, WNOHANG)) == 0; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (done == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    FAIL() << "still running 10 s after SIGINT";
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream f(err);
  const std::string text((std::istreambuf_iterator<char>(f)), {});
  EXPECT_NE(text.find("interrupted; no output written"), std::string::npos) << text;
  // Nothing written: no output, no temporary file.
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    EXPECT_TRUE(entry.path() == in || entry.path() == err) << entry.path();
}

}  // namespace
}  // namespace cvtmesh
