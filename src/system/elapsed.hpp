// Wall-clock time since a start, for timings in reports and for time limits.
#pragma once

#include <chrono>

namespace cvtmesh {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cvtmesh
