// The median of a list of numbers, for thresholds taken from a typical value.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace cvtmesh {

// The upper median of `x` (its element at size/2 once sorted); `x` must not be empty.
inline double median_of(std::vector<double> x) {
  const auto middle = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), middle, x.end());
  return *middle;
}

}  // namespace cvtmesh
