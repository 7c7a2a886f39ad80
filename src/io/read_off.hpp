// cvtmesh's own OFF reader. CGAL 5.5's OFF scanner reads past its buffers on colour entries
// that do not add up (found by fuzzing); OFF is simple enough to read here, strictly, with the
// line of each problem in the message.
#pragma once

#include <cstdint>
#include <filesystem>
#include <istream>

#include "io/polygon_soup.hpp"

namespace cvtmesh {

// Reads an ASCII or binary OFF file: the header keyword [ST][C][N][4][n]OFF [BINARY] (or none),
// the counts, then the vertices (normals, colours and texture coordinates skipped) and the faces
// (colours skipped). Homogeneous (4OFF) points are divided by w. Throws InputError naming `path`
// on anything malformed or truncated; indices are checked against the vertex count.
PolygonSoup read_off(const std::filesystem::path& path, std::istream& in, std::uintmax_t file_size);

}  // namespace cvtmesh
