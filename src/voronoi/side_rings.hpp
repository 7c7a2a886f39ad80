// The input's connectivity along its edges, as the cell pieces need it: per side of each input
// triangle, the next side around the same edge. It depends on the surface alone, so a remesh
// finds it once for all its extractions and topology rounds (igea.ply at 10k: 30 ms of each
// extraction's serial work, two extractions).
#pragma once

#include <cstdint>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

class SideRings {
 public:
  // Throws std::length_error for 2^32 / 3 triangles or more: side ids are 32 bits.
  explicit SideRings(const TriangleMesh& surface);
  // Side 3 t + e (edge e of triangle t joins its corners e and (e + 1) % 3): the next side around
  // its edge. The sides of an edge make a ring: two for an inner edge, one at a boundary, more
  // where the input branches.
  std::uint32_t next(std::uint32_t side) const { return next_[side]; }

 private:
  std::vector<std::uint32_t> next_;
};

}  // namespace cvtmesh
