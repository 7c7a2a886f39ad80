// The sides of a triangle soup's triangles, sorted so that the triangles of an edge are
// neighbours in the list: the connectivity a soup read from a file does not store.
#pragma once

#include <cstdint>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// One triangle side: the edge (lo, hi) with lo < hi, the triangle, whether the triangle walks it
// from lo to hi, and which side it is (from the triangle's corner `side` to the next).
// 16 bytes: the list of a large input's sides is written and read several times a remesh.
struct TriangleSide {
  Index lo, hi;
  Index triangle;
  bool forward;
  std::uint8_t side;
};

// Every triangle's three sides, sorted by (lo, hi, triangle, side). Throws std::length_error for
// a mesh of 2^32 triangles or more.
std::vector<TriangleSide> sorted_sides(const TriangleMesh& mesh);
// The same for triangles over `vertices` vertices.
std::vector<TriangleSide> sorted_sides(std::size_t vertices,
                                       const std::vector<Triangle>& triangles);

// Calls visit(i, j) for each edge's run of sides, sides[i] to sides[j - 1] (j - i triangles have
// it), in order.
template <class Visit>
void for_each_side_run(const std::vector<TriangleSide>& sides, Visit&& visit) {
  for (std::size_t i = 0, j = 0; i < sides.size(); i = j) {
    for (j = i + 1; j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi;
         ++j) {
    }
    visit(i, j);
  }
}

}  // namespace cvtmesh
