// The one check that a count of items fits the 32-bit ids (Index) that the arrays of the
// project's hot paths store, to halve their memory against 64-bit ones.
#pragma once

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// Throws std::length_error ("too many `what`") where `count` items cannot all have an Index.
inline void require_index_range(std::size_t count, const char* what) {
  if (count > std::numeric_limits<Index>::max())
    throw std::length_error(std::string("too many ") + what);
}

}  // namespace cvtmesh
