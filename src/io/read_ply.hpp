// cvtmesh's own PLY reader. CGAL 5.5's PLY reader trusts the header (a property before any
// element wrote out of bounds, a list named like a coordinate was called through a null
// pointer, both found by fuzzing) and resizes a face's index list to whatever count the data
// say; this one checks the header strictly and every count against the bytes left.
#pragma once

#include <cstdint>
#include <filesystem>
#include <istream>

#include "io/polygon_soup.hpp"

namespace cvtmesh {

// Reads an ASCII, binary little-endian or binary big-endian PLY file: the x, y, z properties of
// element "vertex" and the vertex_indices (or vertex_index) list of element "face"; every other
// element and property is read past. `with_scalar`: also the first scalar vertex property that
// is not a position, normal or colour (PolygonSoup::vertex_scalar), which must exist. Throws
// InputError naming `path` on anything malformed.
PolygonSoup read_ply(const std::filesystem::path& path, std::istream& in, std::uintmax_t file_size,
                     bool with_scalar = false);

}  // namespace cvtmesh
