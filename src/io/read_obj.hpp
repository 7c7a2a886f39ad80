// cvtmesh's own OBJ reader: the positions and faces of a Wavefront OBJ file, read strictly, with
// the line of each problem in the message (CGAL 5.5's reader, used before, refuses valid
// statements continued over lines, misreads faces with tabs between corners, stops silently at a
// corner that is no index, and parses numbers by stream extraction: igea.ply as OBJ read in
// 0.19 s more than as OFF).
#pragma once

#include <filesystem>
#include <istream>

#include "io/polygon_soup.hpp"

namespace cvtmesh {

// Reads the vertices ("v x y z", anything after the coordinates skipped) and faces ("f" with
// corners "i", "i/t", "i//n" or "i/t/n"; negative ids count back from the last vertex so far,
// and one that reaches outside the vertices is kept, for the caller's check of ids) of an OBJ
// file. A statement ending in a backslash goes on on the next line; texture coordinates,
// normals, polylines, points, groups, materials and the other statements of the format are
// skipped. Throws InputError naming `path` and the line on an unknown statement, a vertex without
// three numbers, or a corner that is no vertex id (0 included: ids start at 1).
PolygonSoup read_obj(const std::filesystem::path& path, std::istream& in);

}  // namespace cvtmesh
