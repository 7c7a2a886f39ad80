// Binary OFF data, in the layouts that files in the wild use: Geomview's (big-endian words, a
// colour count after each face's indices) and pmp-library's, which writes no colour count, in
// big-endian words since its version 3 and in little-endian ones before (the OFF files of its
// own data folder are of that kind).
#pragma once

#include <filesystem>
#include <istream>

#include "io/polygon_soup.hpp"

namespace cvtmesh {

// What the header keyword says of each vertex: `floats` words (the coordinates first, then
// normals, colours and texture coordinates, skipped), the fourth coordinate the divisor w when
// `homogeneous`; and whether the dimension comes before the counts (nOFF).
struct BinaryOffVertices {
  int floats = 3;
  bool homogeneous = false;
  bool dimension = false;
};

// Reads the rest of `in`, the data after the header line "[ST][C][N][4][n]OFF BINARY": in the
// first of the layouts above, Geomview's first, that reads every face and ends with the file (a
// file of one layout read in another fails, or leaves bytes over); else in Geomview's, if it reads
// every face (bytes after them are ignored, as before other layouts were read); else throws
// InputError naming `path` with the problem that Geomview's layout found.
PolygonSoup read_off_binary(const std::filesystem::path& path, std::istream& in,
                            const BinaryOffVertices& vertices);

}  // namespace cvtmesh
