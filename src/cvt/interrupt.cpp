#include "cvt/interrupt.hpp"

#include "cvtmesh/errors.hpp"

namespace cvtmesh {

namespace {

constexpr unsigned kPolygonsPerCheck = 256;

}  // namespace

Interrupt::Interrupt(std::function<bool()> cancel, double time_limit, Clock::time_point start)
    : cancel_(std::move(cancel)), limited_(time_limit > 0) {
  if (limited_)
    deadline_ = start + std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(time_limit));
}

void Interrupt::check() const {
  if (cancel_ && cancel_()) throw Cancelled("cancelled");
}

bool Interrupt::out_of_time() const {
  check();
  if (limited_ && !timed_out() && Clock::now() >= deadline_)
    timed_out_.store(true, std::memory_order_relaxed);
  return timed_out();
}

void InterruptSink::begin(std::size_t chunks) {
  counts_.assign(chunks, {});
}

void InterruptSink::polygon(std::size_t chunk, const RvdPolygon&) {
  if (counts_[chunk].seen++ % kPolygonsPerCheck == 0) interrupt_.check();
}

}  // namespace cvtmesh
