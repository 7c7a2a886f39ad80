// The 32-bit id check (geometry/index_range) that the kd-trees, the union-find, the surface
// projector, the sides' list and the cell pieces share.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "geometry/index_range.hpp"

namespace cvtmesh {
namespace {

TEST(IndexRange, TakesEveryCountThatAnIndexReachesAndNamesWhatIsTooMany) {
  EXPECT_NO_THROW(require_index_range(0, "points"));
  // The largest count that passes: its ids are 0 .. 2^32 - 2, so none of them is kNoIndex.
  EXPECT_NO_THROW(require_index_range(kNoIndex, "points"));
  try {
    require_index_range(std::uint64_t{1} << 32, "points for a kd-tree");
    FAIL() << "2^32 points have no 32-bit ids";
  } catch (const std::length_error& e) {
    EXPECT_EQ(std::string(e.what()), "too many points for a kd-tree");
  }
}

}  // namespace
}  // namespace cvtmesh
