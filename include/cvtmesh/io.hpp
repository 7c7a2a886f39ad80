// Reading and writing triangle meshes: OBJ, OFF, PLY (ASCII, binary LE/BE), STL (ASCII, binary).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

enum class MeshFormat { obj, off, ply, stl };

// The format named by a path's extension (case-insensitive), or nullopt.
std::optional<MeshFormat> format_from_extension(const std::filesystem::path& path);

struct ReadReport {
  std::size_t polygons_in_file = 0;  // faces as stored, before polygons are triangulated
  std::size_t polygons_split = 0;    // faces with more than 3 corners, fan-triangulated
};

// Reads and validates a mesh. Throws InputError ("PATH: problem") for a missing or unreadable
// file, an unknown extension, an empty mesh, a non-finite coordinate, an out-of-range index, a
// face with fewer than 3 corners, or malformed/truncated data. Vertices are kept as stored
// (unreferenced and duplicate ones included); use repair_mesh() to clean them.
TriangleMesh read_mesh(const std::filesystem::path& path, ReadReport* report = nullptr);

// Writes OBJ/OFF (ASCII, round-trip precision), PLY (binary little-endian) or STL (binary),
// chosen by extension. The file appears atomically: written beside the target under a temporary
// name, then renamed. Throws OutputError on failure, InvalidArgument for an unknown extension.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh);

// Writes `mesh` as binary PLY with one float vertex property `name` = values[v], and a vertex
// colour from red (the smallest value) through yellow to blue (the largest), on a log scale:
// a field over a surface to look at (cvtmesh lfs). Written atomically; OutputError on failure.
void write_ply_with_vertex_scalar(const std::filesystem::path& path, const TriangleMesh& mesh,
                                  const std::vector<double>& values, const char* name);

// One number per vertex, in the file's vertex order (cvtmesh remesh --sizing): a PLY's first
// vertex scalar that is not a position, normal or colour (as `cvtmesh lfs` writes), or else a
// text file of one number a line (blank lines and lines starting with # are skipped). Throws
// InputError naming the file (and the line) for anything else, or a value that is not finite.
std::vector<double> read_vertex_values(const std::filesystem::path& path);

// Throws InvalidArgument if `output` names the same file as `input` (cvtmesh never writes over
// its input).
void ensure_distinct_output(const std::filesystem::path& input,
                            const std::filesystem::path& output);

}  // namespace cvtmesh
