// Stopping a remesh early (issue 22). The caller's cancel stops it at once: check() throws
// Cancelled, from any thread, and the work is abandoned. The time limit stops it where the work
// done so far still makes a valid output: the optimization at the end of an iteration, the
// polishing and the topology control between rounds; the final extraction still runs.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>

#include "cvtmesh/rvd.hpp"

namespace cvtmesh {

class Interrupt {
 public:
  using Clock = std::chrono::steady_clock;

  Interrupt() = default;  // never stops
  // `cancel` may be empty; `time_limit` in seconds from `start`, 0 for none.
  Interrupt(std::function<bool()> cancel, double time_limit, Clock::time_point start);

  // Throws Cancelled when the caller's cancel returns true. Thread-safe.
  void check() const;
  // check(), then whether the time limit has passed; once it has, stays true.
  bool out_of_time() const;
  bool timed_out() const { return timed_out_.load(std::memory_order_relaxed); }

 private:
  std::function<bool()> cancel_;
  bool limited_ = false;
  Clock::time_point deadline_;
  mutable std::atomic<bool> timed_out_{false};
};

// Checks the cancel every few hundred polygons of a traversal, so that even one RVD pass over
// a big input stops within milliseconds of it (a chunk of 1,024 triangles takes about 1.5 ms).
class InterruptSink : public PolygonSink {
 public:
  explicit InterruptSink(const Interrupt& interrupt) : interrupt_(interrupt) {}
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon&) override;
  // It holds nothing of a chunk: a chunk kept needs no check (a sink kept from one traversal to
  // the next, as ExtractionMemory's, is handed only the polygons that changed).
  bool keeps_chunks() const override { return true; }

 private:
  const Interrupt& interrupt_;
  // Polygons seen per chunk (a chunk runs on one thread), a cache line each: every polygon
  // writes its chunk's count, and counts packed side by side kept one line going back and
  // forth between the cores (3% of fandisk.off's remesh to 5k on two threads, 0.04% on one).
  struct alignas(64) Count {
    unsigned seen = 0;
  };
  std::vector<Count> counts_;
};

}  // namespace cvtmesh
